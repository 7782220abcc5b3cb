#include "QuarterResPath.h"

#include <algorithm>
#include <cmath>

#include "render/PrivateGl.h"

#include "ShaderLoader.h"

namespace fx {
namespace {

void bindTextureUnit(int unit, GLuint texture) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, texture);
    glBindSampler(GLuint(unit), 0);
}

void fullscreenState() {
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

// Scissor to `rect` scaled to a target of w x h (the full-res rect's pixels / `divisor`, grown by
// `border` texels), or no scissor for a whole-view rect.
void scissorTo(const QuarterResPath::ScreenRect& rect, int divisor, int border, int w, int h) {
    if (rect.whole) {
        glDisable(GL_SCISSOR_TEST);
        return;
    }
    const int x0 = std::max(0, rect.x0 / divisor - border), y0 = std::max(0, rect.y0 / divisor - border);
    const int x1 = std::min(w, (rect.x1 + divisor - 1) / divisor + border);
    const int y1 = std::min(h, (rect.y1 + divisor - 1) / divisor + border);
    glEnable(GL_SCISSOR_TEST);
    glScissor(x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0));
}

}  // namespace

QuarterResPath::ScreenRect QuarterResPath::screenRect(const ViewInfo& view, const ParticleInstance* instances,
                                                      int count) {
    ScreenRect r;
    float lo[2] = {1e30f, 1e30f}, hi[2] = {-1e30f, -1e30f};
    bool any = false;
    for (int i = 0; i < count; ++i) {
        const ParticleInstance& p = instances[i];
        const glm::vec3 c = glm::vec3(view.view * glm::vec4(p.x, p.y, p.z, 1.0f));
        const float radius = 0.71f * p.size;
        if (!(c.z + radius < -view.nearPlane)) return r;  // reaches the near plane (or NaN): whole view
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 q = c + radius * glm::vec3(corner & 1 ? 1.0f : -1.0f, corner & 2 ? 1.0f : -1.0f,
                                                       corner & 4 ? 1.0f : -1.0f);
            const glm::vec4 clip = view.proj * glm::vec4(q, 1.0f);
            for (int a = 0; a < 2; ++a) {
                const float ndc = clip[a] / clip.w;
                lo[a] = std::min(lo[a], ndc);
                hi[a] = std::max(hi[a], ndc);
            }
        }
        any = true;
    }
    const int w = view.width, h = view.height;
    if (!any) {
        r.whole = false;  // nothing in front of the camera: an empty rect
        return r;
    }
    // NDC to pixels, one pixel of slack for rasterisation rules, clamped to the view.
    auto px = [](float ndc, int size) { return (ndc * 0.5f + 0.5f) * float(size); };
    r.x0 = std::max(0, int(std::floor(px(lo[0], w))) - 1);
    r.y0 = std::max(0, int(std::floor(px(lo[1], h))) - 1);
    r.x1 = std::min(w, int(std::ceil(px(hi[0], w))) + 1);
    r.y1 = std::min(h, int(std::ceil(px(hi[1], h))) + 1);
    if (r.x1 <= r.x0 || r.y1 <= r.y0) {
        r.x0 = r.x1 = r.y0 = r.y1 = 0;
        r.whole = false;
        return r;
    }
    r.whole = r.x0 == 0 && r.y0 == 0 && r.x1 == w && r.y1 == h;
    return r;
}

TargetDesc QuarterResPath::depthTargetDesc() {
    TargetDesc d;
    d.scale = 0.5f;
    d.format = TargetFormat::R32F;
    d.linearFilter = false;
    return d;
}

TargetDesc QuarterResPath::colorTargetDesc(bool withDepth) {
    TargetDesc d;
    d.depth = withDepth;
    d.scale = 0.5f;
    d.format = TargetFormat::RGBA16F;
    d.linearFilter = true;
    return d;
}

TargetDesc QuarterResPath::edgeTargetDesc() {
    TargetDesc d;
    d.depth = true;
    d.scale = 1.0f;
    d.format = TargetFormat::RGBA16F;
    d.linearFilter = false;
    return d;
}

QuarterResPath::~QuarterResPath() {
    if (edgeMask_) glDeleteProgram(edgeMask_);
    if (halfZ_) glDeleteProgram(halfZ_);
    if (downsample_) glDeleteProgram(downsample_);
    if (composite_) glDeleteProgram(composite_);
    if (emptyVao_) glDeleteVertexArrays(1, &emptyVao_);
}

void QuarterResPath::build(const std::string& shaderDir, std::vector<std::string>* errors) {
    std::string error;
    if (!downsample_) {
        downsample_ = buildProgram(shaderDir, "vs_particles_fullscreen.glsl",
                                   "fs_particles_depth_downsample.glsl", "", &error);
        if (downsample_) {
            downsampleDepthLoc_ = glGetUniformLocation(downsample_, "uSceneDepth");
        } else {
            errors->push_back(error);
        }
    }
    if (!halfZ_) {
        halfZ_ = buildProgram(shaderDir, "vs_particles_fullscreen.glsl", "fs_particles_half_z.glsl", "", &error);
        if (halfZ_) {
            halfZDepthLoc_ = glGetUniformLocation(halfZ_, "uSceneDepth");
            halfZFromLinearLoc_ = glGetUniformLocation(halfZ_, "uDepthFromLinear");
            halfZFarLoc_ = glGetUniformLocation(halfZ_, "uFar");
        } else {
            errors->push_back(error);
        }
    }
    if (!composite_) {
        composite_ = buildProgram(shaderDir, "vs_particles_fullscreen.glsl",
                                  "fs_particles_composite.glsl", "", &error);
        if (composite_) {
            halfColorLoc_ = glGetUniformLocation(composite_, "uHalfColor");
            halfDepthLoc_ = glGetUniformLocation(composite_, "uHalfDepth");
            sceneDepthLoc_ = glGetUniformLocation(composite_, "uSceneDepth");
            bilinearLoc_ = glGetUniformLocation(composite_, "uBilinear");
            thresholdLoc_ = glGetUniformLocation(composite_, "uDepthThreshold");
            mixedLoc_ = glGetUniformLocation(composite_, "uMixed");
            edgeColorLoc_ = glGetUniformLocation(composite_, "uEdgeColor");
        } else {
            errors->push_back(error);
        }
    }
    if (!edgeMask_) {
        edgeMask_ = buildProgram(shaderDir, "vs_particles_fullscreen.glsl", "fs_particles_edge_mask.glsl", "", &error);
        if (edgeMask_) {
            maskHalfDepthLoc_ = glGetUniformLocation(edgeMask_, "uHalfDepth");
            maskSceneDepthLoc_ = glGetUniformLocation(edgeMask_, "uSceneDepth");
            maskThresholdLoc_ = glGetUniformLocation(edgeMask_, "uDepthThreshold");
            maskPassLoc_ = glGetUniformLocation(edgeMask_, "uPassDepth");
            maskFailLoc_ = glGetUniformLocation(edgeMask_, "uFailDepth");
        } else {
            errors->push_back(error);
        }
    }
    if (!emptyVao_) glGenVertexArrays(1, &emptyVao_);  // core profile draws need a VAO
}

void QuarterResPath::downsampleDepth(PassContext& ctx, Target sceneDepth, Target halfDepth, const ScreenRect& rect) {
    ctx.bindForDraw(halfDepth);
    fullscreenState();
    scissorTo(rect, 2, 2, ctx.width(halfDepth), ctx.height(halfDepth));
    glDisable(GL_BLEND);
    glUseProgram(downsample_);
    bindTextureUnit(0, ctx.texture(sceneDepth, 0).name);
    glUniform1i(downsampleDepthLoc_, 0);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

bool QuarterResPath::beginQuarter(PassContext& ctx, Target halfColor, const ScreenRect& rect, Target sceneDepth,
                                  const ViewInfo* zView) {
    ctx.bindForDraw(halfColor);
    scissorTo(rect, 2, 2, ctx.width(halfColor), ctx.height(halfColor));
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const GLfloat transparent[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, transparent);
    GLint depthBits = 0;
    if (zView && halfZ_ && sceneDepth.valid()) {
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
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glUseProgram(halfZ_);
    bindTextureUnit(0, ctx.texture(sceneDepth, 0).name);
    glUniform1i(halfZDepthLoc_, 0);
    // Reversed-Z zero-to-one: window z = clip.z / clip.w = P[3][2] / depth - P[2][2].
    glUniform2f(halfZFromLinearLoc_, zView->proj[3][2], -zView->proj[2][2]);
    glUniform1f(halfZFarLoc_, zView->farPlane);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_GEQUAL);
    return true;
}

void QuarterResPath::beginEdges(PassContext& ctx, Target edgeColor, Target halfDepth, Target sceneDepth,
                                const ScreenRect& rect, const ViewInfo& view) {
    ctx.bindForDraw(edgeColor);
    fullscreenState();
    scissorTo(rect, 1, 0, ctx.width(edgeColor), ctx.height(edgeColor));
    const GLfloat transparent[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, transparent);
    // The mask as depth: a fragment at window z in [0, 1] passes LEQUAL 1 (GEQUAL 0) and fails
    // LEQUAL 0 (GEQUAL 1) unless it lies exactly on the near plane, where the particles' near
    // fade has taken them to nothing anyway.
    const bool reversed = view.depth == DepthConvention::ReversedZ;
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glUseProgram(edgeMask_);
    bindTextureUnit(0, ctx.texture(halfDepth, 0).name);
    bindTextureUnit(1, ctx.texture(sceneDepth, 0).name);
    glUniform1i(maskHalfDepthLoc_, 0);
    glUniform1i(maskSceneDepthLoc_, 1);
    glUniform1f(maskThresholdLoc_, kDepthThreshold);
    glUniform1f(maskPassLoc_, reversed ? 0.0f : 1.0f);
    glUniform1f(maskFailLoc_, reversed ? 1.0f : 0.0f);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_FALSE);
    glDepthFunc(reversed ? GL_GEQUAL : GL_LEQUAL);
}

void QuarterResPath::composite(PassContext& ctx, Target sceneColor, Target halfColor,
                               Target halfDepth, Target sceneDepth, bool bilinear, const ScreenRect& rect,
                               Target edgeColor) {
    ctx.bindForDraw(sceneColor);
    fullscreenState();
    scissorTo(rect, 1, 0, ctx.width(sceneColor), ctx.height(sceneColor));
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(composite_);
    bindTextureUnit(0, ctx.texture(halfColor, 0).name);
    bindTextureUnit(1, ctx.texture(halfDepth, 0).name);
    bindTextureUnit(2, ctx.texture(sceneDepth, 0).name);
    glUniform1i(halfColorLoc_, 0);
    glUniform1i(halfDepthLoc_, 1);
    glUniform1i(sceneDepthLoc_, 2);
    glUniform1i(bilinearLoc_, bilinear ? 1 : 0);
    glUniform1f(thresholdLoc_, kDepthThreshold);
    glUniform1i(mixedLoc_, edgeColor.valid() ? 1 : 0);
    glUniform1i(edgeColorLoc_, 3);
    // Unit 3 is bound either way: a sampler uniform must never read a unit with a texture of
    // another kind, and the guard restores units 0-3.
    bindTextureUnit(3, edgeColor.valid() ? ctx.texture(edgeColor, 0).name : 0);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace fx
