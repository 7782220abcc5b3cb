#pragma once
// The fade pyramid: the scene's nearest linear depth over square blocks of a view, 4 x 4 pixels
// at level 0 and twice as wide each level up, down to a level of at most 4 x 4 blocks
// (fs_particles_fade_pyramid.glsl). Built in the particle pass before the soft billboards and
// spheres draw (FadeClassification::On, full resolution): each particle's vertices read the
// blocks of the lowest level that covers it in 16 x 16 of them and set one bit per block where
// the scene may come within its softness, or (a sphere) nearer than its deepest point
// (vs_particles.glsl, FX_FADE_MASK). A fragment in a block without its bit has a fade of exactly
// 1, or a chord the scene does not clip, and skips the scene-depth fetch
// (fs_particles_soft.glsl, fs_particles_spherical.glsl).
//
// Contract:
//  - every level is a lower bound of the decoded scene depth (linearSceneDepth) of every view
//    pixel its texels cover, so a block without its bit never holds a fragment whose fade is
//    under 1: the picture is the one drawn without classification;
//  - build() draws into the plugin's own texture through its own framebuffer; it leaves the draw
//    framebuffer, the vertex array and the viewport as it found them (the particle draw follows
//    in the same pass, its instance stream's attributes set on the bound vertex array) and every
//    other state it sets is the pass guard's to restore;
//  - one texture per renderer, reallocated when a view's size needs other levels.
#include <cstdint>

#include <glm/glm.hpp>

#include "GlStateGuard.h"
#include "SceneDepthSource.h"

namespace fx {

class ProgramCache;

class FadePyramid {
public:
    FadePyramid() = default;
    ~FadePyramid() { releaseGl(); }  ///< the context must be current if anything was allocated
    FadePyramid(const FadePyramid&) = delete;
    FadePyramid& operator=(const FadePyramid&) = delete;

    /// Takes the pyramid's two programs from `programs` (0 where one failed) and looks their
    /// uniforms up; again after a shader reload swapped the cache.
    void bind(const ProgramCache& programs);
    /// Both programs built.
    bool ok() const { return first_ != 0 && reduce_ != 0; }
    /// Builds every level for a view of `viewSize` from `sceneDepth` (bound through `sampler` on
    /// `depthUnit`) as `decode` reads it (placed for the particle pass), and leaves the pyramid
    /// bound on `pyramidUnit` (no sampler object: its own mipmapped filter). False where it cannot
    /// (no programs, an empty view): draw without classification then.
    bool build(uint32_t sceneDepth, const SceneDepthDecode& decode, glm::ivec2 viewSize, const NearestSampler& sampler,
               int depthUnit, int pyramidUnit);
    /// The pyramid's texture (0 before the first build) and its last level.
    uint32_t texture() const { return texture_; }
    int topLevel() const { return levels_ - 1; }
    /// Deletes the GL objects (context current).
    void releaseGl();

    /// Level 0's size for a view of `viewSize`, and the number of levels down to one of at most
    /// 4 x 4 texels.
    static glm::ivec2 baseSize(glm::ivec2 viewSize) { return (viewSize + 3) / 4; }
    static int levelCount(glm::ivec2 viewSize);

private:
    uint32_t first_ = 0, reduce_ = 0;
    int firstDepthLoc_ = -1, firstInvSizeLoc_ = -1, reduceBelowLoc_ = -1;
    SceneDepthUniforms firstDecode_;
    uint32_t texture_ = 0, fbo_ = 0, vao_ = 0;
    glm::ivec2 size_{0};  ///< level 0's size
    int levels_ = 0;
};

}  // namespace fx
