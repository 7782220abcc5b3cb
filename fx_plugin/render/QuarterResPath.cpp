#include "QuarterResPath.h"

#include <algorithm>
#include <cmath>

#include "render/PrivateGl.h"

#include "GlStateGuard.h"
#include "ShaderLoader.h"

namespace fx {
namespace {

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

// NDC to pixels.
float toPixel(float ndc, int size) { return (ndc * 0.5f + 0.5f) * float(size); }

// Appends the pixel rectangle [x0, x1) x [y0, y1) as two triangles.
void addRun(QuarterResPath::ScreenTiles* tiles, int x0, int y0, int x1, int y1) {
    const float a = float(x0), b = float(x1), c = float(y0), d = float(y1);
    const float v[12] = {a, c, b, c, b, d, a, c, b, d, a, d};
    tiles->vertices.insert(tiles->vertices.end(), v, v + 12);
    tiles->pixels += int64_t(x1 - x0) * (y1 - y0);
}

}  // namespace

QuarterResPath::ScreenRect QuarterResPath::screenRect(const ViewInfo& view, const ParticleInstance* instances,
                                                      int count, ScreenTiles* tiles, Footprint footprint) {
    ScreenRect r;
    const int w = view.width, h = view.height;
    const int tilesX = (w + kTileSize - 1) / kTileSize, tilesY = (h + kTileSize - 1) / kTileSize;
    if (tiles) {
        tiles->vertices.clear();
        tiles->pixels = 0;
        tiles->viewWidth = w;
        tiles->viewHeight = h;
        tiles->grid.assign(size_t(std::max(0, tilesX * tilesY)), 0);
    }
    auto wholeView = [&]() {
        if (tiles && w > 0 && h > 0) {
            tiles->vertices.clear();
            tiles->pixels = 0;
            addRun(tiles, 0, 0, w, h);
        }
        return r;  // whole = true
    };
    float lo[2] = {1e30f, 1e30f}, hi[2] = {-1e30f, -1e30f};
    bool any = false;
    for (int i = 0; i < count; ++i) {
        const ParticleInstance& p = instances[i];
        const glm::vec3 c = glm::vec3(view.view * glm::vec4(p.x, p.y, p.z, 1.0f));
        const float radius = 0.71f * p.size;
        // A billboard lies in the view plane through its centre: its square, no depth extent.
        const float depthExtent = footprint == Footprint::Billboard ? 0.0f : radius;
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z) || !std::isfinite(radius)) {
            return wholeView();  // no bound to trust
        }
        if (c.z - depthExtent >= -view.nearPlane) continue;      // wholly behind the near plane: clipped
        if (c.z + depthExtent >= -view.nearPlane) return wholeView();  // reaches the near plane
        float plo[2] = {1e30f, 1e30f}, phi[2] = {-1e30f, -1e30f};
        const int corners = depthExtent > 0.0f ? 8 : 4;  // a flat square has 4
        for (int corner = 0; corner < corners; ++corner) {
            const glm::vec3 q = c + glm::vec3(corner & 1 ? radius : -radius, corner & 2 ? radius : -radius,
                                              corner & 4 ? depthExtent : -depthExtent);
            const glm::vec4 clip = view.proj * glm::vec4(q, 1.0f);
            for (int a = 0; a < 2; ++a) {
                const float ndc = clip[a] / clip.w;
                plo[a] = std::min(plo[a], ndc);
                phi[a] = std::max(phi[a], ndc);
            }
        }
        for (int a = 0; a < 2; ++a) {
            lo[a] = std::min(lo[a], plo[a]);
            hi[a] = std::max(hi[a], phi[a]);
        }
        any = true;
        if (tiles && tilesX > 0 && tilesY > 0) {
            // The particle's pixels grown by the border, as a tile range clamped to the view (the
            // float clamp first: a bound far off screen must not overflow the int).
            auto tileOf = [](float pixel, int border, int tileCount) {
                const float t = std::floor((pixel + float(border)) / float(kTileSize));
                return int(std::min(std::max(t, 0.0f), float(tileCount - 1)));
            };
            const float px0 = toPixel(plo[0], w), px1 = toPixel(phi[0], w);
            const float py0 = toPixel(plo[1], h), py1 = toPixel(phi[1], h);
            if (px1 < -kTileBorder || py1 < -kTileBorder || px0 > w + kTileBorder || py0 > h + kTileBorder) continue;
            const int tx0 = tileOf(px0, -kTileBorder, tilesX), tx1 = tileOf(px1, kTileBorder, tilesX);
            const int ty0 = tileOf(py0, -kTileBorder, tilesY), ty1 = tileOf(py1, kTileBorder, tilesY);
            for (int ty = ty0; ty <= ty1; ++ty) {
                std::fill(tiles->grid.begin() + ty * tilesX + tx0, tiles->grid.begin() + ty * tilesX + tx1 + 1,
                          uint8_t(1));
            }
        }
    }
    if (!any) {
        r.whole = false;  // nothing in front of the camera: an empty rect, no tiles
        return r;
    }
    // NDC to pixels, one pixel of slack for rasterisation rules, clamped to the view.
    r.x0 = std::max(0, int(std::floor(toPixel(lo[0], w))) - 1);
    r.y0 = std::max(0, int(std::floor(toPixel(lo[1], h))) - 1);
    r.x1 = std::min(w, int(std::ceil(toPixel(hi[0], w))) + 1);
    r.y1 = std::min(h, int(std::ceil(toPixel(hi[1], h))) + 1);
    if (r.x1 <= r.x0 || r.y1 <= r.y0) {
        r.x0 = r.x1 = r.y0 = r.y1 = 0;
        r.whole = false;
        return r;  // no tiles either: every bound was off screen
    }
    r.whole = r.x0 == 0 && r.y0 == 0 && r.x1 == w && r.y1 == h;
    if (tiles) {
        // Horizontal runs of marked tiles, clamped to the view.
        for (int ty = 0; ty < tilesY; ++ty) {
            const uint8_t* row = tiles->grid.data() + ty * tilesX;
            for (int tx = 0; tx < tilesX;) {
                if (!row[tx]) {
                    ++tx;
                    continue;
                }
                int end = tx;
                while (end < tilesX && row[end]) ++end;
                addRun(tiles, tx * kTileSize, ty * kTileSize, std::min(w, end * kTileSize),
                       std::min(h, (ty + 1) * kTileSize));
                tx = end;
            }
        }
    }
    return r;
}

TargetDesc QuarterResPath::depthTargetDesc() {
    TargetDesc d;
    d.scale = 0.5f;
    d.format = TargetFormat::RG32F;
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
    for (const CompositeProgram& c : composite_) {
        if (c.program) glDeleteProgram(c.program);
    }
    if (tileVao_) glDeleteVertexArrays(1, &tileVao_);
    if (tileVbo_) glDeleteBuffers(1, &tileVbo_);
}

void QuarterResPath::build(const std::string& shaderDir, std::vector<std::string>* errors) {
    std::string error;
    hostDepth_.create();
    if (!downsample_) {
        downsample_ = buildProgram(shaderDir, "vs_particles_tiles.glsl",
                                   "fs_particles_depth_downsample.glsl", "", &error);
        if (downsample_) {
            downsampleDepthLoc_ = glGetUniformLocation(downsample_, "uSceneDepth");
            downsampleViewLoc_ = glGetUniformLocation(downsample_, "uViewSize");
        } else {
            errors->push_back(error);
        }
    }
    if (!halfZ_) {
        halfZ_ = buildProgram(shaderDir, "vs_particles_tiles.glsl", "fs_particles_half_z.glsl", "", &error);
        if (halfZ_) {
            halfZDepthLoc_ = glGetUniformLocation(halfZ_, "uHalfDepth");
            halfZFromLinearLoc_ = glGetUniformLocation(halfZ_, "uDepthFromLinear");
            halfZFarLoc_ = glGetUniformLocation(halfZ_, "uFar");
            halfZViewLoc_ = glGetUniformLocation(halfZ_, "uViewSize");
        } else {
            errors->push_back(error);
        }
    }
    static const char* const kCompositeDefines[CompositeVariantCount] = {
        "", "#define FX_COMPOSITE_BILINEAR 1\n", "#define FX_COMPOSITE_MIXED 1\n"};
    for (int v = 0; v < CompositeVariantCount; ++v) {
        CompositeProgram& c = composite_[v];
        if (c.program) continue;
        c.program = buildProgram(shaderDir, "vs_particles_tiles.glsl", "fs_particles_composite.glsl",
                                 kCompositeDefines[v], &error);
        if (!c.program) {
            errors->push_back(error);
            continue;
        }
        c.halfColor = glGetUniformLocation(c.program, "uHalfColor");
        c.halfDepth = glGetUniformLocation(c.program, "uHalfDepth");
        c.sceneDepth = glGetUniformLocation(c.program, "uSceneDepth");
        c.threshold = glGetUniformLocation(c.program, "uDepthThreshold");
        c.edgeColor = glGetUniformLocation(c.program, "uEdgeColor");
        c.viewSize = glGetUniformLocation(c.program, "uViewSize");
    }
    if (!edgeMask_) {
        edgeMask_ = buildProgram(shaderDir, "vs_particles_tiles.glsl", "fs_particles_edge_mask.glsl", "", &error);
        if (edgeMask_) {
            maskHalfDepthLoc_ = glGetUniformLocation(edgeMask_, "uHalfDepth");
            maskSceneDepthLoc_ = glGetUniformLocation(edgeMask_, "uSceneDepth");
            maskThresholdLoc_ = glGetUniformLocation(edgeMask_, "uDepthThreshold");
            maskPassLoc_ = glGetUniformLocation(edgeMask_, "uPassDepth");
            maskFailLoc_ = glGetUniformLocation(edgeMask_, "uFailDepth");
            maskViewLoc_ = glGetUniformLocation(edgeMask_, "uViewSize");
        } else {
            errors->push_back(error);
        }
    }
    if (!tileVao_) {
        glGenVertexArrays(1, &tileVao_);
        glGenBuffers(1, &tileVbo_);
        glBindVertexArray(tileVao_);
        glBindBuffer(GL_ARRAY_BUFFER, tileVbo_);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    }
}

void QuarterResPath::drawTiles(int viewSizeLoc, const ScreenTiles& tiles) {
    if (tiles.vertices.empty()) return;
    glUniform2f(viewSizeLoc, float(tiles.viewWidth), float(tiles.viewHeight));
    glBindVertexArray(tileVao_);
    glBindBuffer(GL_ARRAY_BUFFER, tileVbo_);
    // Orphaned every draw: a pass of another view may have drawn its own runs in between.
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(tiles.vertices.size() * sizeof(float)), tiles.vertices.data(),
                 GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(tiles.vertices.size() / 2));
}

void QuarterResPath::downsampleDepth(PassContext& ctx, Target sceneDepth, Target halfDepth, const ScreenRect& rect,
                                     const ScreenTiles& tiles) {
    ctx.bindForDraw(halfDepth);
    fullscreenState();
    scissorTo(rect, 2, 2, ctx.width(halfDepth), ctx.height(halfDepth));
    glDisable(GL_BLEND);
    glUseProgram(downsample_);
    hostDepth_.bindTexture(0, ctx.texture(sceneDepth, 0).name);
    glUniform1i(downsampleDepthLoc_, 0);
    drawTiles(downsampleViewLoc_, tiles);
}

bool QuarterResPath::beginQuarter(PassContext& ctx, Target halfColor, const ScreenRect& rect,
                                  const ScreenTiles& tiles, Target halfDepth, const ViewInfo* zView) {
    ctx.bindForDraw(halfColor);
    scissorTo(rect, 2, 2, ctx.width(halfColor), ctx.height(halfColor));
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const GLfloat transparent[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, transparent);
    GLint depthBits = 0;
    if (zView && halfZ_ && halfDepth.valid()) {
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
    bindTextureUnit(0, ctx.texture(halfDepth, 0).name);
    glUniform1i(halfZDepthLoc_, 0);
    // Reversed-Z zero-to-one: window z = clip.z / clip.w = P[3][2] / depth - P[2][2].
    glUniform2f(halfZFromLinearLoc_, zView->proj[3][2], -zView->proj[2][2]);
    glUniform1f(halfZFarLoc_, zView->farPlane);
    drawTiles(halfZViewLoc_, tiles);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_GEQUAL);
    return true;
}

void QuarterResPath::beginEdges(PassContext& ctx, Target edgeColor, Target halfDepth, Target sceneDepth,
                                const ScreenRect& rect, const ScreenTiles& tiles, const ViewInfo& view) {
    ctx.bindForDraw(edgeColor);
    fullscreenState();
    scissorTo(rect, 1, 0, ctx.width(edgeColor), ctx.height(edgeColor));
    const GLfloat transparent[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, transparent);
    // The mask as depth: a fragment at window z in [0, 1] passes LEQUAL 1 (GEQUAL 0) and fails
    // LEQUAL 0 (GEQUAL 1) unless it lies exactly on the near plane, where the particles' near
    // fade has taken them to nothing anyway.
    const bool reversed = view.depth == DepthConvention::ReversedZ;
    // Outside the tiles no particle fragment lands, but a pooled target's z-buffer holds an old
    // frame's mask there: fail everything first, the tiles then get this frame's mask.
    glDepthMask(GL_TRUE);
    const GLfloat fail = reversed ? 1.0f : 0.0f;
    glClearBufferfv(GL_DEPTH, 0, &fail);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glUseProgram(edgeMask_);
    bindTextureUnit(0, ctx.texture(halfDepth, 0).name);
    hostDepth_.bindTexture(1, ctx.texture(sceneDepth, 0).name);
    glUniform1i(maskHalfDepthLoc_, 0);
    glUniform1i(maskSceneDepthLoc_, 1);
    glUniform1f(maskThresholdLoc_, kDepthThreshold);
    glUniform1f(maskPassLoc_, reversed ? 0.0f : 1.0f);
    glUniform1f(maskFailLoc_, reversed ? 1.0f : 0.0f);
    drawTiles(maskViewLoc_, tiles);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_FALSE);
    glDepthFunc(reversed ? GL_GEQUAL : GL_LEQUAL);
}

void QuarterResPath::composite(PassContext& ctx, Target sceneColor, Target halfColor,
                               Target halfDepth, Target sceneDepth, bool bilinear, const ScreenRect& rect,
                               const ScreenTiles& tiles, Target edgeColor) {
    ctx.bindForDraw(sceneColor);
    fullscreenState();
    scissorTo(rect, 1, 0, ctx.width(sceneColor), ctx.height(sceneColor));
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    const CompositeProgram& c = composite_[edgeColor.valid() ? Mixed : bilinear ? Bilinear : DepthAware];
    glUseProgram(c.program);
    bindTextureUnit(0, ctx.texture(halfColor, 0).name);
    bindTextureUnit(1, ctx.texture(halfDepth, 0).name);
    hostDepth_.bindTexture(2, ctx.texture(sceneDepth, 0).name);
    // A location a build left out (-1) is ignored by glUniform*.
    glUniform1i(c.halfColor, 0);
    glUniform1i(c.halfDepth, 1);
    glUniform1i(c.sceneDepth, 2);
    glUniform1f(c.threshold, kDepthThreshold);
    glUniform1i(c.edgeColor, 3);
    // Unit 3 is bound either way: a sampler uniform must never read a unit with a texture of
    // another kind, and the guard restores units 0-3.
    bindTextureUnit(3, edgeColor.valid() ? ctx.texture(edgeColor, 0).name : 0);
    drawTiles(c.viewSize, tiles);
}

}  // namespace fx
