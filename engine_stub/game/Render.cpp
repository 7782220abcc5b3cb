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
        for (Key k : {Key::P, Key::Q, Key::M, Key::H, Key::B, Key::E}) p.keyPressed(k);  // typed text
        return;
    }
    if (p.keyPressed(Key::P)) o.prepassEqual = !o.prepassEqual;
    fx::RenderOptions ro = plugin ? plugin->renderOptions() : fx::RenderOptions{};
    if (p.keyPressed(Key::Q)) ro.quarterRes = !ro.quarterRes;
    if (p.keyPressed(Key::B)) ro.bilinearUpsample = !ro.bilinearUpsample;
    if (p.keyPressed(Key::M)) {
        // FromReaction -> Hard -> Soft -> Spherical -> Mega -> FromReaction
        ro.techniqueOverride = nextTechniqueMode(ro.techniqueOverride).technique;
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

bool Render::Dyn(Game& game, const RenderFrameOutputs& out) {
    Trace::call("Render::Dyn");
    handleKeys(game);
    Platform& platform = game.platform();
    const int w = platform.width(), h = platform.height();
    if (w <= 0 || h <= 0) return false;  // minimised: nothing to draw, nothing allocated

    const Options& options = game.options();
    cubeScene& scene = game.scene();
    cubeView& chase = game.chaseView();
    cubeView& chase2 = game.chase2View();
    cubeView& mirror = game.mirrorView();
    SpecialFX& fx = game.specialFX();
    scene.setCarTransform(game.vehicle().transform());
    chase.setSize(w, h);
    mirror.setSize(std::max(1, int(w * 0.30f)), std::max(1, int(h * 0.13f)));

    rtt::RenderTargetPool& pool = game.pool();
    rtt::FrameGraph& graph = game.graph();
    pool.setViewSize(w, h);
    pool.beginFrame();
    graph.reset();

    FrameSettings settings;
    settings.prepassEqual = options.prepassEqual;
    settings.pluginImmediate = options.pluginZBuffer;
    settings.pluginLinearDepth = options.pluginLinearDepth;
    settings.plugin = options.effects ? fx.plugin() : nullptr;
    settings.drawLegacy = options.effects;
    settings.cameraQuads = game.cameraQuads().empty() ? nullptr : &game.cameraQuads();
    if (out.sceneDepth) {
        out.sceneDepth->clear();
        settings.sceneDepthOut = out.sceneDepth;
    }
    settings.hud = options.hud;
    if (settings.hud) {
        char text[160];
        const fx::RenderOptions ro = settings.plugin ? settings.plugin->renderOptions() : fx::RenderOptions{};
        std::snprintf(text, sizeof text, "%s  %s%s%s  t=%.2fs  particles %d",
                      fx.path() == FxPath::Legacy ? "legacy smoke" : "fx plugin",
                      settings.plugin ? techniqueMode(ro.techniqueOverride).label : "hard sprites",
                      settings.prepassEqual ? " +prepass-EQUAL" : "",
                      ro.quarterRes ? (ro.bilinearUpsample ? " +quarter(bilinear)" : " +quarter") : "",
                      game.time(), fx.particlesAlive());
        settings.hudText = text;
    }
    std::vector<cubeView*> views;
    rtt::FrameGraphResource sceneColor;
    if (options.split) {
        // Two players side by side in one framebuffer: one colour target with one z-buffer, each
        // chase view drawing into its half (cubeView::placeIn), each with its own smoke. The
        // target is cleared once here, before either view draws.
        const int left = w / 2;
        chase.setSize(left, h);
        chase2.setSize(w - left, h);
        rtt::FrameGraph::TargetDesc d;
        d.width = w;
        d.height = h;
        d.color[0] = rtt::ColorFormat::RGBA8;
        d.depth = scene.renderer().reversedZ() ? rtt::DepthFormat::Depth32F : rtt::DepthFormat::Depth24;
        const rtt::FrameGraphResource shared = graph.create("split.color", d);
        const bool reversed = scene.renderer().reversedZ();
        graph.addPass("split.clear", 0, [&](rtt::PassBuilder& b) { b.write(shared); },
                      [shared, reversed](rtt::PassContext& ctx) {
                          rtt::ClearValues cv;
                          cv.color[0] = {0.0f, 0.0f, 0.0f, 1.0f};
                          cv.depth = reversed ? 0.0f : 1.0f;
                          ctx.clear(shared, cv);
                      });
        chase.placeIn(shared, 0, 0, w, h);
        chase2.placeIn(shared, left, 0, w, h);
        settings.hud = false;  // the HUD is drawn over a whole target
        views = {&chase, &chase2};
        scene.Render(graph, views, settings);
        sceneColor = shared;
    } else if (options.splitAlone != 0) {
        // One half of --split on its own: the same camera over a window of the half's size.
        cubeView& v = options.splitAlone == 2 ? chase2 : chase;
        v.setSize(w, h);
        settings.hud = false;
        views = {&v};
        sceneColor = scene.Render(graph, views, settings);
    } else {
        chase.placeIn(rtt::FrameGraphResource{}, 0, 0, 0, 0);
        if (options.mirror) views.push_back(&mirror);
        views.push_back(&chase);
        sceneColor = scene.Render(graph, views, settings);
    }

    const rtt::FrameGraphResource color =
        game.overlay() ? game.overlay()->declarePasses(game, graph, sceneColor, w, h) : sceneColor;

    // [present] the side effect every frame keeps: show the frame (window) and/or read it back.
    ImageRGBA8* const frame = out.frame;
    const bool window = platform.backend() == Backend::GLFW;
    graph.addPass("present", kPresentOrder,
                  [&](rtt::PassBuilder& b) {
                      b.read(color);
                      b.sideEffect();
                  },
                  [frame, color, window, w, h](rtt::PassContext& ctx) {
                      if (window) rtt::present(ctx.pool(), ctx.handle(color), 0, 0, 0, w, h);
                      if (frame) {
                          frame->width = w;
                          frame->height = h;
                          rtt::readRGBA8(ctx.pool(), ctx.handle(color), 0, &frame->pixels);
                      }
                  });
    if (!graph.compile()) {
        std::fprintf(stderr, "frame graph: %s\n", graph.report().error.c_str());
        pool.endFrame();
        return true;
    }
    graph.execute();
    if (!graph.report().error.empty()) std::fprintf(stderr, "frame graph: %s\n", graph.report().error.c_str());
    pool.endFrame();
    if (out.passRuns)
        for (const std::string& n : graph.report().executed) ++(*out.passRuns)[n];
    if (out.passCulls)
        for (const std::string& n : graph.report().culled) ++(*out.passCulls)[n];
    if (window) platform.present();
    return true;
}

}  // namespace cube
