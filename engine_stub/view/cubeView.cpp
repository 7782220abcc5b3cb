#include "view/cubeView.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "platform/Trace.h"
#include "rtt/Readback.h"
#include "rtt/RenderTargetPool.h"
#include "view/Buckets.h"
#include "view/FxFrameBuilder.h"
#include "view/cubeScene.h"

namespace cube {

glm::mat4 ViewCamera::view() const { return glm::lookAt(eye, target, up); }
glm::mat4 ViewCamera::proj(float aspect, bool reversedZ) const {
    const float a = aspect > 0.0f ? aspect : 1.0f;
    // Zero-to-one with the planes swapped is reversed-Z: z_ndc = n/(f-n) * (f/d - 1), 1 at the
    // near plane, 0 at the far one. Float keeps its relative precision near 0, so depth
    // resolution stays proportional to distance at any near/far ratio.
    if (reversedZ) return glm::perspectiveRH_ZO(fovY, a, farPlane, nearPlane);
    return glm::perspective(fovY, a, nearPlane, farPlane);
}


bool cubeView::bindColor(rtt::PassContext& ctx, rtt::FrameGraphResource color) const {
    if (!ctx.bindForDraw(color)) return false;
    if (placed()) ctx.setViewport(x_, y_, width_, height_);
    return true;
}

bool cubeView::bindColor(rtt::PassContext& ctx, rtt::FrameGraphResource color, rtt::FrameGraphResource second) const {
    if (!ctx.bindForDraw(color, second)) return false;
    if (placed()) ctx.setViewport(x_, y_, width_, height_);
    return true;
}

rtt::FrameGraphResource cubeView::Render(cubeScene& scene, rtt::FrameGraph& graph, const FrameSettings& settings) {
    Trace::call("cubeView::Render");
    // (CUBE renders shadow maps here; this stand-in has none.)
    return RenderObjects(scene, graph, settings);
}

void cubeView::recordBuckets(cubeScene& scene) {
    scene.renderer().meshes().record(scene.data(), scene.carNode(), scene.carTransform(), &all_);
    opaque_.clear();
    alphaTested_.clear();
    const glm::mat4 viewProj = proj_ * view_;
    for (const MeshDraw& d : all_) {
        // Frustum test of the world box against the six clip planes (conservative).
        bool outside = false;
        for (int plane = 0; plane < 6 && !outside; ++plane) {
            const int axis = plane / 2;
            const float sign = (plane % 2) ? -1.0f : 1.0f;
            const glm::vec4 p = glm::vec4(viewProj[0][3], viewProj[1][3], viewProj[2][3], viewProj[3][3]) +
                                sign * glm::vec4(viewProj[0][axis], viewProj[1][axis], viewProj[2][axis],
                                                 viewProj[3][axis]);
            const glm::vec3 n(p);
            const glm::vec3 far(n.x >= 0 ? d.worldMax.x : d.worldMin.x, n.y >= 0 ? d.worldMax.y : d.worldMin.y,
                                n.z >= 0 ? d.worldMax.z : d.worldMin.z);
            outside = glm::dot(n, far) + p.w < 0.0f;
        }
        if (outside) continue;
        (d.alphaTested ? alphaTested_ : opaque_).push_back(d);
    }
    // Opaque front to back (early depth rejection); the order is identical in both depth modes.
    const glm::vec3 eye = camera_.eye;
    std::stable_sort(opaque_.begin(), opaque_.end(), [&](const MeshDraw& a, const MeshDraw& b) {
        const glm::vec3 ca = 0.5f * (a.worldMin + a.worldMax), cb = 0.5f * (b.worldMin + b.worldMax);
        return glm::dot(ca - eye, ca - eye) < glm::dot(cb - eye, cb - eye);
    });
}

rtt::FrameGraphResource cubeView::RenderObjects(cubeScene& scene, rtt::FrameGraph& graph,
                                                const FrameSettings& settings) {
    Trace::call("cubeView::RenderObjects");
    // Camera parameters (view, fov, clip planes), then the buckets (culled, sorted).
    view_ = camera_.view();
    reversedZ_ = scene.renderer().reversedZ();
    fog_ = scene.renderer().fog();
    proj_ = camera_.proj(height_ > 0 ? float(width_) / float(height_) : 1.0f, reversedZ_);
    recordBuckets(scene);

    // The view's frame, top to bottom in pipeline order. Each pass declares what it reads and
    // writes; compile() culls a pass whose output nobody reads, allocates only what kept passes
    // use, and decides where the linear scene depth comes from: the depth prepass when it is
    // declared and something reads scene_depth (the colour target then draws on its z-buffer,
    // PassContext::sharesDepth), else the opaque and alpha-tested passes as a second render
    // target when something reads it (PassContext::isNeeded), else nobody.
    const Targets t = declareTargets(graph);
    declareSmokeShadow(graph, t, settings);          // CUBE's shadow maps: here only the smoke's
    declareDepthPrepass(scene, graph, t, settings);  // prepass-EQUAL only; not taken unless scene_depth is read
    declareOpaque(scene, graph, t, settings);        // writes the linear depth too when read, no prepass
    declareAlphaTested(scene, graph, t);
    declareSky(scene, graph, t);
    declareLegacySprites(scene, graph, t, settings);
    declarePluginPasses(graph, t, settings);         // soft/spherical read scene depth; quarter-res composites
    declareDepthReadback(graph, t, settings);        // only when the application asked for it
    declareHud(scene, graph, t, settings);           // mirror inset and text
    return t.color;
}

cubeView::Targets cubeView::declareTargets(rtt::FrameGraph& graph) {
    // A placed view's linear depth is its shared target's size (it is the opaque pass's second
    // render target, which must match the colour); the plugin reads it at the view's origin.
    auto sized = [&](rtt::RenderTargetDesc d) {
        d.width = placed() ? targetWidth_ : width_;
        d.height = placed() ? targetHeight_ : height_;
        return d;
    };
    names_.clear();
    names_.reserve(8);
    names_.push_back(name_ + ".scene_depth");
    rtt::RenderTargetDesc depthDesc;
    depthDesc.color[0] = rtt::ColorFormat::R32F;
    depthDesc.depth = zBufferFormat();  // the prepass's z-buffer; compile() drops it unless shared
    depthDesc.filter = rtt::Filter::Nearest;
    Targets t;
    t.sceneDepth = graph.create(names_.back().c_str(), sized(depthDesc));
    if (placed()) {
        t.color = placedIn_;
        return t;
    }

    // Draws on the prepass z-buffer when a kept prepass wrote it (prepass-EQUAL), else on its own.
    names_.push_back(name_ + ".color");
    rtt::FrameGraph::TargetDesc colorDesc;
    static_cast<rtt::RenderTargetDesc&>(colorDesc) = sized(rtt::RenderTargetDesc{});
    colorDesc.color[0] = rtt::ColorFormat::RGBA8;
    colorDesc.depth = zBufferFormat();
    colorDesc.sharedDepthIfWritten = t.sceneDepth;
    t.color = graph.create(names_.back().c_str(), colorDesc);
    return t;
}

rtt::DepthFormat cubeView::zBufferFormat() const {
    return reversedZ_ ? rtt::DepthFormat::Depth32F : rtt::DepthFormat::Depth24;
}

CameraMatrices cubeView::cameraMatrices() const {
    CameraMatrices cam;
    cam.view = view_;
    cam.proj = proj_;
    cam.fovY = camera_.fovY;
    cam.aspect = height_ > 0 ? float(width_) / float(height_) : 1.0f;
    return cam;
}

void cubeView::declareDepthPrepass(cubeScene& scene, rtt::FrameGraph& graph, const Targets& t,
                                   const FrameSettings& settings) {
    // Linear view depth + z-buffer, for prepass-EQUAL only. The pass only offers scene_depth: it
    // runs when a later kept pass reads it (and is then its writer: the colour target draws on
    // its z-buffer, the opaque pass's offer is not taken), else it is not taken. The immediate
    // path reads the colour target's own z-buffer: no prepass to offer.
    if (!settings.prepassEqual || (settings.plugin && settings.pluginImmediate)) return;
    const CameraMatrices cam = cameraMatrices();
    const CameraQuads quads = settings.cameraQuads ? *settings.cameraQuads : CameraQuads{};
    SceneRenderer* r = &scene.renderer();
    const rtt::FrameGraphResource depth = t.sceneDepth;
    graph.addPass(passName(bucketInfo(Bucket::DepthPrepass).name).c_str(),
                  order(bucketInfo(Bucket::DepthPrepass).order),
                  [&](rtt::PassBuilder& b) { b.writeIfRead(depth); },
                  [this, r, depth, cam, quads, reversed = reversedZ_](rtt::PassContext& ctx) {
                      rtt::ClearValues cv;
                      cv.color[0] = {1e30f, 0.0f, 0.0f, 0.0f};  // "infinitely far" where nothing is drawn
                      cv.depth = reversed ? 0.0f : 1.0f;          // the far plane
                      ctx.clear(depth, cv);
                      ctx.bindForDraw(depth);
                      r->depthPrepass(opaque_, alphaTested_, cam, quads);
                  });
}

void cubeView::declareOpaque(cubeScene& scene, rtt::FrameGraph& graph, const Targets& t,
                             const FrameSettings& settings) {
    // LEQUAL with its own z-buffer, or EQUAL on the prepass z-buffer without depth writes when
    // compile() gave the colour target the prepass's (sharesDepth); the linear depth as a second
    // render target only when it is read and no prepass wrote it (isNeeded).
    const CameraMatrices cam = cameraMatrices();
    const CameraQuads quads = settings.cameraQuads ? *settings.cameraQuads : CameraQuads{};
    SceneRenderer* r = &scene.renderer();
    const rtt::FrameGraphResource color = t.color, depth = t.sceneDepth;
    // The smoke's shadow darkens the ground (and whatever else lies under the cloud).
    const rtt::FrameGraphResource smoke{smokeShadow_.opacity.id};
    const glm::mat4 worldToSmoke = smokeShadow_.worldToShadow;
    graph.addPass(passName(bucketInfo(Bucket::Opaque).name).c_str(), order(bucketInfo(Bucket::Opaque).order),
                  [&](rtt::PassBuilder& b) {
                      b.write(color);
                      b.writeIfRead(depth);
                      if (smoke.valid()) b.read(smoke);
                  },
                  [this, r, color, depth, cam, quads, smoke, worldToSmoke,
                   reversed = reversedZ_](rtt::PassContext& ctx) {
                      r->setSmokeShadow(smoke.valid() ? ctx.texture(smoke, 0) : 0u, worldToSmoke);
                      const bool equal = ctx.sharesDepth(color);
                      rtt::ClearValues cv;
                      cv.color[0] = {0.0f, 0.0f, 0.0f, 1.0f};
                      cv.depth = reversed ? 0.0f : 1.0f;
                      cv.clearDepth = !equal;
                      cv.clearStencil = !equal;
                      if (!placed()) ctx.clear(color, cv);  // a shared target is cleared once, by its owner
                      if (ctx.isNeeded(depth)) {
                          rtt::ClearValues far;
                          far.color[0] = {1e30f, 0.0f, 0.0f, 0.0f};  // "infinitely far" where nothing is drawn
                          ctx.clear(depth, far);
                          if (!bindColor(ctx, color, depth)) return;
                      } else {
                          bindColor(ctx, color);
                      }
                      r->opaque(opaque_, cam, equal, quads);
                  });
}

void cubeView::declareAlphaTested(cubeScene& scene, rtt::FrameGraph& graph, const Targets& t) {
    // Nothing in the race scene uses it: an empty bucket declares no pass.
    if (alphaTested_.empty()) return;
    const CameraMatrices cam = cameraMatrices();
    SceneRenderer* r = &scene.renderer();
    const rtt::FrameGraphResource color = t.color, depth = t.sceneDepth;
    graph.addPass(passName(bucketInfo(Bucket::AlphaTested).name).c_str(),
                  order(bucketInfo(Bucket::AlphaTested).order),
                  [&](rtt::PassBuilder& b) {
                      b.write(color);
                      b.writeIfRead(depth);  // as the opaque pass: blends onto its linear depth
                  },
                  [this, r, color, depth, cam](rtt::PassContext& ctx) {
                      if (ctx.isNeeded(depth) ? !bindColor(ctx, color, depth) : !bindColor(ctx, color)) return;
                      r->alphaTested(alphaTested_, cam, ctx.sharesDepth(color));
                  });
}

void cubeView::declareSky(cubeScene& scene, rtt::FrameGraph& graph, const Targets& t) {
    // At the far plane where nothing was drawn.
    const CameraMatrices cam = cameraMatrices();
    const SceneRenderer* r = &scene.renderer();
    const rtt::FrameGraphResource color = t.color;
    graph.addPass(passName(bucketInfo(Bucket::Sky).name).c_str(), order(bucketInfo(Bucket::Sky).order),
                  [&](rtt::PassBuilder& b) { b.write(color); },
                  [this, r, color, cam](rtt::PassContext& ctx) {
                      bindColor(ctx, color);
                      r->sky(cam);
                  });
}

void cubeView::declareLegacySprites(cubeScene& scene, rtt::FrameGraph& graph, const Targets& t,
                                    const FrameSettings& settings) {
    // The old CUBE path: CPU-aligned sprites, only when a legacy system has live particles.
    bool anyLegacy = false;
    for (const auto& ps : scene.particleSystems())
        anyLegacy |= settings.drawLegacy && ps->kind() == cubeParticleSystem::Kind::Legacy && ps->alive() > 0;
    if (!anyLegacy) return;
    const glm::mat4 view = view_, viewProj = proj_ * view_;
    const glm::mat4 inv = glm::inverse(view);
    const glm::vec3 eye = camera_.eye, right(inv[0]), up(inv[1]);
    cubeScene* sc = &scene;
    const rtt::FrameGraphResource color = t.color;
    graph.addPass((name_ + ".legacy_smoke").c_str(), order(bucketInfo(Bucket::Particles).order),
                  [&](rtt::PassBuilder& b) { b.write(color); },
                  [this, sc, color, viewProj, eye, right, up](rtt::PassContext& ctx) {
                      bindColor(ctx, color);
                      static std::vector<cubeParticleSystem::SpriteVertex> quads;
                      for (const auto& ps : sc->particleSystems()) {
                          if (ps->kind() != cubeParticleSystem::Kind::Legacy) continue;
                          ps->BuildQuads(eye, right, up, &quads);
                          sc->renderer().sprites(quads, viewProj, ps->tint());
                      }
                  });
}

void cubeView::declarePluginPasses(rtt::FrameGraph& graph, const Targets& t, const FrameSettings& settings) {
    // The plugin adds its passes here, straight into the graph (nothing when no particle is
    // visible). A pass of it that reads scene depth is what keeps the depth prepass (or the
    // opaque pass's second render target) alive: compile() decides, nothing here does.
    if (settings.plugin && settings.pluginImmediate) {
        // API 2's immediate path, as an engine without a frame graph uses it: one pass binds the
        // colour target with its z-buffer and the plugin draws into it, copying and linearising
        // that z-buffer itself when a technique reads depth. No linear scene depth is declared.
        fx::Plugin* plugin = settings.plugin;
        const fx::ViewInfo info = pluginView();
        const rtt::FrameGraphResource color = t.color;
        fx::HostDepth depth;  // the colour target's own z-buffer, as the scene was drawn into it
        depth.clipDepthZeroToOne = reversedZ_;
        graph.addPass(passName("fx_immediate").c_str(), order(bucketInfo(Bucket::Particles).order),
                      [&](rtt::PassBuilder& b) { b.write(color); },
                      [this, plugin, info, depth, color](rtt::PassContext& ctx) {
                          // The view's rectangle as the viewport: renderView draws where it points.
                          if (bindColor(ctx, color)) plugin->renderView(info, depth);
                      });
        return;
    }
    FxFrameBuilder fx(graph, t.color, t.sceneDepth, name_ + ".", order(bucketInfo(Bucket::Particles).order),
                      width_, height_);
    if (placed()) fx.placeView(x_, y_);
    // The z-buffer the opaque pass drew, sampled in place by the plugin: no linear depth is then
    // written. Under prepass-EQUAL it is the prepass's (the colour target draws on it), and
    // reading it is what runs the prepass. Only the reversed-Z float z-buffer is offered: its
    // distance error is about 6e-8 t at any near/far; a standard 24-bit one loses 3e-8 t^2 / near
    // (render/DepthMapping.h: 30 cm at 1 km with near 0.1 m), coarser than a soft particle's
    // softness out there, so under --depth standard the plugin reads the linear R32F as before.
    if (!settings.pluginLinearDepth && reversedZ_) {
        fx.offerZBuffer(settings.prepassEqual ? t.sceneDepth : t.color, true);
    }
    if (settings.plugin) settings.plugin->declarePasses(pluginView(), fx);
}

fx::ViewInfo cubeView::pluginView() const {
    fx::ViewInfo info;
    info.name = name_.c_str();
    // The fog the scene's shaders apply, so the smoke fades with the track behind it.
    info.fog.mode = static_cast<fx::Fog::Mode>(static_cast<int>(fog_.mode));
    info.fog.color = fog_.color;
    info.fog.start = fog_.start;
    info.fog.end = fog_.end;
    info.fog.density = fog_.density;
    info.view = view_;
    info.proj = proj_;
    info.eye = camera_.eye;
    info.nearPlane = camera_.nearPlane;
    info.farPlane = camera_.farPlane;
    info.depth = reversedZ_ ? fx::DepthConvention::ReversedZ : fx::DepthConvention::Standard;
    info.width = width_;
    info.height = height_;
    if (placed()) {  // frame-graph path: where the view lies in sceneColor (renderView reads the viewport)
        info.x = x_;
        info.y = y_;
        info.targetWidth = targetWidth_;
        info.targetHeight = targetHeight_;
    }
    return info;
}

void cubeView::declareSmokeShadow(rtt::FrameGraph& graph, const Targets& t, const FrameSettings& settings) {
    // Nothing unless the plugin lights smoke that is alive (it declares nothing otherwise).
    smokeShadow_ = fx::SmokeShadow{};
    if (!settings.plugin) return;
    FxFrameBuilder fx(graph, t.color, t.sceneDepth, name_ + ".", order(bucketInfo(Bucket::Shadows).order),
                      width_, height_);
    smokeShadow_ = settings.plugin->declareShadowPasses(pluginView(), fx);
}

void cubeView::declareDepthReadback(rtt::FrameGraph& graph, const Targets& t, const FrameSettings& settings) {
    // The frame's own scene depth, for an application that measures against it (fxbench's
    // depth-edge mask): it reads whichever writer compile() picked, so no second copy is drawn.
    if (!settings.sceneDepthOut) return;
    std::vector<float>* out = settings.sceneDepthOut;
    const rtt::FrameGraphResource depth = t.sceneDepth;
    graph.addPass((name_ + ".scene_depth_readback").c_str(), order(bucketInfo(Bucket::Hud).order) - 1,
                  [&](rtt::PassBuilder& b) {
                      b.read(depth);
                      b.sideEffect();
                  },
                  [depth, out](rtt::PassContext& ctx) {
                      if (rtt::readFloat(ctx.pool(), ctx.handle(depth), 0, rtt::FloatLayout::Native, out) !=
                          rtt::RttError::None)
                          out->clear();
                  });
}

void cubeView::declareHud(cubeScene& scene, rtt::FrameGraph& graph, const Targets& t, const FrameSettings& settings) {
    if (!settings.hud && !settings.inset.valid()) return;
    const rtt::FrameGraphResource color = t.color, inset = settings.inset;
    const bool flip = settings.insetFlipX;
    const std::string text = settings.hudText;
    const bool hud = settings.hud;
    const int w = width_, h = height_;
    SceneRenderer* r = &scene.renderer();
    graph.addPass(passName(bucketInfo(Bucket::Hud).name).c_str(), order(bucketInfo(Bucket::Hud).order),
                  [&](rtt::PassBuilder& b) {
                      if (inset.valid()) b.read(inset);
                      b.write(color);
                  },
                  [r, color, inset, flip, text, hud, w, h](rtt::PassContext& ctx) {
                      ctx.bindForDraw(color);
                      if (inset.valid()) r->inset(ctx.texture(inset, 0), ctx.width(inset), ctx.height(inset), flip, w, h);
                      if (hud) r->text(text, w, h);
                  });
}

}  // namespace cube
