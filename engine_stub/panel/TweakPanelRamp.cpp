// The tweak panel's colour-ramp editor: a gradient preview with stops that can be moved,
// recoloured, added and removed (the rest of the Reactions window is in TweakPanel.cpp).
#include "panel/TweakPanel.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>
#include <yaml-cpp/yaml.h>

#include "panel/PanelHelpers.h"
#include "panel/YamlTextEdit.h"

namespace cube {

using namespace panel;

void TweakPanel::buildColorRamp(int reaction, const fx::ReactionKeyInfo& info, const std::string& valueText) {
    const std::string id = plugin_->reactionName(reaction) + "/" + info.key;
    const YAML::Node v = parseValue(valueText);
    struct Stop {
        float t;
        float rgba[4];
    };
    std::vector<Stop> stops;
    for (const YAML::Node& n : v) {
        Stop s{asFloat(n["t"]), {1, 1, 1, 1}};
        for (int c = 0; c < 4 && n["rgba"] && n["rgba"].IsSequence() && size_t(c) < n["rgba"].size(); ++c) {
            s.rgba[c] = asFloat(n["rgba"][size_t(c)]);
        }
        stops.push_back(s);
    }
    ImGui::TextUnformatted(shortKey(info.key).c_str());
    tooltip(info);
    // The gradient as the particles see it over their life, left (birth) to right (death).
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    const float w = ImGui::CalcItemWidth() + 60.0f, h = 18.0f;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    auto col = [](const Stop& s) { return ImGui::GetColorU32(ImVec4(s.rgba[0], s.rgba[1], s.rgba[2], s.rgba[3])); };
    dl->AddRectFilled(p0, ImVec2(p0.x + w, p0.y + h), IM_COL32(40, 40, 40, 255));
    if (!stops.empty()) {
        float x = p0.x;
        for (size_t k = 0; k <= stops.size(); ++k) {
            const Stop& a = stops[k == 0 ? 0 : k - 1];
            const Stop& b = stops[k < stops.size() ? k : stops.size() - 1];
            const float x1 = k < stops.size() ? p0.x + w * b.t : p0.x + w;
            if (x1 > x) dl->AddRectFilledMultiColor(ImVec2(x, p0.y), ImVec2(x1, p0.y + h), col(a), col(b), col(b), col(a));
            x = std::max(x, x1);
        }
        for (const Stop& s : stops) {
            const float sx = p0.x + w * s.t;
            dl->AddTriangleFilled(ImVec2(sx, p0.y + h - 6), ImVec2(sx - 4, p0.y + h + 2), ImVec2(sx + 4, p0.y + h + 2),
                                  IM_COL32(255, 255, 255, 255));
        }
    }
    ImGui::Dummy(ImVec2(w, h + 4.0f));
    note(id);
    std::string error;
    for (size_t j = 0; j < stops.size(); ++j) {
        ImGui::PushID(int(j));
        const std::string stopKey = info.key + "[" + std::to_string(j) + "]";
        float t = stops[j].t;
        ImGui::SetNextItemWidth(ImGui::CalcItemWidth() * 0.5f);
        if (ImGui::SliderFloat("##t", &t, 0.0f, 1.0f, "t %.2f") && t != stops[j].t) {
            edit(reaction, stopKey + ".t", panel::formatNumber(t, false, "0.0"), stopKey + ".t");
        }
        note(id + "[" + std::to_string(j) + "].t");
        ImGui::SameLine();
        float rgba[4] = {stops[j].rgba[0], stops[j].rgba[1], stops[j].rgba[2], stops[j].rgba[3]};
        if (ImGui::ColorEdit4("##rgba", rgba, ImGuiColorEditFlags_NoInputs | ImGuiColorEditFlags_AlphaPreviewHalf |
                                                  ImGuiColorEditFlags_AlphaBar | ImGuiColorEditFlags_Float)) {
            for (int c = 0; c < 4; ++c) {
                if (rgba[c] == stops[j].rgba[c]) continue;
                edit(reaction, stopKey + ".rgba[" + std::to_string(c) + "]", panel::formatNumber(rgba[c], false, "0.0"),
                     stopKey + ".rgba");
            }
        }
        note(id + "[" + std::to_string(j) + "].rgba");
        ImGui::SameLine();
        if (ImGui::SmallButton("+")) {
            if (session_->duplicateStop(reaction, int(j), &error)) message_.clear(); else message_ = error;
        }
        ImGui::SameLine();
        if (ImGui::SmallButton("-")) {
            if (session_->removeStop(reaction, int(j), &error)) message_.clear(); else message_ = error;
        }
        ImGui::PopID();
    }
}

}  // namespace cube
