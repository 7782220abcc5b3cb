#include "game/Render.h"

#include <cstdio>

#include "game/Game.h"
#include "game/TechniqueModes.h"
#include "platform/Trace.h"
#include "rtt/Blit.h"
#include "rtt/Readback.h"
#include "view/Buckets.h"

namespace cube {

void Render::handleKeys(Game& game) {
    Platform& p = game.platform();
    Options& o = game.options();
    fx::Plugin* plugin = game.specialFX().plugin();
    if (game.overlay() && game.overlay()->wantsKeyboard()) {
        for (Key k : {Key::P, Key::Q, Key::M, Key::H, Key::S, Key::B, Key::E}) p.keyPressed(k);  // typed text
        return;
    }
    if (p.keyPressed(Key::P)) o.prepassEqual = !o.prepassEqual;
    fx::RenderOptions ro = plugin ? plugin->renderOptions() : fx::RenderOptions{};
    if (p.keyPressed(Key::Q)) ro.quarterRes = !ro.quarterRes;
    if (p.keyPressed(Key::B)) ro.bilinearUpsample = !ro.bilinearUpsample;
    if (p.keyPressed(Key::M)) {
        // FromReaction -> Hard -> Soft -> Spherical -> Mega -> FromReaction
        ro.techniqueOverride = fx::Technique((size_t(ro.techniqueOverride) + 1) % kTechniqueModeCount);
    }
    if (p.keyPressed(Key::H)) o.hud = !o.hud;
    if (p.keyPressed(Key::E)) game.fireExplosionAtCar();
    if (!plugin) return;
    const fx::RenderOptions was = plugin->renderOptions();
    plugin->setRenderOptions(ro);
    // A switch may reach programs the old options did not (quarter-res, mega): built now, between
    // frames, not while the next frame's passes are declared.
    if (ro.techniqueOverride != was.techniqueOverride || ro.quarterRes != was.quarterRes ||
        ro.bilinearUpsample != was.bilinearUpsample) {
        (void)plugin->prepareGl(nullptr);  // a failure is logged once by the plugin
    }
}

void Render::Dyn(Game& game) {
    Trace::call("Render::Dyn");
    handleKeys(game);
    Platform& platform = game.platform();
    const int w = platform.width(), h = platform.height();
    if (w <= 0 || h <= 0) return;  // minimised: nothing to draw, nothing allocated

    game.scene_.setCarTransform(game.vehicle_.transform());
    game.chase_.setSize(w, h);
    game.mirror_.setSize(std::max(1, int(w * 0.30f)), std::max(1, int(h * 0.13f)));

    rtt::RenderTargetPool& pool = *game.pool_;
    rtt::FrameGraph& graph = *game.graph_;
    pool.setViewSize(w, h);
    pool.beginFrame();
    graph.reset();

    FrameSettings settings;
    settings.prepassEqual = game.options_.prepassEqual;
    settings.pluginImmediate = game.options_.pluginZBuffer;
    settings.pluginLinearDepth = game.options_.pluginLinearDepth;
    settings.plugin = game.options_.effects ? game.specialFX_.plugin() : nullptr;
    settings.drawLegacy = game.options_.effects;
    settings.cameraQuads = game.cameraQuads_.empty() ? nullptr : &game.cameraQuads_;
    if (game.captureDepthNext_) {
        game.lastSceneDepth_.clear();
        settings.sceneDepthOut = &game.lastSceneDepth_;
        game.captureDepthNext_ = false;
    }
    settings.hud = game.options_.hud;
    if (settings.hud) {
        char text[160];
        const fx::RenderOptions ro = settings.plugin ? settings.plugin->renderOptions() : fx::RenderOptions{};
        std::snprintf(text, sizeof text, "%s  %s%s%s  t=%.2fs  particles %d",
                      game.specialFX_.path() == FxPath::Legacy ? "legacy smoke" : "fx plugin",
                      settings.plugin ? techniqueMode(ro.techniqueOverride).label : "hard sprites",
                      settings.prepassEqual ? " +prepass-EQUAL" : "",
                      ro.quarterRes ? (ro.bilinearUpsample ? " +quarter(bilinear)" : " +quarter") : "",
                      game.time_, game.specialFX_.particlesAlive());
        settings.hudText = text;
    }
    std::vector<cubeView*> views;
    rtt::FrameGraphResource sceneColor;
    if (game.options_.split) {
        // Two players side by side in one framebuffer: one colour target with one z-buffer, each
        // chase view drawing into its half (cubeView::placeIn), each with its own smoke. The
        // target is cleared once here, before either view draws.
        const int left = w / 2;
        game.chase_.setSize(left, h);
        game.chase2_.setSize(w - left, h);
        rtt::FrameGraph::TargetDesc d;
        d.width = w;
        d.height = h;
        d.color[0] = rtt::ColorFormat::RGBA8;
        d.depth = game.scene_.renderer().reversedZ() ? rtt::DepthFormat::Depth32F : rtt::DepthFormat::Depth24;
        const rtt::FrameGraphResource shared = graph.create("split.color", d);
        const bool reversed = game.scene_.renderer().reversedZ();
        graph.addPass("split.clear", 0, [&](rtt::PassBuilder& b) { b.write(shared); },
                      [shared, reversed](rtt::PassContext& ctx) {
                          rtt::ClearValues cv;
                          cv.color[0] = {0.0f, 0.0f, 0.0f, 1.0f};
                          cv.depth = reversed ? 0.0f : 1.0f;
                          ctx.clear(shared, cv);
                      });
        game.chase_.placeIn(shared, 0, 0, w, h);
        game.chase2_.placeIn(shared, left, 0, w, h);
        settings.hud = false;  // the HUD is drawn over a whole target
        views = {&game.chase_, &game.chase2_};
        game.scene_.Render(graph, views, settings);
        sceneColor = shared;
    } else if (game.options_.splitAlone != 0) {
        // One half of --split on its own: the same camera over a window of the half's size.
        cubeView& v = game.options_.splitAlone == 2 ? game.chase2_ : game.chase_;
        v.setSize(w, h);
        settings.hud = false;
        views = {&v};
        sceneColor = game.scene_.Render(graph, views, settings);
    } else {
        game.chase_.placeIn(rtt::FrameGraphResource{}, 0, 0, 0, 0);
        if (game.options_.mirror) views.push_back(&game.mirror_);
        views.push_back(&game.chase_);
        sceneColor = game.scene_.Render(graph, views, settings);
    }

    const rtt::FrameGraphResource color =
        game.overlay_ ? game.overlay_->declarePasses(game, graph, sceneColor, w, h) : sceneColor;

    // [present] the side effect every frame keeps: show the frame (window) and/or read it back.
    const bool capture = game.captureNext_;
    const bool window = platform.backend() == Backend::GLFW;
    Game* g = &game;
    graph.addPass("present", kPresentOrder,
                  [&](rtt::PassBuilder& b) {
                      b.read(color);
                      b.sideEffect();
                  },
                  [g, color, capture, window, w, h](rtt::PassContext& ctx) {
                      if (window) rtt::present(ctx.pool(), ctx.handle(color), 0, 0, 0, w, h);
                      if (capture) {
                          g->lastFrame_.width = w;
                          g->lastFrame_.height = h;
                          rtt::readRGBA8(ctx.pool(), ctx.handle(color), 0, &g->lastFrame_.pixels);
                      }
                  });
    game.captureNext_ = false;
    if (!graph.compile()) {
        std::fprintf(stderr, "frame graph: %s\n", graph.report().error.c_str());
        pool.endFrame();
        return;
    }
    graph.execute();
    if (!graph.report().error.empty()) std::fprintf(stderr, "frame graph: %s\n", graph.report().error.c_str());
    pool.endFrame();
    for (const std::string& n : graph.report().executed) ++game.passRuns_[n];
    for (const std::string& n : graph.report().culled) ++game.passCulls_[n];
    if (window) platform.present();
}

}  // namespace cube
