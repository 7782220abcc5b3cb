#pragma once
// The live tweak panel (cube_game --panel): a Dear ImGui UI over the frame with a widget for
// every key of every loaded reaction, generated from the plugin's schema (fx::ReactionKeyInfo:
// type, range, unit, meaning as a tooltip), the run-time render switches, time scale and pause,
// camera presets, and the last 300 frames' pass timings, particle counts and render targets.
// Edits go through panel::EditSession (applied at once with the file loader's validation,
// undo/redo, save in place, revert, files changed on disk).
//
// It is a GameOverlay: beginFrame feeds ImGui the frame's input (the window's events and any
// injected ones, one queue) and builds the UI before the update; declarePasses adds one pass,
// "panel", that draws it (render/PanelRenderer) onto the main view's colour before present.
// Hidden (F1 in a window, setVisible(false)), it declares nothing and changes nothing.
// This file holds no GL call: the drawing is the back end's.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "game/Game.h"
#include "panel/EditSession.h"
#include "platform/Platform.h"

struct ImGuiContext;

namespace cube {

class PanelRenderer;

class TweakPanel final : public GameOverlay {
public:
    TweakPanel();
    ~TweakPanel() override;
    TweakPanel(const TweakPanel&) = delete;
    TweakPanel& operator=(const TweakPanel&) = delete;

    /// Needs the game's GL context current (builds the panel's program and font texture) and
    /// the plugin path (--fx plugin). False + error otherwise.
    bool init(Game& game, std::string* error);

    /// Queues an input event for the next frame (tests; the window's events arrive the same way).
    void inject(const InputEvent& event) { queue_.push_back(event); }
    void setVisible(bool visible) { visible_ = visible; }
    bool visible() const { return visible_; }

    // GameOverlay
    void beginFrame(Game& game, float dt) override;
    rtt::FrameGraphResource declarePasses(Game& game, rtt::FrameGraph& graph, rtt::FrameGraphResource color,
                                          int width, int height) override;
    bool wantsKeyboard() const override { return visible_ && wantsKeyboard_; }

    /// Where the widget `id` was drawn in the last frame, in pixels from the top-left:
    /// "<reaction>/<key>" for reaction keys ("burnout_smoke/particle.drag"), or the button and
    /// switch names ("save", "undo", "quarter_res", ...). False when it was not drawn.
    bool widgetRect(const std::string& id, float* x0, float* y0, float* x1, float* y1) const;
    /// Shows reaction `index` in the reactions window.
    void selectReaction(int index) { selected_ = index; }
    /// The last refusal or failure shown in the panel ("" when the last edit went through).
    const std::string& message() const { return message_; }
    panel::EditSession& session() { return *session_; }
    /// Draws the last built frame into the bound framebuffer now (tests of the GL state).
    void drawNow(int width, int height);

private:
    struct Cached {
        int version = -1;
        std::map<std::string, std::string> values;  ///< "<reaction>/<key>" -> running value text
    };
    void feedInput(Game& game, float dt);
    void buildReactionsWindow(Game& game);
    void buildFrameWindow(Game& game);
    void buildKey(int reaction, const fx::ReactionKeyInfo& info);
    void buildColorRamp(int reaction, const fx::ReactionKeyInfo& info, const std::string& value);
    void buildConflictDialog();
    const std::string& runningValue(int reaction, const std::string& key);
    void edit(int reaction, const std::string& key, const std::string& value, const std::string& group);
    /// Records the last item's rectangle; `frameOnly`: without the label to its right.
    void note(const std::string& id, bool frameOnly = false);
    void recordTimings(Game& game);

    ImGuiContext* context_ = nullptr;
    std::unique_ptr<PanelRenderer> renderer_;
    std::unique_ptr<panel::EditSession> session_;
    fx::Plugin* plugin_ = nullptr;
    std::vector<fx::ReactionKeyInfo> schema_;
    std::vector<InputEvent> queue_;
    std::map<std::string, std::vector<float>> rects_;
    Cached cache_;
    int lastReloads_ = -1;
    int selected_ = 0;
    bool visible_ = true;
    bool wantsKeyboard_ = false;
    bool built_ = false;
    long long frames_ = 0;
    std::string message_;
    // Timings: the last kHistory frames, per pass and for the whole frame (ms).
    static constexpr int kHistory = 300;
    std::map<std::string, std::vector<float>> passHistory_;
    std::vector<float> frameHistory_;
    int historyNext_ = 0;
    std::vector<std::string> lastPasses_;
};

}  // namespace cube
