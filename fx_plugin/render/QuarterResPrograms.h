#pragma once
// The GL programs of the quarter-res passes (QuarterResPath.h) and their uniform locations: the
// depth downsample, the half-res z-fill and the composite's two builds, all drawn over the screen
// tiles' runs (ScreenTiles.h) from one stream buffer.
// The programs are the ProgramCache's (its pass keys): this set compiles nothing and deletes no
// program; bind() takes them from the running cache, again after a shader reload swapped it.
#include <cstdint>
#include <string>
#include <vector>

#include "GlStateGuard.h"
#include "ProgramCache.h"
#include "ScreenTiles.h"

#include "SceneDepthSource.h"

namespace fx {

struct QuarterResPrograms {
    QuarterResPrograms() = default;
    ~QuarterResPrograms();
    QuarterResPrograms(const QuarterResPrograms&) = delete;
    QuarterResPrograms& operator=(const QuarterResPrograms&) = delete;

    /// Takes the quarter-res programs of `programs` (0 where one failed) and looks their uniforms
    /// up; creates the stream buffer and the sampler once. `programs` must outlive their use
    /// (until the next bind). Context current.
    void bind(const ProgramCache& programs);
    /// The downsample and the composites built: quarter res can draw.
    bool ok() const {
        return downsample && composite[DepthAware].program && composite[Bilinear].program && tileVao_;
    }
    /// The half-res z-test's program built (without it the quarter pass is simply not z-tested).
    bool halfZOk() const { return halfZ != 0; }

    /// Draws `tiles`' runs with the bound program (its uViewSize at `viewSizeLoc`), the vertices
    /// uploaded to this set's own stream buffer.
    void drawTiles(int viewSizeLoc, const ScreenTiles& tiles);

    NearestSampler hostDepth;  ///< the host's scene depth and the half-res depth, read whatever sampling was set
    ClampSampler halfColorSampler{ClampSampler::Filter::Linear};  ///< the composite's half-res colour, filtered
    uint32_t downsample = 0;
    int downsampleDepthLoc = -1, downsampleViewLoc = -1, downsampleCornerLoc = -1;
    SceneDepthUniforms downsampleDecode;
    uint32_t halfZ = 0;
    int halfZDepthLoc = -1, halfZFromLinearLoc = -1, halfZFarLoc = -1, halfZViewLoc = -1;
    /// The composite's builds: depth-aware, plain bilinear (RenderOptions::bilinearUpsample).
    enum CompositeVariant { DepthAware, Bilinear, CompositeVariantCount };
    struct CompositeProgram {
        uint32_t program = 0;
        int halfColor = -1, halfDepth = -1, sceneDepth = -1, threshold = -1, viewSize = -1;
        int lowMap = -1, invLow = -1;  ///< the footprint's line (fs_particles_composite.glsl)
        SceneDepthUniforms decode;
    };
    CompositeProgram composite[CompositeVariantCount];

private:
    uint32_t tileVao_ = 0, tileVbo_ = 0;
};

}  // namespace fx
