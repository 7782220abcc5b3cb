// The tweak panel's Frame window: render switches, time and camera, per-pass timing graphs and
// particle counts (the Reactions window and the input/draw plumbing are in TweakPanel.cpp).
#include "panel/TweakPanel.h"

#include <algorithm>
#include <cfloat>
#include <cstdio>

#include <imgui.h>

#include "game/TechniqueModes.h"

namespace cube {

void TweakPanel::buildFrameWindow(Game& game) {
    const ImGuiIO& io = ImGui::GetIO();
    const float width = std::min(430.0f, io.DisplaySize.x * 0.4f);
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - width - 8.0f, 8.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(width, std::min(640.0f, io.DisplaySize.y - 16.0f)), ImGuiCond_FirstUseEver);
    ImGui::Begin("Frame");
    ImGui::TextDisabled("%s, timing %s", game.platform().rendererName().c_str(), game.graph().timingMethod());

    if (ImGui::CollapsingHeader("Render", ImGuiTreeNodeFlags_DefaultOpen)) {
        fx::RenderOptions ro = plugin_->renderOptions();
        const char* techniques[kTechniqueModeCount];
        for (size_t i = 0; i < kTechniqueModeCount; ++i) techniques[i] = kTechniqueModes[i].label;
        int t = int(ro.techniqueOverride);
        bool changed = ImGui::Combo("technique", &t, techniques, int(kTechniqueModeCount));
        note("technique");
        ro.techniqueOverride = fx::Technique(t);
        ImGui::Checkbox("prepass-EQUAL", &game.options().prepassEqual);
        note("prepass_equal");
        changed |= ImGui::Checkbox("quarter-res", &ro.quarterRes);
        note("quarter_res");
        ImGui::SameLine();
        changed |= ImGui::Checkbox("bilinear upsample", &ro.bilinearUpsample);
        note("bilinear_upsample");
        if (changed) {
            plugin_->setRenderOptions(ro);
            (void)plugin_->prepareGl(nullptr);  // what the new options reach, built between frames
        }
        // Trimmed polygons / octagons or full quads: the same picture, fewer fragments.
        bool trimmed = plugin_->particleShape() == fx::ParticleShape::Trimmed;
        if (ImGui::Checkbox("trimmed shapes", &trimmed)) {
            plugin_->setParticleShape(trimmed ? fx::ParticleShape::Trimmed : fx::ParticleShape::Quad);
        }
        note("trimmed_shapes");
        ImGui::TextDisabled("%s", game.scene().renderer().reversedZ() ? "reversed-Z float depth" : "standard 24-bit depth");
    }
    if (ImGui::CollapsingHeader("Light", ImGuiTreeNodeFlags_DefaultOpen)) {
        // The sun lights the scene and the smoke (Game::setSun); lit smoke can be switched off.
        float azimuth = float(game.options().sunAzimuth), elevation = float(game.options().sunElevation);
        bool moved = ImGui::SliderFloat("sun azimuth", &azimuth, 0.0f, 360.0f, "%.0f deg");
        note("sun_azimuth", true);
        moved |= ImGui::SliderFloat("sun elevation", &elevation, float(kMinSunElevationDeg), float(kMaxSunElevationDeg),
                                    "%.0f deg");
        note("sun_elevation", true);
        if (moved) game.setSun(azimuth, elevation);
        bool lit = game.options().litSmoke;
        if (ImGui::Checkbox("lit smoke", &lit)) {
            game.options().litSmoke = lit;
            game.specialFX().setLitSmoke(lit);
            game.specialFX().setSceneLight(game.sun());
        }
        note("lit_smoke");
    }
    if (ImGui::CollapsingHeader("Time and camera", ImGuiTreeNodeFlags_DefaultOpen)) {
        float scale = game.timeScale();
        if (ImGui::SliderFloat("time scale", &scale, 0.0f, 4.0f, "%.2fx")) game.setTimeScale(scale);
        note("time_scale", true);
        bool paused = game.paused();
        if (ImGui::Checkbox("pause", &paused)) game.setPaused(paused);
        note("pause");
        ImGui::SameLine();
        ImGui::Text("t = %.2f s", game.time());
        int preset = int(game.cameraPreset());
        ImGui::RadioButton("chase", &preset, int(CameraPreset::Chase));
        note("camera_chase");
        ImGui::SameLine();
        ImGui::RadioButton("burnout close-up", &preset, int(CameraPreset::BurnoutCloseUp));
        note("camera_burnout");
        if (game.hasBarrier()) {
            ImGui::SameLine();
            ImGui::RadioButton("barrier", &preset, int(CameraPreset::Barrier));
            note("camera_barrier");
        }
        game.setCameraPreset(CameraPreset(preset));
    }
    if (ImGui::CollapsingHeader("Timings", ImGuiTreeNodeFlags_DefaultOpen)) {
        const float last = frameHistory_[size_t((historyNext_ + kHistory - 1) % kHistory)];
        char overlay[48];
        std::snprintf(overlay, sizeof overlay, "frame %.2f ms", last);
        ImGui::PlotLines("##frame", frameHistory_.data(), kHistory, historyNext_, overlay, 0.0f, FLT_MAX,
                         ImVec2(ImGui::GetContentRegionAvail().x, 50.0f));
        note("frame_graph");
        if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
            ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthStretch, 1.4f);
            ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthStretch, 0.5f);
            ImGui::TableSetupColumn("last 300 frames", ImGuiTableColumnFlags_WidthStretch, 1.6f);
            ImGui::TableHeadersRow();
            for (const std::string& name : lastPasses_) {
                auto it = passHistory_.find(name);
                if (it == passHistory_.end()) continue;
                ImGui::TableNextRow();
                ImGui::TableSetColumnIndex(0);
                ImGui::TextUnformatted(name.c_str());
                ImGui::TableSetColumnIndex(1);
                ImGui::Text("%.2f", it->second[size_t((historyNext_ + kHistory - 1) % kHistory)]);
                ImGui::TableSetColumnIndex(2);
                ImGui::PushID(name.c_str());
                ImGui::PlotLines("##h", it->second.data(), kHistory, historyNext_, nullptr, 0.0f, FLT_MAX,
                                 ImVec2(ImGui::GetContentRegionAvail().x, 14.0f));
                ImGui::PopID();
            }
            ImGui::EndTable();
        }
        const rtt::FrameGraphReport& report = game.graph().report();
        ImGui::Text("render targets alive %d, used this frame %d", report.targetsLive, report.targetsAcquired);
    }
    if (ImGui::CollapsingHeader("Particles", ImGuiTreeNodeFlags_DefaultOpen)) {
        for (int i = 0; i < plugin_->reactionCount(); ++i) {
            ImGui::Text("%-16s %6d / %s", plugin_->reactionName(i).c_str(), plugin_->reactionParticlesAlive(i),
                        runningValue(i, "emission.capacity").c_str());
        }
        ImGui::Text("drawn last view %d", plugin_->stats().particlesDrawn);
    }
    ImGui::End();
}

}  // namespace cube
