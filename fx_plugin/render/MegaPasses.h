#pragma once
// The mega-particles' pass bodies (MegaRenderer.h declares them): the depth downsample, the
// spheres, the two blurs (the second shades) and the composite, with the GL objects they draw
// through: the programs, the colour ramps, the instance stream, a framebuffer object of the
// renderer's own (the spheres and blurs write two of the host's textures at once) and the scene
// depth's sampler. Each body runs inside the caller's GlStateGuard.
#include <cstdint>
#include <memory>
#include <utility>

#include "ColorRampTexture.h"
#include "DrawList.h"
#include "GlStateGuard.h"
#include "InstanceStream.h"
#include "LightState.h"
#include "MegaPrograms.h"
#include "RendererConfig.h"
#include "ScreenTiles.h"
#include "fx/HostAdapter.h"

#include "SceneDepthSource.h"

namespace fx {

/// One view's recorded cloud, shared with the pass bodies until the host has run them.
struct MegaCloud {
    ViewInfo view;
    DrawList list;
    MegaDesc mega;
    LightingDesc lighting;
    LightState light;
    float softScale = 2.0f;  ///< 1 / render.softness of the first batch
    float time = 0.0f;       ///< simulation clock of the first batch, s
    ScreenRect rect;         ///< full-resolution pixels the spheres can touch
    SceneDepthDecode depthDecode;  ///< how its scene depth reads (SceneDepthSource.h)
};

class MegaPasses {
public:
    /// Relative depth difference at which a blur tap's weight has fallen to 1/e.
    static constexpr float kDepthFalloff = 0.35f;
    /// Optical depth of a sphere of alpha 1 along its diameter (fs_mega_spheres.glsl): coverage
    /// 1 - exp(-1.25) = 0.71 through the middle of one opaque sphere, more where spheres overlap.
    static constexpr float kDensity = 1.25f;

    explicit MegaPasses(SizeMismatchReport sizeMismatch) : sizeMismatch_(std::move(sizeMismatch)) {}
    MegaPasses(const MegaPasses&) = delete;
    MegaPasses& operator=(const MegaPasses&) = delete;

    /// Takes `programs` (bound to the cache, ok()) and creates the other GL objects. Inside a guard.
    void create(std::unique_ptr<MegaPrograms> programs);
    /// A shader reload's new set (bound to the swapped cache); the old one is returned.
    std::unique_ptr<MegaPrograms> swapPrograms(std::unique_ptr<MegaPrograms> next) {
        programs_.swap(next);
        return next;
    }
    /// Drops the programs (the ProgramCache's, deleted with it), deletes the framebuffer object
    /// and the vertex array (inside a guard); the ramp, stream and sampler delete theirs with
    /// this object.
    void releaseGl();
    ColorRampTexture& ramp() { return ramp_; }

    void runDepth(PassContext& ctx, const MegaCloud& r, Target sceneDepth, Target megaDepth);
    void runSpheres(PassContext& ctx, const MegaCloud& r, Target megaDepth, Target color, Target density);
    void runBlur(PassContext& ctx, const MegaCloud& r, Target inColor, Target inDensity, Target outColor,
                 Target outSecond, bool shade);
    void runComposite(PassContext& ctx, const MegaCloud& r, Target cloud, Target cloudDepth, Target sceneDepth,
                      Target sceneColor);

private:
    /// Binds the framebuffer object with `a` and `b` as colour attachments 0 and 1, sets the
    /// viewport to `a`'s size and clears `a` to `clearA`, `b` to 0 (the whole targets).
    void beginOwnTarget(PassContext& ctx, Target a, Target b, const float clearA[4]);
    void endOwnTarget();
    /// Blur extent of the cloud in spheres-target texels (taps each side, + 2).
    static int blurBorder(const MegaCloud& r);
    /// Draws the full-screen triangle with the bound program.
    void drawFullscreen();

    SizeMismatchReport sizeMismatch_;
    std::unique_ptr<MegaPrograms> programs_;
    ColorRampTexture ramp_;
    InstanceStream stream_;
    uint32_t fbo_ = 0, emptyVao_ = 0;
    NearestSampler hostDepth_;  ///< the host's scene depth, read whatever sampling it set
};

}  // namespace fx
