#pragma once
// Fade classification (Plugin::setFadeClassification): before the full-res
// particle pass, one small pass reduces the scene depth to its (min, max) per 16 px tile and per
// 64 px tile ("particles_tile_depth", targets "particles_tiles" and "particles_tiles_coarse",
// RG32F, a 1/256 and a 1/4096 of the view's pixels). The soft and spherical programs built with
// FX_CLASSIFY read those in the vertex shader (shaders/particles_classify.glsl) and put every
// particle in one of three classes: fade needed (as without classification), wholly in front of
// the scene by more than its softness (the fragment shader skips the scene-depth fetch and the
// fade), wholly hidden behind it (not rasterised). The image is the unclassified one, bit for bit.
//
// Where it pays: on a GPU the fragment shader's branch is per particle, coherent, and skips a
// dependent texture fetch. On a CPU rasteriser (llvmpipe runs both sides of a branch) only the
// hidden particles' triangle set-up is saved, against the tile pass: the switch is off by
// default and fxbench measures both (`soft+classify`, `spherical+classify`).
//
// Counting (Plugin::setFadeClassCounting): after the particle draws, one point per soft or
// spherical particle is classified again by the same function and added into a 1 x 1 RGBA32F
// target, which is read back: a wait for the GPU, so only for diagnostics and benchmarks.
//
// Quarter res is not classified: its half-res pass already z-tests a quarter of the fragments
// (see ParticleRenderer.h), and its depth is the half-res minimum, not the full-res tiles.
#include <cstdint>
#include <string>
#include <vector>

#include "GlStateGuard.h"
#include "SceneDepthSource.h"
#include "ShaderLoader.h"
#include "fx/HostAdapter.h"
#include "fx/Plugin.h"

namespace fx {

class InstanceStream;
struct DrawBatch;

class FadeClassifier {
public:
    static constexpr int kTileSize = 16;        ///< particles_classify.glsl kTileSize
    static constexpr int kCoarseTileSize = 64;  ///< particles_classify.glsl kCoarseTileSize
    static constexpr const char* kPass = "particles_tile_depth";
    static constexpr const char* kTileTarget = "particles_tiles";
    static constexpr const char* kCoarseTarget = "particles_tiles_coarse";
    /// Texture units of the tile targets in the classified particle draws.
    static constexpr int kTileUnit = 4, kCoarseUnit = 5;

    FadeClassifier() = default;
    ~FadeClassifier();
    FadeClassifier(const FadeClassifier&) = delete;
    FadeClassifier& operator=(const FadeClassifier&) = delete;

    /// Builds the tile programs and the counting program; appends one "file:line: message" block
    /// per failure to *errors. The classified particle programs are ProgramCache keys
    /// (Key::classified), built by the renderer with the rest.
    void build(const std::string& shaderDir, std::vector<std::string>* errors);
    /// The same from `read` (a snapshot: the files of the running particle programs).
    void build(const ShaderReader& read, std::vector<std::string>* errors);
    /// Reads the classifier's files (and their includes) through `read` without building
    /// anything: a snapshot then holds them for a build later (enabling classification after a
    /// rejected edit builds from the files that went live).
    static void readSources(const ShaderReader& read);
    /// Everything built.
    bool ok() const;

    /// The tile targets of a view of `width` x `height` pixels.
    static TargetDesc tileTargetDesc(int width, int height, bool coarse);

    /// The tile pass body: fills `tiles` and `coarse` from the linear scene depth.
    void buildTiles(PassContext& ctx, Target sceneDepth, const SceneDepthDecode& decode, Target tiles, Target coarse);

    /// Counts the classes of `batches`' soft and spherical particles (the instance stream holds
    /// them, uploaded): draws into the counter and reads it back. Changes the framebuffer,
    /// viewport, program, blend and the texture units kTileUnit / kCoarseUnit (inside the
    /// caller's GlStateGuard).
    FadeClassCounts count(const std::vector<DrawBatch>& batches, InstanceStream& stream, const ViewInfo& view,
                          uint32_t tiles, uint32_t coarse);

private:
    NearestSampler hostDepth_;   ///< the host's scene depth, read whatever sampling it set
    uint32_t tileProgram_ = 0, coarseProgram_ = 0, countProgram_ = 0;
    int tileSourceLoc_ = -1, coarseSourceLoc_ = -1;
    SceneDepthUniforms tileDecodeLoc_;
    int countView_ = -1, countProj_ = -1, countNear_ = -1, countSoftScale_ = -1, countSphere_ = -1,
        countTiles_ = -1, countCoarse_ = -1, countViewSize_ = -1;
    uint32_t vao_ = 0;         ///< empty: the tile pass's triangle comes from gl_VertexID
    uint32_t counter_ = 0;     ///< 1 x 1 RGBA32F
    uint32_t counterFbo_ = 0;
};

}  // namespace fx
