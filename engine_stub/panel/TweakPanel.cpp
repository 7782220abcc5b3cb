#include "panel/TweakPanel.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>
#include <yaml-cpp/yaml.h>

#include "panel/PanelHelpers.h"
#include "panel/YamlTextEdit.h"
#include "render/PanelRenderer.h"
#include "view/Buckets.h"

namespace cube {

namespace {
using Kind = fx::ReactionKeyInfo::Kind;
using namespace panel;
}  // namespace

TweakPanel::TweakPanel() = default;

TweakPanel::~TweakPanel() {
    renderer_.reset();  // GL objects first, while the context is current
    if (context_) ImGui::DestroyContext(context_);
}

bool TweakPanel::init(Game& game, std::string* error) {
    plugin_ = game.specialFX().plugin();
    if (!plugin_) {
        *error = "--panel: needs the plugin's reactions (--fx plugin)";
        return false;
    }
    session_ = std::make_unique<panel::EditSession>(*plugin_);
    if (!session_->open(error)) return false;
    schema_ = plugin_->reactionSchema();
    // Start on the first wheel-smoke reaction: the one people come to tune.
    for (int i = plugin_->reactionCount() - 1; i >= 0; --i) {
        if (plugin_->reactionValue(i, "type") == "wheel_smoke") selected_ = i;
    }

    context_ = ImGui::CreateContext();
    ImGui::SetCurrentContext(context_);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini next to the user's files
    io.LogFilename = nullptr;
    io.BackendPlatformName = "cube_platform";
    io.BackendRendererName = "cube_panel_renderer";
    io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
    const std::pair<ImGuiKey_, UiKey> keys[] = {
        {ImGuiKey_Tab, UiKey::Tab}, {ImGuiKey_LeftArrow, UiKey::Left}, {ImGuiKey_RightArrow, UiKey::Right},
        {ImGuiKey_UpArrow, UiKey::Up}, {ImGuiKey_DownArrow, UiKey::Down}, {ImGuiKey_PageUp, UiKey::PageUp},
        {ImGuiKey_PageDown, UiKey::PageDown}, {ImGuiKey_Home, UiKey::Home}, {ImGuiKey_End, UiKey::End},
        {ImGuiKey_Delete, UiKey::Delete}, {ImGuiKey_Backspace, UiKey::Backspace}, {ImGuiKey_Enter, UiKey::Enter},
        {ImGuiKey_Escape, UiKey::Escape}, {ImGuiKey_A, UiKey::A}, {ImGuiKey_C, UiKey::C}, {ImGuiKey_V, UiKey::V},
        {ImGuiKey_X, UiKey::X}, {ImGuiKey_Y, UiKey::Y}, {ImGuiKey_Z, UiKey::Z}};
    for (const auto& k : keys) io.KeyMap[k.first] = int(k.second);
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 3.0f;
    ImGui::GetStyle().Colors[ImGuiCol_WindowBg].w = 0.88f;

    renderer_ = std::make_unique<PanelRenderer>();
    if (!renderer_->init(error)) return false;
    frameHistory_.assign(kHistory, 0.0f);
    return true;
}

void TweakPanel::feedInput(Game& game, float dt) {
    std::vector<InputEvent> incoming;
    game.platform().takeInputEvents(&incoming);
    queue_.insert(queue_.end(), incoming.begin(), incoming.end());
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(std::max(game.platform().width(), 1)), float(std::max(game.platform().height(), 1)));
    io.DeltaTime = dt > 0.0f ? dt : 1.0f / 60.0f;
    // ImGui 1.86 reads input as a state per frame: a press and its release in one frame would
    // be lost, so the queue stops after each button or key change and resumes next frame.
    size_t used = 0;
    while (used < queue_.size()) {
        const InputEvent& e = queue_[used++];
        bool stop = false;
        switch (e.type) {
            case InputEvent::Type::MouseMove: io.MousePos = ImVec2(e.x, e.y); break;
            case InputEvent::Type::MouseButton:
                if (e.button >= 0 && e.button < 5) io.MouseDown[e.button] = e.down;
                stop = true;
                break;
            case InputEvent::Type::Scroll:
                io.MouseWheelH += e.x;
                io.MouseWheel += e.y;
                break;
            case InputEvent::Type::Key:
                io.KeysDown[int(e.key)] = e.down;
                if (e.key == UiKey::Ctrl) io.KeyCtrl = e.down;
                if (e.key == UiKey::Shift) io.KeyShift = e.down;
                if (e.key == UiKey::Alt) io.KeyAlt = e.down;
                stop = true;
                break;
            case InputEvent::Type::Char: io.AddInputCharacter(e.codepoint); break;
        }
        if (stop) break;
    }
    queue_.erase(queue_.begin(), queue_.begin() + std::ptrdiff_t(used));
}

void TweakPanel::recordTimings(Game& game) {
    const rtt::FrameGraphReport& report = game.graph().report();
    for (auto& track : passHistory_) track.second[size_t(historyNext_)] = 0.0f;
    for (const rtt::PassTiming& t : report.timings) {
        std::vector<float>& track = passHistory_[t.name];
        if (track.empty()) track.assign(kHistory, 0.0f);
        track[size_t(historyNext_)] = t.lastMs > 0.0 ? float(t.lastMs) : 0.0f;
    }
    frameHistory_[size_t(historyNext_)] = game.frameMs().empty() ? 0.0f : float(game.frameMs().back());
    historyNext_ = (historyNext_ + 1) % kHistory;
    lastPasses_ = report.executed;
}

void TweakPanel::beginFrame(Game& game, float dt) {
    if (!visible_ || !context_) {
        std::vector<InputEvent> dropped;  // a hidden panel takes no input
        game.platform().takeInputEvents(&dropped);
        queue_.clear();
        return;
    }
    ImGui::SetCurrentContext(context_);
    if (frames_ > 0) recordTimings(game);
    std::string error;
    // Twice a second at 60 fps: cheap (the files are small) and soon enough for a person.
    if (frames_ % 30 == 0 && session_->checkDisk(&error) && !error.empty()) message_ = error;
    feedInput(game, dt);
    rects_.clear();
    ImGui::NewFrame();
    buildReactionsWindow(game);
    buildFrameWindow(game);
    buildConflictDialog();
    if (!ImGui::IsAnyItemActive()) session_->endGroup();
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.WantTextInput && io.KeyCtrl && ImGui::IsKeyPressed(int(UiKey::Z), false)) {
        if (!session_->undo(&error) && !error.empty()) message_ = error;
    }
    if (!io.WantTextInput && io.KeyCtrl && ImGui::IsKeyPressed(int(UiKey::Y), false)) {
        if (!session_->redo(&error) && !error.empty()) message_ = error;
    }
    wantsKeyboard_ = io.WantTextInput;
    ImGui::Render();
    built_ = true;
    ++frames_;
}

rtt::FrameGraphResource TweakPanel::declarePasses(Game&, rtt::FrameGraph& graph, rtt::FrameGraphResource color,
                                                  int width, int height) {
    if (!visible_ || !built_) return color;
    PanelRenderer* renderer = renderer_.get();
    ImGuiContext* context = context_;
    graph.addPass("panel", kPresentOrder - 1, [&](rtt::PassBuilder& b) { b.write(color); },
                  [renderer, context, color, width, height](rtt::PassContext& ctx) {
                      ctx.bindForDraw(color);
                      ImGui::SetCurrentContext(context);
                      if (const ImDrawData* data = ImGui::GetDrawData()) renderer->draw(*data, width, height);
                  });
    return color;
}

void TweakPanel::drawNow(int width, int height) {
    if (!built_) return;
    ImGui::SetCurrentContext(context_);
    if (const ImDrawData* data = ImGui::GetDrawData()) renderer_->draw(*data, width, height);
}

bool TweakPanel::widgetRect(const std::string& id, float* x0, float* y0, float* x1, float* y1) const {
    auto it = rects_.find(id);
    if (it == rects_.end()) return false;
    *x0 = it->second[0];
    *y0 = it->second[1];
    *x1 = it->second[2];
    *y1 = it->second[3];
    return true;
}

void TweakPanel::note(const std::string& id, bool frameOnly) {
    const ImVec2 a = ImGui::GetItemRectMin();
    ImVec2 b = ImGui::GetItemRectMax();
    if (frameOnly) b.x = std::min(b.x, a.x + ImGui::CalcItemWidth());  // leave out the label
    // Only what is on screen: a widget scrolled out of its window is not clickable.
    if (!ImGui::IsItemVisible()) return;
    rects_[id] = {a.x, a.y, b.x, b.y};
}

const std::string& TweakPanel::runningValue(int reaction, const std::string& key) {
    const int reloads = plugin_->stats().reloads;
    if (cache_.version != session_->version() || reloads != lastReloads_) {
        cache_.values.clear();
        cache_.version = session_->version();
        lastReloads_ = reloads;
    }
    const std::string id = std::to_string(reaction) + "/" + key;
    auto it = cache_.values.find(id);
    if (it == cache_.values.end()) it = cache_.values.emplace(id, plugin_->reactionValue(reaction, key)).first;
    return it->second;
}

void TweakPanel::edit(int reaction, const std::string& key, const std::string& value, const std::string& group) {
    std::string error;
    if (session_->set(reaction, key, value, &error, group)) {
        message_.clear();
    } else {
        message_ = error;
    }
}

void TweakPanel::buildReactionsWindow(Game& game) {
    const ImGuiIO& io = ImGui::GetIO();
    const float width = std::min(470.0f, io.DisplaySize.x * 0.45f);
    const float top = game.options().hud ? 52.0f : 8.0f;  // below the HUD's text line
    ImGui::SetNextWindowPos(ImVec2(8.0f, top), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(width, io.DisplaySize.y - top - 8.0f), ImGuiCond_FirstUseEver);
    ImGui::Begin("Reactions");
    std::string error;
    const std::vector<panel::Document>& docs = session_->documents();
    for (size_t d = 0; d < docs.size(); ++d) {
        ImGui::PushID(int(d));
        ImGui::Text("%s%s", baseName(docs[d].path).c_str(), docs[d].dirty() ? " *" : "");
        ImGui::SameLine(width * 0.55f);
        if (ImGui::SmallButton("Save")) {
            if (session_->save(int(d), &error)) message_.clear(); else message_ = error;
        }
        note("save:" + baseName(docs[d].path));
        ImGui::SameLine();
        if (ImGui::SmallButton("Revert")) {
            if (session_->revert(int(d), &error)) message_.clear(); else message_ = error;
        }
        note("revert:" + baseName(docs[d].path));
        ImGui::PopID();
    }
    if (ImGui::Button("Undo") && !session_->undo(&error) && !error.empty()) message_ = error;
    note("undo");
    ImGui::SameLine();
    if (ImGui::Button("Redo") && !session_->redo(&error) && !error.empty()) message_ = error;
    note("redo");
    ImGui::SameLine();
    ImGui::TextDisabled("(Ctrl+Z / Ctrl+Y)");
    if (!message_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", message_.c_str());
        ImGui::PopStyleColor();
    }
    ImGui::Separator();

    const int count = plugin_->reactionCount();
    if (count == 0) {
        ImGui::TextDisabled("no reaction loaded");
        ImGui::End();
        return;
    }
    selected_ = std::min(std::max(selected_, 0), count - 1);
    const std::string current = plugin_->reactionName(selected_);
    if (ImGui::BeginCombo("reaction", current.c_str())) {
        for (int i = 0; i < count; ++i) {
            if (ImGui::Selectable(plugin_->reactionName(i).c_str(), i == selected_)) selected_ = i;
        }
        ImGui::EndCombo();
    }
    note("reaction");
    ImGui::SameLine();
    ImGui::TextDisabled("%s", baseName(plugin_->reactionFile(selected_)).c_str());

    ImGui::PushItemWidth(width * 0.55f);
    std::string open;
    bool shown = true;
    for (const fx::ReactionKeyInfo& info : schema_) {
        const std::string s = section(info.key);
        if (s != open) {
            open = s;
            shown = ImGui::CollapsingHeader(s.c_str(), ImGuiTreeNodeFlags_DefaultOpen);
        }
        if (shown) buildKey(selected_, info);
    }
    ImGui::PopItemWidth();
    ImGui::End();
}

void TweakPanel::buildKey(int reaction, const fx::ReactionKeyInfo& info) {
    const std::string id = plugin_->reactionName(reaction) + "/" + info.key;
    const std::string valueText = runningValue(reaction, info.key);
    const YAML::Node v = parseValue(valueText);
    const std::string label = shortKey(info.key);
    ImGui::PushID(info.key.c_str());
    const bool narrow = info.max - info.min <= 200.0;
    switch (info.kind) {
        case Kind::Name:
            ImGui::LabelText(label.c_str(), "%s", valueText.c_str());
            break;
        case Kind::Number: {
            float f = asFloat(v);
            const float before = f;
            const std::string fmt = numberFormat(narrow && info.max - info.min <= 2.0 ? "%.3f" : "%.2f", info.unit);
            const bool changed = narrow ? ImGui::SliderFloat(label.c_str(), &f, float(info.min), float(info.max), fmt.c_str())
                                        : ImGui::DragFloat(label.c_str(), &f, std::max(std::abs(f) * 0.005f, 0.01f),
                                                           float(info.min), float(info.max), fmt.c_str());
            note(id, true);
            tooltip(info);
            if (changed && f != before) edit(reaction, info.key, panel::formatNumber(f, false, valueText), info.key);
            break;
        }
        case Kind::Integer: {
            int i = int(asFloat(v));
            const int before = i;
            const std::string fmt = numberFormat("%d", info.unit);
            const bool changed = narrow ? ImGui::SliderInt(label.c_str(), &i, int(info.min), int(info.max), fmt.c_str())
                                        : ImGui::DragInt(label.c_str(), &i, std::max(std::abs(float(i)) * 0.005f, 1.0f),
                                                         int(info.min), int(info.max), fmt.c_str());
            note(id, true);
            tooltip(info);
            if (changed && i != before) edit(reaction, info.key, std::to_string(i), info.key);
            break;
        }
        case Kind::Bool: {
            bool b = valueText == "true";
            if (ImGui::Checkbox(label.c_str(), &b)) edit(reaction, info.key, b ? "true" : "false", "");
            note(id);
            tooltip(info);
            break;
        }
        case Kind::Choice: {
            if (ImGui::BeginCombo(label.c_str(), valueText.c_str())) {
                for (const std::string& c : info.choices) {
                    if (ImGui::Selectable(c.c_str(), c == valueText) && c != valueText) edit(reaction, info.key, c, "");
                }
                ImGui::EndCombo();
            }
            note(id);
            tooltip(info);
            break;
        }
        case Kind::ChoiceList: {
            std::vector<std::string> running;
            for (const YAML::Node& n : v) running.push_back(n.Scalar());
            auto has = [&](const std::string& c) { return std::find(running.begin(), running.end(), c) != running.end(); };
            std::string toggled;
            bool turnedOn = false;
            for (size_t c = 0; c < info.choices.size(); ++c) {
                bool b = has(info.choices[c]);
                if (c > 0) ImGui::SameLine();
                if (ImGui::Checkbox(info.choices[c].c_str(), &b)) {
                    toggled = info.choices[c];
                    turnedOn = b;
                }
                note(id + "." + info.choices[c]);
                tooltip(info);
            }
            ImGui::SameLine();
            ImGui::TextUnformatted(label.c_str());
            if (!toggled.empty()) {
                std::string list;  // in the schema's order
                for (const std::string& c : info.choices) {
                    if (c == toggled ? turnedOn : has(c)) list += (list.empty() ? "" : ", ") + c;
                }
                edit(reaction, info.key, "[" + list + "]", "");
            }
            break;
        }
        case Kind::NumberRange:
        case Kind::IntegerPair: {
            const bool integer = info.kind == Kind::IntegerPair;
            float pair[2] = {asFloat(v.IsSequence() ? v[0] : v), asFloat(v.IsSequence() ? v[1] : v)};
            int ipair[2] = {int(pair[0]), int(pair[1])};
            bool changed = false;
            if (integer) {
                changed = ImGui::SliderInt2(label.c_str(), ipair, int(info.min), int(info.max));
                pair[0] = float(ipair[0]);
                pair[1] = float(ipair[1]);
            } else {
                const std::string fmt = numberFormat("%.2f", info.unit);
                changed = ImGui::SliderFloat2(label.c_str(), pair, float(info.min), float(info.max), fmt.c_str());
            }
            note(id, true);
            tooltip(info);
            if (changed) {
                const float old0 = asFloat(v.IsSequence() ? v[0] : v), old1 = asFloat(v.IsSequence() ? v[1] : v);
                const std::string a = panel::formatNumber(pair[0], integer), b = panel::formatNumber(pair[1], integer);
                // One element changed: edit that element where the file has a list, else the
                // whole value (a single number, or the key absent).
                const int j = pair[0] != old0 ? 0 : (pair[1] != old1 ? 1 : -1);
                const std::string element = info.key + "[" + std::to_string(j) + "]";
                if (j >= 0 && session_->hasEntry(reaction, element)) {
                    edit(reaction, element, j == 0 ? a : b, info.key);
                } else if (j >= 0) {
                    edit(reaction, info.key, "[" + a + ", " + b + "]", info.key);
                }
            }
            break;
        }
        case Kind::ColorRamp:
            buildColorRamp(reaction, info, valueText);
            break;
    }
    ImGui::PopID();
}

void TweakPanel::buildConflictDialog() {
    const std::vector<panel::Document>& docs = session_->documents();
    for (size_t d = 0; d < docs.size(); ++d) {
        if (!docs[d].conflict) continue;
        const char* title = "File changed on disk";
        if (!ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
        if (ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
            ImGui::Text("%s changed on disk while it has unsaved edits.", docs[d].path.c_str());
            std::string error;
            if (ImGui::Button("Reload from disk (drop my edits)")) {
                if (!session_->resolveConflict(int(d), true, &error)) message_ = error;
                ImGui::CloseCurrentPopup();
            }
            note("conflict:reload");
            ImGui::SameLine();
            if (ImGui::Button("Keep my edits (Save overwrites)")) {
                session_->resolveConflict(int(d), false, &error);
                ImGui::CloseCurrentPopup();
            }
            note("conflict:keep");
            ImGui::EndPopup();
        }
        break;  // one question at a time
    }
}

}  // namespace cube
