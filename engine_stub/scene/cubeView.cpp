#include "scene/cubeView.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "game/FxFrameBuilder.h"
#include "game/Trace.h"
#include "rtt/RenderTargetPool.h"
#include "scene/Buckets.h"
#include "scene/cubeScene.h"

namespace cube {

glm::mat4 ViewCamera::view() const { return glm::lookAt(eye, target, up); }
glm::mat4 ViewCamera::proj(float aspect) const {
    return glm::perspective(fovY, aspect > 0.0f ? aspect : 1.0f, nearPlane, farPlane);
}


rtt::FrameGraphResource cubeView::Render(cubeScene& scene, rtt::FrameGraph& graph, const FrameSettings& settings) {
    Trace::call("cubeView::Render");
    // (CUBE renders shadow maps here; this stand-in has none.)
    return RenderObjects(scene, graph, settings);
}

void cubeView::recordBuckets(cubeScene& scene) {
    scene.gpu().record(scene.data(), scene.carNode(), scene.carTransform(), &all_);
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
    // Camera parameters (view, fov, clip planes).
    view_ = camera_.view();
    proj_ = camera_.proj(height_ > 0 ? float(width_) / float(height_) : 1.0f);
    recordBuckets(scene);

    // Particle bucket first, on paper: what it needs decides whether a depth prepass exists.
    FxFrameBuilder fxPasses(graph, name_ + ".", order(bucketInfo(Bucket::Particles).order), width_, height_);
    if (settings.plugin) {
        fx::ViewInfo info;
        info.name = name_.c_str();
        info.view = view_;
        info.proj = proj_;
        info.eye = camera_.eye;
        info.nearPlane = camera_.nearPlane;
        info.farPlane = camera_.farPlane;
        info.width = width_;
        info.height = height_;
        settings.plugin->declarePasses(info, fxPasses);
    }
    const bool needDepth = fxPasses.readsSceneDepth();
    const bool equal = settings.prepassEqual && needDepth;
    prepassDeclared_ = needDepth;

    auto sized = [&](rtt::RenderTargetDesc d) {
        d.width = width_;
        d.height = height_;
        return d;
    };
    names_.clear();
    names_.reserve(8);
    names_.push_back(name_ + ".scene_depth");
    rtt::RenderTargetDesc depthDesc;
    depthDesc.color[0] = rtt::ColorFormat::R32F;
    depthDesc.depth = rtt::DepthFormat::Depth24;
    depthDesc.filter = rtt::Filter::Nearest;
    const rtt::FrameGraphResource sceneDepth = graph.create(names_.back().c_str(), sized(depthDesc));

    names_.push_back(name_ + ".color");
    rtt::FrameGraph::TargetDesc colorDesc;
    static_cast<rtt::RenderTargetDesc&>(colorDesc) = sized(rtt::RenderTargetDesc{});
    colorDesc.color[0] = rtt::ColorFormat::RGBA8;
    if (equal) colorDesc.sharedDepthOf = sceneDepth;
    else colorDesc.depth = rtt::DepthFormat::Depth24;
    const rtt::FrameGraphResource color = graph.create(names_.back().c_str(), colorDesc);

    const glm::mat4 view = view_, proj = proj_;
    const glm::vec3 eye = camera_.eye;
    cubeScene* sc = &scene;
    const int layers = settings.overdrawLayers, cost = settings.overdrawCost;
    const float fovY = camera_.fovY, aspect = height_ > 0 ? float(width_) / float(height_) : 1.0f;

    // [depth prepass] linear view depth + z-buffer; culled unless a particle reads scene depth.
    graph.addPass((name_ + "." + bucketInfo(Bucket::DepthPrepass).name).c_str(),
                  order(bucketInfo(Bucket::DepthPrepass).order),
                  [&](rtt::PassBuilder& b) { b.write(sceneDepth); },
                  [this, sc, sceneDepth, view, proj, layers, fovY, aspect](rtt::PassContext& ctx) {
                      rtt::ClearValues cv;
                      cv.color[0] = {1e30f, 0.0f, 0.0f, 0.0f};  // "infinitely far" where nothing is drawn
                      ctx.clear(sceneDepth, cv);
                      ctx.bindForDraw(sceneDepth);
                      glEnable(GL_DEPTH_TEST);
                      glDepthFunc(GL_LESS);
                      glDepthMask(GL_TRUE);
                      glEnable(GL_CULL_FACE);
                      const gl::Program& p = sc->prepassProgram;
                      glUseProgram(p.id());
                      glUniformMatrix4fv(p.uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
                      glUniformMatrix4fv(p.uniform("uProj"), 1, GL_FALSE, glm::value_ptr(proj));
                      sc->gpu().draw(opaque_, p.uniform("uModel"), -1);
                      sc->gpu().draw(alphaTested_, p.uniform("uModel"), -1);
                      sc->drawOverdrawPanels(p, layers, view, fovY, aspect);
                      glDisable(GL_CULL_FACE);
                      glDisable(GL_DEPTH_TEST);
                      glUseProgram(0);
                  });

    // [opaque] LESS with its own z-buffer, or EQUAL on the prepass z-buffer without depth writes.
    graph.addPass((name_ + "." + bucketInfo(Bucket::Opaque).name).c_str(), order(bucketInfo(Bucket::Opaque).order),
                  [&](rtt::PassBuilder& b) { b.write(color); },
                  [this, sc, color, view, proj, equal, layers, cost, fovY, aspect](rtt::PassContext& ctx) {
                      rtt::ClearValues cv;
                      cv.color[0] = {0.0f, 0.0f, 0.0f, 1.0f};
                      cv.clearDepth = !equal;
                      cv.clearStencil = !equal;
                      ctx.clear(color, cv);
                      ctx.bindForDraw(color);
                      glEnable(GL_DEPTH_TEST);
                      // LEQUAL, not LESS: where two surfaces meet at exactly the same depth the
                      // last drawn wins, which is what EQUAL on the prepass z-buffer does too.
                      // So the two paths give the same pixel even at coplanar seams.
                      glDepthFunc(equal ? GL_EQUAL : GL_LEQUAL);
                      glDepthMask(equal ? GL_FALSE : GL_TRUE);
                      glEnable(GL_CULL_FACE);
                      const gl::Program& p = sc->meshProgram;
                      glUseProgram(p.id());
                      glUniformMatrix4fv(p.uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
                      glUniformMatrix4fv(p.uniform("uProj"), 1, GL_FALSE, glm::value_ptr(proj));
                      sc->gpu().draw(opaque_, p.uniform("uModel"), p.uniform("uBaseColor"));
                      if (layers > 0) {
                          const gl::Program& c = sc->costlyProgram;
                          glUseProgram(c.id());
                          glUniformMatrix4fv(c.uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
                          glUniformMatrix4fv(c.uniform("uProj"), 1, GL_FALSE, glm::value_ptr(proj));
                          glUniform1i(c.uniform("uCost"), cost);
                          sc->drawOverdrawPanels(c, layers, view, fovY, aspect);
                      }
                      glDisable(GL_CULL_FACE);
                      glDepthMask(GL_TRUE);
                      glDepthFunc(GL_LESS);
                      glDisable(GL_DEPTH_TEST);
                      glUseProgram(0);
                  });

    // [alpha-tested] nothing in the race scene uses it: an empty bucket declares no pass.
    if (!alphaTested_.empty()) {
        graph.addPass((name_ + "." + bucketInfo(Bucket::AlphaTested).name).c_str(),
                      order(bucketInfo(Bucket::AlphaTested).order), [&](rtt::PassBuilder& b) { b.write(color); },
                      [this, sc, color, view, proj, equal](rtt::PassContext& ctx) {
                          ctx.bindForDraw(color);
                          glEnable(GL_DEPTH_TEST);
                          glDepthFunc(equal ? GL_EQUAL : GL_LEQUAL);
                          glDepthMask(equal ? GL_FALSE : GL_TRUE);
                          glEnable(GL_CULL_FACE);  // as in the prepass, or EQUAL would differ
                          const gl::Program& p = sc->meshProgram;
                          glUseProgram(p.id());
                          glUniformMatrix4fv(p.uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
                          glUniformMatrix4fv(p.uniform("uProj"), 1, GL_FALSE, glm::value_ptr(proj));
                          sc->gpu().draw(alphaTested_, p.uniform("uModel"), p.uniform("uBaseColor"));
                          glDisable(GL_CULL_FACE);
                          glDepthMask(GL_TRUE);
                          glDepthFunc(GL_LESS);
                          glDisable(GL_DEPTH_TEST);
                          glUseProgram(0);
                      });
    }

    // [sky] at the far plane where nothing was drawn.
    graph.addPass((name_ + "." + bucketInfo(Bucket::Sky).name).c_str(), order(bucketInfo(Bucket::Sky).order),
                  [&](rtt::PassBuilder& b) { b.write(color); },
                  [sc, color, view, proj](rtt::PassContext& ctx) {
                      ctx.bindForDraw(color);
                      glEnable(GL_DEPTH_TEST);
                      glDepthFunc(GL_LEQUAL);
                      glDepthMask(GL_FALSE);
                      const gl::Program& p = sc->skyProgram;
                      glUseProgram(p.id());
                      const glm::mat4 inv = glm::inverse(proj * glm::mat4(glm::mat3(view)));
                      glUniformMatrix4fv(p.uniform("uInvViewProj"), 1, GL_FALSE, glm::value_ptr(inv));
                      glUniform1f(p.uniform("uDepth"), 1.0f);
                      glBindVertexArray(sc->emptyVao);
                      glDrawArrays(GL_TRIANGLES, 0, 3);
                      glBindVertexArray(0);
                      glDepthMask(GL_TRUE);
                      glDepthFunc(GL_LESS);
                      glDisable(GL_DEPTH_TEST);
                      glUseProgram(0);
                  });

    // [particles] legacy sprites (the old CUBE path) ...
    bool anyLegacy = false;
    for (const auto& ps : scene.particleSystems())
        anyLegacy |= settings.drawLegacy && ps->kind() == cubeParticleSystem::Kind::Legacy && ps->alive() > 0;
    if (anyLegacy) {
        const glm::mat4 inv = glm::inverse(view);
        const glm::vec3 right(inv[0]), up(inv[1]);
        graph.addPass((name_ + ".legacy_smoke").c_str(), order(bucketInfo(Bucket::Particles).order),
                      [&](rtt::PassBuilder& b) { b.write(color); },
                      [sc, color, view, proj, eye, right, up](rtt::PassContext& ctx) {
                          ctx.bindForDraw(color);
                          static std::vector<cubeParticleSystem::SpriteVertex> quads;
                          const glm::mat4 vp = proj * view;
                          for (const auto& ps : sc->particleSystems()) {
                              if (ps->kind() != cubeParticleSystem::Kind::Legacy) continue;
                              ps->BuildQuads(eye, right, up, &quads);
                              sc->legacySprites.draw(quads, glm::value_ptr(vp), ps->tint());
                          }
                      });
    }
    // ... and the plugin's passes (nothing was recorded when no particle is visible).
    fxPasses.replay(color, sceneDepth);

    // [HUD] mirror inset and text.
    if (settings.hud || settings.inset.valid()) {
        const rtt::FrameGraphResource inset = settings.inset;
        const bool flip = settings.insetFlipX;
        const std::string text = settings.hudText;
        const bool hud = settings.hud;
        const int w = width_, h = height_;
        graph.addPass((name_ + "." + bucketInfo(Bucket::Hud).name).c_str(), order(bucketInfo(Bucket::Hud).order),
                      [&](rtt::PassBuilder& b) {
                          if (inset.valid()) b.read(inset);
                          b.write(color);
                      },
                      [sc, color, inset, flip, text, hud, w, h](rtt::PassContext& ctx) {
                          ctx.bindForDraw(color);
                          if (inset.valid()) {
                              const int iw = ctx.width(inset), ih = ctx.height(inset);
                              const int x = (w - iw) / 2, y = h - ih - 12;
                              glViewport(x - 3, y - 3, iw + 6, ih + 6);  // frame
                              glEnable(GL_SCISSOR_TEST);
                              glScissor(x - 3, y - 3, iw + 6, ih + 6);
                              const GLfloat frame[4] = {0.05f, 0.05f, 0.05f, 1.0f};
                              glClearBufferfv(GL_COLOR, 0, frame);
                              glDisable(GL_SCISSOR_TEST);
                              glViewport(x, y, iw, ih);
                              const gl::Program& p = sc->blitProgram;
                              glUseProgram(p.id());
                              glActiveTexture(GL_TEXTURE0);
                              glBindTexture(GL_TEXTURE_2D, ctx.texture(inset, 0));
                              glUniform1i(p.uniform("uSource"), 0);
                              glUniform1f(p.uniform("uFlipX"), flip ? 1.0f : 0.0f);
                              glUniform1f(p.uniform("uDepth"), 0.0f);
                              glBindVertexArray(sc->emptyVao);
                              glDrawArrays(GL_TRIANGLES, 0, 3);
                              glBindVertexArray(0);
                              glBindTexture(GL_TEXTURE_2D, 0);
                              glUseProgram(0);
                              glViewport(0, 0, w, h);
                          }
                          if (hud) {
                              sc->hud.setText(text);
                              sc->hud.draw(w, h);
                          }
                      });
    }
    return color;
}

}  // namespace cube
