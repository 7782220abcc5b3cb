#pragma once
// The host's own z-buffer as the plugin's linear scene depth. A host that has no
// linear R32F depth gives either a depth texture (GL_DEPTH_COMPONENT16/24/32F or
// GL_DEPTH24_STENCIL8, GL_TEXTURE_2D, drawn with the view's projection) or nothing but the
// framebuffer bound for drawing; DepthLinearizer copies the latter's depth attachment into a depth
// texture of its own (glCopyTexSubImage2D from the read framebuffer: works on the default
// framebuffer and on an FBO; a multisampled one is resolved with a depth blit), then one
// full-screen pass (ProgramCache::LinearizeDepth, the cache's program) writes the linear
// depth (metres, >= 0; "nothing drawn" = the view's far plane) into an R32F target the caller
// provides. The maths and its precision: DepthMapping.h.
//
// GL: every call runs inside the caller's GlStateGuard (it binds textures on unit 0, a sampler,
// the read/draw framebuffers, a program and a vertex array, and changes the viewport).
#include <cstdint>

#include <glm/glm.hpp>

#include "DepthMapping.h"
#include "ProgramCache.h"

namespace fx {

/// Depth internal formats DepthLinearizer reads (0 for anything else).
uint32_t supportedDepthFormat(uint32_t internalFormat);

class DepthLinearizer {
public:
    DepthLinearizer() = default;
    ~DepthLinearizer();  ///< frees its GL objects: the context must be current if any exist
    DepthLinearizer(const DepthLinearizer&) = delete;
    DepthLinearizer& operator=(const DepthLinearizer&) = delete;

    /// Takes the linearise program of `programs` and looks its uniforms up where it is not the
    /// one taken before (a reload swapped the cache; releaseGl); creates the vertex array and the
    /// sampler once. Compiles nothing; the program stays the cache's. False where `programs` has
    /// none (not built, or failed).
    bool bind(const ProgramCache& programs);
    /// The internal format of the depth attachment of `framebuffer` (0 = the default one), with
    /// its stencil where it has one: GL_DEPTH_COMPONENT16/24/32F, GL_DEPTH24_STENCIL8,
    /// GL_DEPTH32F_STENCIL8; 0 when it has no depth.
    static uint32_t framebufferDepthFormat(uint32_t framebuffer);
    /// GL_SAMPLES of `framebuffer` (0: single-sampled).
    static int framebufferSamples(uint32_t framebuffer);
    /// The internal format of level 0 of GL_TEXTURE_2D `texture` (binds it on the active unit).
    static uint32_t textureFormat(uint32_t texture);
    /// The size of level 0 of GL_TEXTURE_2D `texture` (binds it on the active unit, as textureFormat).
    static void textureSize(uint32_t texture, int* width, int* height);

    /// Copies the depth of `framebuffer`'s rect (x, y, width, height) into the plugin's own depth
    /// texture (format `format`, from framebufferDepthFormat; reallocated when the size or the
    /// format changes) and returns it. Single-sampled: glCopyTexSubImage2D (any framebuffer, the
    /// default one included); multisampled (`samples` > 0): a depth blit, which resolves it.
    /// With a `region` only its pixels are copied (the rest of the texture keeps old values).
    uint32_t copyFramebufferDepth(uint32_t framebuffer, int x, int y, int width, int height, uint32_t format,
                                  int samples = 0, const DepthRegion& region = DepthRegion{});

    /// Draws the linear depth of `depthTexture` (window depth, read without comparison, nearest)
    /// into `targetFramebuffer` (an R32F colour attachment of width x height). `background` goes
    /// where nothing was drawn. Needs prepare(). With a `region` only its pixels are linearised;
    /// the rest of the target is cleared to `background` (nothing drawn). `depthTexture` holds the
    /// view's pixel (0, 0) at `texelOrigin` and is `textureSize` (0 = width x height): a host
    /// texture of the whole framebuffer holds the view at the viewport's origin.
    void linearize(uint32_t depthTexture, const glm::mat4& proj, const DepthMapping& mapping, float background,
                   uint32_t targetFramebuffer, int width, int height, const DepthRegion& region = DepthRegion{},
                   glm::ivec2 texelOrigin = glm::ivec2(0), glm::ivec2 textureSize = glm::ivec2(0));

    /// Depth copies made so far (a frame whose passes read no depth makes none).
    int copies() const { return copies_; }
    int linearizations() const { return linearizations_; }
    void releaseGl();

private:
    uint32_t program_ = 0, vao_ = 0, sampler_ = 0, copy_ = 0, resolveFbo_ = 0;
    int copyWidth_ = 0, copyHeight_ = 0;
    uint32_t copyFormat_ = 0;
    int locDepth_ = -1, locCoeffs_ = -1, locFarWindow_ = -1, locReversed_ = -1, locBackground_ = -1, locInvSize_ = -1;
    int locTexelOrigin_ = -1;
    int copies_ = 0, linearizations_ = 0;
};

}  // namespace fx
