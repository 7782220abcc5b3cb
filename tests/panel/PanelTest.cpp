// The panel in a headless game, driven by injected input events like a user's.
#include <gtest/gtest.h>

#include "PassChecks.h"

#include <cmath>

#include "PanelTestUtil.h"
#include "gl/Gl.h"
#include "panel/TweakPanel.h"

using namespace paneltest;
using cube::InputEvent;
using cube::UiKey;

namespace {

constexpr int kW = 1000, kH = 1000;

class PanelTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string error;
        ASSERT_TRUE(game.Init(options(copy.dir(), kW, kH), &error)) << error;
        plugin = game.specialFX().plugin();
        ASSERT_TRUE(panel.init(game, &error)) << error;
        game.setOverlay(&panel);
        burnout = reactionIndex(*plugin, "burnout_smoke");
        ASSERT_GE(burnout, 0);
        panel.selectReaction(burnout);
        cube::gl::resetErrorCount();
        frame();
    }
    void TearDown() override { game.setOverlay(nullptr); }
    void frame() { game.Dyn(1.0f / 60.0f); }
    // One event of `type` to the panel, with the fields that `fill` sets.
    template <typename Fill>
    void send(InputEvent::Type type, Fill fill) {
        InputEvent e;
        e.type = type;
        fill(e);
        panel.inject(e);
    }
    void move(float x, float y) {
        send(InputEvent::Type::MouseMove, [&](InputEvent& e) {
            e.x = x;
            e.y = y;
        });
    }
    void button(bool down) {
        send(InputEvent::Type::MouseButton, [&](InputEvent& e) { e.down = down; });
    }
    void key(UiKey k, bool down) {
        send(InputEvent::Type::Key, [&](InputEvent& e) {
            e.key = k;
            e.down = down;
        });
    }
    void type(const std::string& text) {
        for (char c : text) send(InputEvent::Type::Char, [&](InputEvent& e) { e.codepoint = unsigned(c); });
    }
    struct Rect {
        float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        float cy() const { return 0.5f * (y0 + y1); }
    };
    Rect rect(const std::string& id) {
        Rect r;
        EXPECT_TRUE(panel.widgetRect(id, &r.x0, &r.y0, &r.x1, &r.y1)) << id << " was not drawn";
        return r;
    }
    // Press at (x0, y), drag to (x1, y), release: one frame per step, as ImGui reads input.
    void drag(float x0, float x1, float y) {
        move(x0, y);
        frame();
        button(true);
        frame();
        move(x1, y);
        frame();
        button(false);
        frame();
    }
    void click(const Rect& r) {
        move(0.5f * (r.x0 + r.x1), r.cy());
        frame();
        button(true);
        frame();
        button(false);
        frame();
    }
    std::string value(const std::string& k) { return plugin->reactionValue(burnout, k); }

    ReactionCopy copy;
    cube::Game game;
    cube::TweakPanel panel;
    fx::Plugin* plugin = nullptr;
    int burnout = -1;
};


TEST_F(PanelTest, AnInjectedDragOnASliderChangesTheRunningValueWithinItsRange) {
    const Rect r = rect("burnout_smoke/particle.size_variation");  // a slider over [0, 0.9]
    ASSERT_EQ(value("particle.size_variation"), "0.25");
    // To 3/4 of the slider: about 0.675 (the grab's width makes it inexact: 0.05 tolerance).
    drag(r.x0 + 0.25f * (r.x1 - r.x0), r.x0 + 0.75f * (r.x1 - r.x0), r.cy());
    const float mid = std::stof(value("particle.size_variation"));
    EXPECT_NEAR(mid, 0.675f, 0.05f);
    // Far past the right end: the slider stops at the schema's maximum, never beyond.
    drag(r.x0 + 0.5f * (r.x1 - r.x0), r.x1 + 300.0f, r.cy());
    EXPECT_EQ(value("particle.size_variation"), "0.9");
    EXPECT_EQ(panel.message(), "");
    // Live in the plugin, not yet on disk.
    EXPECT_EQ(readFile(copy.file("burnout_smoke.yaml")).find("size_variation: 0.9"), std::string::npos);
    EXPECT_EQ(cube::gl::errorCount(), 0) << cube::gl::lastError();
}

TEST_F(PanelTest, TheSaveButtonWritesOnlyTheDraggedValue) {
    const std::string before = readFile(copy.file("burnout_smoke.yaml"));
    const Rect r = rect("burnout_smoke/particle.size_variation");
    drag(r.x0 + 0.5f * (r.x1 - r.x0), r.x1 + 300.0f, r.cy());
    ASSERT_EQ(value("particle.size_variation"), "0.9");
    click(rect("save:burnout_smoke.yaml"));
    const std::string after = readFile(copy.file("burnout_smoke.yaml"));
    std::string expected = before;
    expected.replace(expected.find("size_variation: 0.25"), 20, "size_variation: 0.9");
    EXPECT_EQ(after, expected);
}

TEST_F(PanelTest, AValueTypedOutOfRangeIsRefusedWithTheSchemasMessage) {
    const int running = plugin->reactionCount();
    const Rect r = rect("burnout_smoke/particle.size_variation");
    // Ctrl+click turns the slider into a text field (its text selected); type 5, Enter.
    key(UiKey::Ctrl, true);
    frame();
    click(r);
    key(UiKey::Ctrl, false);
    frame();
    EXPECT_TRUE(panel.wantsKeyboard());
    type("5");
    frame();
    key(UiKey::Enter, true);
    frame();
    key(UiKey::Enter, false);
    frame();
    EXPECT_EQ(value("particle.size_variation"), "0.25");
    // The typed 5 is written like the value it replaces (0.25): "5.0".
    EXPECT_NE(panel.message().find("error[OutOfRange] reactions[0].particle.size_variation: expected a number in [0, 0.9], got '5.0'"),
              std::string::npos)
        << panel.message();
    // The running set never broke: the smoke keeps its particles and its values.
    EXPECT_EQ(plugin->reactionCount(), running);
    EXPECT_EQ(value("particle.drag"), "1.2");
}

TEST_F(PanelTest, RenderSwitchesChangeTheRunningOptions) {
    ASSERT_FALSE(plugin->renderOptions().quarterRes);
    click(rect("quarter_res"));
    EXPECT_TRUE(plugin->renderOptions().quarterRes);
    frame();  // a quarter-res frame with the panel over it
    EXPECT_TRUE(passKept(game.graph(), "panel"));
    click(rect("pause"));
    const double t = game.time();
    frame();
    EXPECT_EQ(game.time(), t);
    ASSERT_EQ(plugin->particleShape(), fx::ParticleShape::Trimmed);
    click(rect("trimmed_shapes"));
    EXPECT_EQ(plugin->particleShape(), fx::ParticleShape::Quad);
    click(rect("trimmed_shapes"));
    EXPECT_EQ(plugin->particleShape(), fx::ParticleShape::Trimmed);
}

TEST_F(PanelTest, TheSunSlidersMoveTheSunAndLitSmokeSwitchesOff) {
    const Rect r = rect("sun_elevation");  // a slider over [1, 90] degrees
    // Far past the left end: the lowest sun the engine accepts, and the scene's sun follows.
    drag(r.x0 + 0.5f * (r.x1 - r.x0), r.x0 - 300.0f, r.cy());
    EXPECT_DOUBLE_EQ(game.options().sunElevation, 1.0);
    EXPECT_LT(game.sun().toSun.y, 0.02f);
    EXPECT_TRUE(game.options().litSmoke);
    click(rect("lit_smoke"));
    EXPECT_FALSE(game.options().litSmoke);
    click(rect("lit_smoke"));
    EXPECT_TRUE(game.options().litSmoke);
    EXPECT_EQ(cube::gl::errorCount(), 0) << cube::gl::lastError();
}

TEST_F(PanelTest, ThePanelAddsNoGlErrorAndRestoresTheGlState) {
    for (int i = 0; i < 3; ++i) frame();
    ASSERT_EQ(cube::gl::errorCount(), 0) << cube::gl::lastError();
    // A host state unlike the panel's: everything it sets must come back as it was.
    GLuint texture = 0, vao = 0;
    glGenTextures(1, &texture);
    glGenVertexArrays(1, &vao);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture);
    glActiveTexture(GL_TEXTURE2);
    glBindVertexArray(vao);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GEQUAL);
    glDepthMask(GL_FALSE);
    glEnable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glBlendFuncSeparate(GL_ONE, GL_ZERO, GL_ZERO, GL_ONE);
    glBlendEquationSeparate(GL_FUNC_SUBTRACT, GL_MAX);
    glDisable(GL_SCISSOR_TEST);
    glScissor(3, 4, 5, 6);
    auto snapshot = [] {
        std::vector<GLint> s;
        for (GLenum e : {GL_CURRENT_PROGRAM, GL_VERTEX_ARRAY_BINDING, GL_ARRAY_BUFFER_BINDING, GL_ACTIVE_TEXTURE,
                         GL_DEPTH_FUNC, GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB, GL_BLEND_SRC_ALPHA, GL_BLEND_DST_ALPHA,
                         GL_BLEND_EQUATION_RGB, GL_BLEND_EQUATION_ALPHA, GL_DRAW_FRAMEBUFFER_BINDING}) {
            GLint v = 0;
            glGetIntegerv(e, &v);
            s.push_back(v);
        }
        GLint box[4];
        glGetIntegerv(GL_SCISSOR_BOX, box);
        s.insert(s.end(), box, box + 4);
        GLint active = 0, tex0 = 0, sampler0 = 0;
        glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
        glActiveTexture(GL_TEXTURE0);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &tex0);
        glGetIntegerv(GL_SAMPLER_BINDING, &sampler0);
        glActiveTexture(GLenum(active));
        s.push_back(tex0);
        s.push_back(sampler0);
        for (GLenum cap : {GL_DEPTH_TEST, GL_CULL_FACE, GL_BLEND, GL_SCISSOR_TEST}) s.push_back(glIsEnabled(cap));
        GLboolean mask = GL_TRUE;
        glGetBooleanv(GL_DEPTH_WRITEMASK, &mask);
        s.push_back(mask);
        return s;
    };
    const std::vector<GLint> before = snapshot();
    panel.drawNow(kW, kH);
    const std::vector<GLint> after = snapshot();
    EXPECT_EQ(before, after);
    glBindVertexArray(0);
    glDeleteVertexArrays(1, &vao);
    glDeleteTextures(1, &texture);
    glActiveTexture(GL_TEXTURE0);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glBlendFunc(GL_ONE, GL_ZERO);
    glBlendEquation(GL_FUNC_ADD);
    EXPECT_EQ(cube::gl::errorCount(), 0) << cube::gl::lastError();
}

TEST(PanelOff, TheFrameIsByteIdenticalToARunWithoutThePanel) {
    ReactionCopy copy;
    std::string error;
    auto run = [&](int mode) {  // 0: no panel, 1: panel set but hidden, 2: panel shown
        cube::Game game;
        EXPECT_TRUE(game.Init(options(copy.dir(), 480, 360), &error)) << error;
        cube::TweakPanel panel;
        if (mode > 0) {
            EXPECT_TRUE(panel.init(game, &error)) << error;
            panel.setVisible(mode == 2);
            game.setOverlay(&panel);
        }
        for (int i = 0; i < 40; ++i) {
            if (i + 1 == 40) game.captureNextFrame();
            game.Dyn(1.0f / 60.0f);
        }
        game.setOverlay(nullptr);
        return game.lastFrame().pixels;
    };
    const std::vector<uint8_t> bare = run(0), hidden = run(1), shown = run(2);
    ASSERT_FALSE(bare.empty());
    EXPECT_TRUE(bare == hidden) << "a hidden panel changed the frame";
    EXPECT_FALSE(bare == shown) << "the shown panel drew nothing (this test could not fail)";
}

TEST_F(PanelTest, AFileChangedOnDiskIsTakenLiveWhenItHasNoUnsavedEdits) {
    // Another editor adds a reaction to the burnout file; no --watch: the panel notices.
    const int running = plugin->reactionCount();
    const std::string path = copy.file("burnout_smoke.yaml");
    std::string text = readFile(path);
    text += "  - name: burnout_smoke_front\n    type: wheel_smoke\n    trigger: {wheels: front}\n";
    writeFile(path, text);
    for (int i = 0; i < 31; ++i) frame();  // the panel looks at the files twice a second
    EXPECT_EQ(plugin->reactionCount(), running + 1);
    EXPECT_EQ(game.specialFX().reactionCount(), running + 1) << "the game's Reactions follow the new set";
    EXPECT_EQ(reactionIndex(*plugin, "burnout_smoke_front") >= 0, true);
    EXPECT_EQ(plugin->stats().apiErrors, 0);
    EXPECT_EQ(panel.session().documents()[size_t(panel.session().documentOf(burnout))].text, text);
}

TEST_F(PanelTest, CtrlZUndoesADragAsOneStepAndCtrlYRedoesIt) {
    const Rect r = rect("burnout_smoke/particle.size_variation");
    drag(r.x0 + 0.25f * (r.x1 - r.x0), r.x1 + 300.0f, r.cy());  // several values, one drag
    ASSERT_EQ(value("particle.size_variation"), "0.9");
    auto chord = [&](UiKey k) {
        key(UiKey::Ctrl, true);
        key(k, true);
        key(k, false);
        key(UiKey::Ctrl, false);
        for (int i = 0; i < 4; ++i) frame();
    };
    chord(UiKey::Z);
    EXPECT_EQ(value("particle.size_variation"), "0.25");
    chord(UiKey::Y);
    EXPECT_EQ(value("particle.size_variation"), "0.9");
}

TEST_F(PanelTest, CameraPresetsMoveTheMainCamera) {
    const glm::vec3 car = game.vehicle().pose().position;
    EXPECT_GT(glm::length(game.chaseView().camera().eye - car), 7.0f);  // chase: 7.5 m behind
    click(rect("camera_burnout"));
    frame();
    EXPECT_EQ(game.cameraPreset(), cube::CameraPreset::BurnoutCloseUp);
    const glm::vec3 carNow = game.vehicle().pose().position;
    EXPECT_LT(glm::length(game.chaseView().camera().eye - carNow), 5.0f);  // beside the rear axle
    ASSERT_TRUE(game.hasBarrier());
    click(rect("camera_barrier"));
    frame();
    EXPECT_EQ(game.cameraPreset(), cube::CameraPreset::Barrier);
    const glm::vec3 toTarget = game.chaseView().camera().target - game.chaseView().camera().eye;
    EXPECT_GE(glm::length(toTarget), 12.0f * 0.99f);
    click(rect("camera_chase"));
    frame();
    EXPECT_EQ(game.cameraPreset(), cube::CameraPreset::Chase);
}

TEST_F(PanelTest, AFileChangedOnDiskDuringEditsAsksTheUserAndKeepsTheEditsWhenToldTo) {
    const Rect r = rect("burnout_smoke/particle.size_variation");
    drag(r.x0 + 0.5f * (r.x1 - r.x0), r.x1 + 300.0f, r.cy());
    ASSERT_EQ(value("particle.size_variation"), "0.9");
    const std::string path = copy.file("burnout_smoke.yaml");
    std::string disk = readFile(path);
    disk.replace(disk.find("rate: 90"), 8, "rate: 70");
    writeFile(path, disk);
    for (int i = 0; i < 31; ++i) frame();
    // Nothing changed behind the user's back: the question is on screen.
    EXPECT_EQ(value("emission.rate"), "90");
    EXPECT_EQ(value("particle.size_variation"), "0.9");
    click(rect("conflict:keep"));
    frame();
    float x0, y0, x1, y1;
    EXPECT_FALSE(panel.widgetRect("conflict:keep", &x0, &y0, &x1, &y1)) << "the question was answered";
    EXPECT_EQ(value("particle.size_variation"), "0.9");
    EXPECT_EQ(value("emission.rate"), "90");
    // Save now overwrites the disk's version with the panel's.
    click(rect("save:burnout_smoke.yaml"));
    EXPECT_NE(readFile(path).find("size_variation: 0.9"), std::string::npos);
    EXPECT_NE(readFile(path).find("rate: 90"), std::string::npos);
}

}  // namespace
