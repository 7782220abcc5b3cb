#include "QuarterResPath.h"

#include <utility>

#include "base/EnvSwitch.h"
#include "render/PrivateGl.h"

#include "GlStateGuard.h"
#include "PassDeclaration.h"

namespace fx {
namespace {

// Into the bound target's z-buffer only: no colour, every fragment writes its depth.
void beginDepthOnly() {
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
}

// Colour back on; the depth test stays on with `func`, without writes.
void endDepthOnly(GLenum func) {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_FALSE);
    glDepthFunc(func);
}

// CUBEFX_QUARTER_CHOICE_IN_PASS (EnvSwitch.h): 0 chooses every view while it is declared, 1 (or
// unset) leaves the choice to the passes where it can.
EnvSwitch gChoiceInPass("CUBEFX_QUARTER_CHOICE_IN_PASS",
                        "fx: CUBEFX_QUARTER_CHOICE_IN_PASS is neither 0 nor 1; quarter res keeps its default (a frame "
                        "graph's view chooses in its first pass)");

TargetDesc targetDesc(float scale, TargetFormat format, bool linearFilter, bool depth) {
    TargetDesc d;
    d.depth = depth;
    d.scale = scale;
    d.format = format;
    d.linearFilter = linearFilter;
    return d;
}

}  // namespace

TargetDesc QuarterResPath::depthTargetDesc() { return targetDesc(0.5f, TargetFormat::RG32F, false, false); }

TargetDesc QuarterResPath::colorTargetDesc(bool withDepth, bool spheres) {
    return targetDesc(0.5f, spheres ? TargetFormat::RGBA16F : TargetFormat::RGBA8, true, withDepth);
}

QuarterResPath::QuarterResPath(ParticleDraw& draw, SizeMismatchReport sizeMismatch)
    : draw_(draw), sizeMismatch_(std::move(sizeMismatch)) {}

void QuarterResPath::declare(FrameBuilder& frame, const std::shared_ptr<ParticleView>& record) {
    const ViewInfo& view = record->view;
    const Target color = frame.sceneColor();
    const Target opacity = record->opacity;
    // The z-buffer, sampled in place, where the host offers it; else its linear depth.
    const SceneDepthSource source = sceneDepthSource(frame, view);
    const Target depth = source.target;
    const SceneDepthDecode decode = source.decode;
    const Target halfDepth = frame.createTarget(kDepthTarget, depthTargetDesc());
    // Under reversed-Z the half-res particles are z-tested too (beginQuarter).
    const bool halfZ = record->reversedZ && programs_->halfZOk();
    const bool spheres = footprintOf(record->list) == Footprint::Box;  // a spherical batch is drawn
    const Target halfColor = frame.createTarget(kColorTarget, colorTargetDesc(halfZ, spheres));
    narrowDepthRead(frame, record->rect, view.width, view.height);
    frame.addPass(kDownsamplePass, {depth}, {halfDepth}, [this, record, depth, decode, halfDepth](PassContext& ctx) {
        if (!settle(*record)) return;
        // Only what this pass declared may be touched: the scene depth.
        if (!targetsFitView(ctx, record->view, depth, Target{}, sizeMismatch_)) return;
        GlStateGuard guard;
        DebugGroup group(kDownsamplePass);
        downsampleDepth(ctx, *record, depth, decode, halfDepth);
    });
    addPassReading(frame, kQuarterPass, {halfDepth, opacity}, halfColor,
                   [this, record, halfDepth, halfColor, halfZ, opacity](PassContext& ctx) {
                       if (!settle(*record)) return;
                       GlStateGuard guard(record->view.depth);  // z-tested against the half z written here
                       DebugGroup group(kQuarterPass);
                       DrawInputs in;
                       in.zTested = beginQuarter(ctx, *record, halfColor, halfZ ? halfDepth : Target{});
                       in.quarterRes = true;
                       in.sceneDepth = ctx.texture(halfDepth, 0).name;
                       in.opacity = opacity.valid() ? ctx.texture(opacity, 0).name : 0;
                       draw_.draw(*record, in);
                   });
    narrowDepthRead(frame, record->rect, view.width, view.height);
    addPassReading(frame, kCompositePass, {halfColor, halfDepth, depth}, color,
                   [this, record, color, halfColor, halfDepth, depth, decode](PassContext& ctx) {
                       if (!settle(*record)) return;
                       GlStateGuard guard;
                       DebugGroup group(kCompositePass);
                       composite(ctx, *record, color, halfColor, halfDepth, depth, decode);
                   });
}

bool QuarterResPath::choiceInPass() { return gChoiceInPass.on(); }
void QuarterResPath::setChoiceInPass(bool on) { gChoiceInPass.set(on); }
void QuarterResPath::resetChoiceInPass() { gChoiceInPass.reset(); }
const char* QuarterResPath::choiceInPassProblem() { return gChoiceInPass.problem(); }

bool QuarterResPath::settle(ParticleView& v) {
    if (v.quarter == ParticleView::Quarter::Pending) {
        glFlush();
        bound(v);
        v.quarter = quarterResPays(v.rect, v.tiles) ? ParticleView::Quarter::Yes : ParticleView::Quarter::No;
    }
    return v.quarter == ParticleView::Quarter::Yes;
}

void QuarterResPath::bound(ParticleView& v) const {
    const BillboardReach reach = draw_.billboardReach(v, true);
    v.rect = screenRect(v.view, v.list.instances.data(), v.list.particleCount(), &v.tiles, footprintOf(v.list),
                        draw_.jobs(), &reach);
}

void QuarterResPath::downsampleDepth(PassContext& ctx, const ParticleView& v, Target sceneDepth,
                                     const SceneDepthDecode& decode, Target halfDepth) {
    QuarterResPrograms& p = *programs_;
    ctx.bindForDraw(halfDepth);
    plainDrawState();
    scissorTo(v.rect, 0.5f, 2, ctx.width(halfDepth), ctx.height(halfDepth));
    glUseProgram(p.downsample);
    const TextureRef depthRef = ctx.texture(sceneDepth, 0);
    p.hostDepth.bindTexture(0, depthRef.name);
    glUniform1i(p.downsampleDepthLoc, 0);
    const SceneDepthDecode placed = decode.placedFor(depthRef, v.view, false);
    setSceneDepthDecode(p.downsampleDecode, placed);
    sceneDepthBarrier(decode);
    // The block's corner as a line in gl_FragCoord (fs_particles_depth_downsample.glsl).
    const glm::vec2 inv = 1.0f / glm::vec2(float(depthRef.width), float(depthRef.height));
    glUniform4f(p.downsampleCornerLoc, 2.0f * inv.x, 2.0f * inv.y, float(placed.texel.x) * inv.x,
                float(placed.texel.y) * inv.y);
    p.drawTiles(p.downsampleViewLoc, v.tiles);
}

bool QuarterResPath::beginQuarter(PassContext& ctx, const ParticleView& v, Target halfColor, Target halfDepth) {
    QuarterResPrograms& p = *programs_;
    ctx.bindForDraw(halfColor);
    scissorTo(v.rect, 0.5f, 2, ctx.width(halfColor), ctx.height(halfColor));
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const GLfloat transparent[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, transparent);
    GLint depthBits = 0;
    if (p.halfZ && halfDepth.valid()) {
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                              GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depthBits);
    }
    if (depthBits == 0) {
        glDisable(GL_DEPTH_TEST);
        return false;
    }
    // The farthest depth of each block into the half-res z-buffer, no colour.
    const GLfloat far = 0.0f;  // reversed-Z: 0 is the far plane
    glClearBufferfv(GL_DEPTH, 0, &far);
    beginDepthOnly();
    glUseProgram(p.halfZ);
    bindTextureUnit(0, ctx.texture(halfDepth, 0).name);
    glUniform1i(p.halfZDepthLoc, 0);
    // Reversed-Z zero-to-one: window z = clip.z / clip.w = P[3][2] / depth - P[2][2].
    glUniform2f(p.halfZFromLinearLoc, v.view.proj[3][2], -v.view.proj[2][2]);
    glUniform1f(p.halfZFarLoc, v.view.farPlane);
    p.drawTiles(p.halfZViewLoc, v.tiles);
    endDepthOnly(GL_GEQUAL);
    return true;
}

void QuarterResPath::composite(PassContext& ctx, const ParticleView& v, Target sceneColor, Target halfColor,
                               Target halfDepth, Target sceneDepth, const SceneDepthDecode& decode) {
    QuarterResPrograms& p = *programs_;
    ctx.bindForDraw(sceneColor);
    const HostClip clip = HostClip::current();
    plainDrawState();
    scissorToView(v.rect, 0, v.view, clip);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    const bool bilinear = v.settings.options.bilinearUpsample;
    const QuarterResPrograms::CompositeProgram& c =
        p.composite[bilinear ? QuarterResPrograms::Bilinear : QuarterResPrograms::DepthAware];
    glUseProgram(c.program);
    // Through the plugin's own samplers: the composite's weights come from the colour's bilinear
    // filter, and its taps are clamped by clamping to the edge, whatever the target's parameters.
    p.halfColorSampler.bindTexture(0, ctx.texture(halfColor, 0).name);
    p.hostDepth.bindTexture(1, ctx.texture(halfDepth, 0).name);
    const TextureRef depthRef = ctx.texture(sceneDepth, 0);
    p.hostDepth.bindTexture(2, depthRef.name);
    // A location a build left out (-1) is ignored by glUniform*.
    glUniform1i(c.halfColor, 0);
    glUniform1i(c.halfDepth, 1);
    glUniform1i(c.sceneDepth, 2);
    const SceneDepthDecode placed = decode.placedFor(depthRef, v.view, true);  // drawn into sceneColor
    setSceneDepthDecode(c.decode, placed);
    sceneDepthBarrier(decode);
    glUniform1f(c.threshold, kDepthThreshold);
    // The footprint's line in gl_FragCoord (fs_particles_composite.glsl): worked out here once,
    // not per fragment.
    const TextureRef halfRef = ctx.texture(halfColor, 0);
    const glm::vec2 invLow = 1.0f / glm::vec2(float(halfRef.width), float(halfRef.height));
    const glm::vec2 scale = glm::vec2(float(halfRef.width), float(halfRef.height)) /
                            glm::vec2(float(v.view.width), float(v.view.height));
    const glm::vec2 origin = -glm::vec2(placed.drawOrigin) * scale;
    glUniform4f(c.lowMap, scale.x, scale.y, origin.x - 0.5f, origin.y - 0.5f);
    glUniform2f(c.invLow, invLow.x, invLow.y);
    p.drawTiles(c.viewSize, v.tiles);
}

}  // namespace fx
