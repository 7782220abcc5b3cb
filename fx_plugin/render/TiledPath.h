#pragma once
// Tiled (RenderOptions::tiling, API 2.4; `tiled`, 2.3): hard and soft billboards and spherical
// particles of a full-resolution view shaded by a compute shader per 16 x 16 pixel tile instead of
// rasterised and blended one fragment at a time. By default (Tiling::Auto) on a GPU, not on a
// software rasterizer, where it measured 2.3-5x slower than the raster path (wanted()).
//   "particles_tiled_setup"  only for a view binned in its pass (deferBins()): reads sceneDepth,
//                      writes sceneColor (draws nothing into it: the two passes stay together)
//   "particles_tiled"  reads sceneDepth (the z-buffer in place, or the host's linear depth),
//                      writes sceneColor
// Declaring the pass bounds the view's particles and counts each tile's entries on the CPU
// (binParticles, TileBins.h: each particle into the tiles its bound touches, front to back). The
// pass writes each tile's list on the GPU (TileSort.h: a pair per particle and tile, sorted by
// tile, stably); a view of at most cpuListLimit() entries (none by default on a GPU) gets its lists
// written on the CPU instead (writeEntries). A view of many particles (ordersOnGpu) comes with its
// list unsorted (DrawList::orderPending), the GPU sorts its particles back to front first, and
// its bins wait for the pass (deferBins()), where the GPU works them out (gpuBins()). The pass sets each particle up once (a compute
// dispatch, one invocation per particle: what the vertex shader works out), then dispatches one work group per tile that holds particles (one invocation per pixel:
// one scene-depth fetch per pixel, the particles' records read in order, the blend in registers,
// stopped once the pixel is opaque) into the plugin's own RGBA16F image, and draws those tiles
// onto sceneColor blended (ONE, ONE_MINUS_SRC_ALPHA): one blend per covered pixel instead of one
// per particle fragment (cs_particles_tiled.glsl).
//
// Why: on the GPUs this project is measured on, soft's raster pass is bound by its per-fragment
// texture reads (docs/results.md, session 21: soft's depth fetch is 0.485 ms of its 1.690 ms
// pass on the H200, spherical's 0.36 ms of 3.681), and by the blend of every fragment of
// overdraw; here the depth fetch is paid per pixel and no fragment is blended.
//
// Where it draws: a context with compute shaders, shader storage buffers and image load/store
// (GL 4.3, or the three ARB extensions: available()), a view whose every batch is hard, soft or
// spherical, lit or not (lit smoke: the FX_LIT builds, reading the frame's opacity map), at most
// kMaxBatches batches, under a projection whose w does not depend on x
// and y (perspective or orthographic; with spheres, perspective). Elsewhere the renderer draws the
// view at full resolution as before (canDraw() says which). With RenderOptions::quarterRes a view
// this path can draw is drawn here, not at quarter res (it costs less: ParticleRenderer's
// declarePasses); quarterResAlways keeps quarter res.
//
// The picture: the raster path's up to rounding (one blend of a float sum instead of a blend per
// fragment into the target; a texel level picked from one level of detail per particle, for a
// sphere that of its centre), hard particles cut where the scene is nearer in linear depth instead
// of window depth, and a pixel's particles behind an opacity of 1 - 1/2048 left out
// (TiledPathTest: at most 4/255, spheres 5; docs/results.md has fxbench's error).
//
// GL state: the pass runs in a GlStateGuard; what it touches beyond the guard's rows (shader
// storage buffer bindings 0-4 and the generic one, image unit 0) it reads first and puts back.
#include <functional>
#include <memory>

#include "ParticleDraw.h"
#include "RendererConfig.h"
#include "TileSort.h"
#include "TiledStageTimes.h"

namespace fx {

class TiledPath {
public:
    static constexpr const char* kPass = "particles_tiled";
    /// The first of a view's two passes when its bins wait for the pass (deferBins()).
    static constexpr const char* kSetupPass = "particles_tiled_setup";
    static constexpr int kMaxBatches = 32;  ///< cs_particles_tiled.glsl's kMaxBatches
    static constexpr int kTileSize = ScreenTiles::kTileSize;  ///< the compute shader's group size
    /// Up to this many list entries a view's lists are written on the CPU and uploaded, above it
    /// on the GPU (TileSort). 0 since the emit wrote one pair per invocation: on the H200
    /// (docs/results.md, session 28) the GPU's lists then cost the pass 0.06-0.07 ms where the CPU's
    /// cost the frame 0.14-0.36 ms more outside the passes (1,000 and 4,000 particles, the standard
    /// scene), and were never the cheaper frame at any size measured (1,000 to 520,000 entries).
    /// Until then 131,072: the GPU's lists took 0.18 ms plus 2 ns an entry (session 26).
    static constexpr uint32_t kCpuListEntries = 0;
    /// The same on a software rasterizer (softwareRasterizer()), whose compute shaders run on the
    /// CPU: there the host writing the lists costs less than its "GPU" sorting them (llvmpipe,
    /// 640x360: soft+tiled 104.7 ms a frame with these, 116.8 with the GPU's).
    static constexpr uint32_t kSoftwareCpuListEntries = 131072;
    /// The limit in use: the environment's CUBEFX_TILED_CPU_LISTS (a whole number of entries; 0:
    /// always the GPU sort) or setCpuListLimit()'s where either is set, so a GPU session can find
    /// where the CPU's lists stop paying without a rebuild and tests can compare the two ways;
    /// else kSoftwareCpuListEntries on a software rasterizer, kCpuListEntries elsewhere.
    static uint32_t cpuListLimit(bool softwareRasterizer);
    static void setCpuListLimit(uint32_t entries);
    /// Back to the environment's limit, or the defaults where it has none.
    static void resetCpuListLimit();
    /// What was wrong with CUBEFX_TILED_CPU_LISTS (ignored then), or null: for the renderer's log.
    static const char* cpuListLimitProblem();
    /// Views whose lists were written on the CPU / sorted on the GPU, since the process started.
    static uint64_t cpuListViews();
    static uint64_t gpuSortedViews();

    TiledPath(ParticleDraw& draw, SizeMismatchReport sizeMismatch);
    ~TiledPath();
    TiledPath(const TiledPath&) = delete;
    TiledPath& operator=(const TiledPath&) = delete;

    /// The current context has what the path needs (see above). Context current.
    static bool available();
    /// Whether `options` draw the tiled path in the current context: available() and tiled or
    /// Tiling::On, or Tiling::Auto where the context is not a software rasterizer. Context current.
    static bool wanted(const RenderOptions& options);
    /// Whether a GL_RENDERER string names a software rasterizer (Mesa's llvmpipe, softpipe and
    /// swrast, SwiftShader, Microsoft's Basic Render Driver): where Tiling::Auto rasterises.
    static bool softwareRasterizer(const char* renderer);
    /// Takes the tiled programs of `programs` (0 where one failed or was never built) and looks
    /// their uniforms up. Context current, inside a guard.
    void bind(const ProgramCache& programs);
    /// Its programs built (the sort's too); litOk: the lit ones as well.
    bool ok() const { return setup_ != 0 && shade_ != 0 && composite_ != 0 && sort_.ok(); }
    bool litOk() const { return ok() && setupLit_ != 0 && shadeLit_ != 0; }
    /// Whether `view` draws `batch` lit: a scene light and a reaction that takes it (as the raster
    /// path's drawKey).
    static bool litBatch(const ParticleView& view, const DrawBatch& batch) {
        return view.lit() && batch.lighting.lit(batch.blend);
    }
    /// Whether this view can be drawn tiled (the rule above; no GL).
    static bool canDraw(const ParticleView& view);
    /// Whether `proj`'s w does not depend on x and y: what canDraw asks of every view.
    static bool flatW(const glm::mat4& proj);
    /// Whether a view of `particles` particles drawn here has them sorted back to front on the GPU
    /// (TileSort::DepthOrder): the order's programs built, the GPU writes the lists (cpuListLimit()
    /// 0) and at least TileSort::orderLimit() particles. The renderer builds such a view's list
    /// without its CPU sort (DrawList::orderPending); declare() takes either.
    bool ordersOnGpu(int particles) const {
        return sort_.orderOk() && cpuListLimit(software_) == 0 && particles > 0 &&
               uint32_t(particles) >= TileSort::orderLimit(software_);
    }

    /// Bins the view's particles and declares its pass; false (nothing declared) where a particle
    /// has no bound, the lists would not fit a shader storage block or a lit batch finds no lit
    /// program: the caller declares the full-resolution pass instead.
    /// `jobs`: the host's job system, for the binning.
    /// `fallback`: how the full-resolution pass draws the view into color, reading depth (decoded)
    /// and opacity, in this pass (it reads and writes what this one declares). Given, a view the
    /// GPU orders is binned in the pass instead (deferBins()), which calls it where those bins fail.
    using Fallback = std::function<void(PassContext& ctx, Target color, Target depth, const SceneDepthDecode& decode,
                                        Target opacity)>;
    bool declare(FrameBuilder& frame, const std::shared_ptr<ParticleView>& view, const Jobs& jobs = Jobs(),
                 Fallback fallback = nullptr);

    /// Deferred bins. A view the GPU orders (ordersOnGpu, DrawList::orderPending) in a frame graph
    /// (in the immediate path only where the GPU bins it, gpuBins()) is binned when its passes run, not when it is declared: its first
    /// pass (kSetupPass) uploads the instances, issues the particles' order and records (which
    /// need no bins) and flushes; the second (kPass) bins on the host's threads (or reads back the
    /// GPU's bins, gpuBins()), then writes the lists and shades the tiles. The GPU works through the scene's passes and those dispatches
    /// meanwhile, where a frame that bins while declaring leaves it idle until its first pass
    /// (fxbench's "declare"; bench_draw: binning 256,000 particles takes 1.3 ms on the H200's
    /// host's 16 threads, docs/results.md session 29). Two passes, not one, so that the time the
    /// GPU still waits for the bins falls between passes, where a host's GPU timer counts it
    /// outside them (fxbench's "outside"), not inside the second: kPass's own timer query is
    /// flushed with its dispatches, after the bins (unless the driver flushes it on its own
    /// earlier). The picture is the same bit for bit
    /// (TiledPathTest). Where the bins then fail (a particle with no bound, lists past a storage
    /// block), the second pass draws the view through declare()'s fallback; where the first did
    /// not run just before it for this view, the second does its work too.
    /// On unless CUBEFX_TILED_DEFER_BINS=0 or setDeferBins(false), for A/B runs on a GPU.
    static bool deferBins();
    static void setDeferBins(bool on);
    static void resetDeferBins();           ///< back to the environment's, or on
    static const char* deferBinsProblem();  ///< what was wrong with CUBEFX_TILED_DEFER_BINS, or null
    /// Views binned in their pass, and those of them drawn through the fallback, since the process started.
    static uint64_t deferredBinViews();
    static uint64_t deferredFallbacks();
    /// The GPU's bins. A view binned in its pass is bounded and counted by the GPU
    /// (TileSort::binOnGpu: FX_TILE_BOUND, FX_TILE_LIST), issued in the first pass with the
    /// particles' order and records, instead of on the host's threads in the second; the second
    /// reads back how many entries and which tiles (readGpuBins: a wait, for what the GPU had queued)
    /// and goes on as before. What the CPU saves: every per-particle step of the bins (on the H200's
    /// 16 threads 1.3 ms at 256,000 particles, docs/results.md session 29) and the upload of their
    /// words. The lists are binParticles' bit for bit where the GPU's division rounds as the CPU's
    /// (llvmpipe: TileSortTest), and the picture is the same either way: a bound a rounding off
    /// moves at most a tile of the pixel it is grown by, where the particle draws nothing.
    /// renderView's views too (its scene depth copy then covers the view: the bins are known only
    /// once the passes run; on the host's threads they are binned while declared, the copy narrowed
    /// to them). On unless CUBEFX_TILED_GPU_BINS=0 or setGpuBins(false), for A/B runs on a GPU;
    /// without its two programs (TileSort::binsOk) the host's threads bin as before.
    static bool gpuBins();
    static void setGpuBins(bool on);
    static void resetGpuBins();           ///< back to the environment's, or on
    static const char* gpuBinsProblem();  ///< what was wrong with CUBEFX_TILED_GPU_BINS, or null
    static uint64_t gpuBinnedViews();     ///< views the GPU binned, since the process started
    /// The particles of a view the GPU bins written in its first pass: declaring only culls and
    /// counts them (DrawList::gatherPending), and the pass writes them from the pools straight
    /// into its mapped storage buffer (fillInstances) instead of copying the list declaring wrote.
    /// On unless CUBEFX_TILED_GATHER_IN_PASS=0 or setGatherInPass(false), for A/B runs on a GPU.
    static bool gatherInPass();
    static void setGatherInPass(bool on);
    static void resetGatherInPass();           ///< back to the environment's, or on
    static const char* gatherInPassProblem();  ///< what was wrong with CUBEFX_TILED_GATHER_IN_PASS, or null
    /// Views whose particles their first pass wrote so, since the process started.
    static uint64_t gatheredViews();
    /// Where TiledStageTimes' reports go (the renderer's log); none: not reported.
    void setStageLog(std::function<void(const std::string&)> log) { stageLog_ = std::move(log); }

private:
    // What run() does of a view: all of it in one pass (Whole, its bins made while declaring);
    // or, binned in its pass, the first of two (Setup: the instances, the particles' order and
    // records, flushed) and then the second (Tiles: the bins, the lists, the tiles).
    enum class Stage : uint8_t { Whole, Setup, Tiles };
    // Draws the view, or sets it up (Stage::Setup); false where deferred bins failed and nothing
    // was drawn. Inside the pass's guard.
    bool run(PassContext& ctx, ParticleView& v, Target color, Target depth, const SceneDepthDecode& decode,
             Target opacity, Stage stage);
    // The batches as binParticles takes them; returns their count.
    static int batchRanges(const ParticleView& v, TileBins::Range* ranges);
    // A view binned in its pass is binned by the GPU: switched on (gpuBins()) and its programs built.
    bool binsOnGpu() const { return gpuBins() && sort_.binsOk(); }
    void ensureObjects(int width, int height);

    ParticleDraw& draw_;
    SizeMismatchReport sizeMismatch_;
    const ParticleView* setUpView_ = nullptr;  ///< the view whose Setup stage ran last, until a stage runs again
    bool gpuBinned_ = false;  ///< that Setup stage (or this Tiles stage) issued the GPU's bins
    TiledStageTimes stageTimes_;  ///< CUBEFX_TILED_STAGE_TIMES=1: a deferred view's GPU time by stage
    std::function<void(const std::string&)> stageLog_;
    uint32_t setup_ = 0, shade_ = 0, composite_ = 0, setupLit_ = 0, shadeLit_ = 0;
    bool software_ = false;  ///< the context is a software rasterizer (bind()): cpuListLimit's default
    struct ShadeUniforms {
        int view = -1, proj = -1, nearPlane = -1, farPlane = -1, atlas = -1, ramp = -1, sceneDepth = -1;
        int batchA = -1, batchB = -1, batchRange = -1, batchCount = -1, instanceCount = -1, pixelSlope = -1;
        int tileCount = -1, groupsX = -1, viewSize = -1, pixelToNdc = -1, atlasTexels = -1;
        SceneDepthUniforms decode;
        FogUniforms fog;
        // FX_LIT only.
        int batchLight = -1, batchShade = -1, sunView = -1, sunColor = -1, shadowed = -1, viewToShadow = -1,
            opacity = -1, litAtlas = -1, trimmed = -1, shapeBuckets = -1, lodScale = -1;
    };
    ShadeUniforms setupUniforms_, shadeUniforms_, setupLitUniforms_, shadeLitUniforms_;
    int compositeAccum_ = -1, compositeOrigin_ = -1, compositeViewSize_ = -1;
    TileSort sort_;                              ///< writes the tiles' lists
    uint32_t tileBuffer_ = 0;                    ///< the tiles (shader storage)
    size_t tileCapacity_ = 0;
    uint32_t instanceBuffer_ = 0;                ///< the instances (shader storage, the pass's own)
    size_t instanceCapacity_ = 0;
    uint32_t entryBuffer_ = 0;                   ///< the lists when the CPU wrote them
    size_t entryCapacity_ = 0;
    uint32_t recordBuffer_ = 0;                  ///< the particles' records (the setup dispatch's)
    size_t recordCapacity_ = 0;
    uint32_t lightBuffer_ = 0;                   ///< lit particles' light (the lit setup's)
    size_t lightCapacity_ = 0;
    uint32_t shapeBuffer_ = 0;                   ///< the billboards' trimmed polygons (lit setup and shade)
    std::vector<glm::vec4> shapesUploaded_;      ///< what shapeBuffer_ holds
    uint32_t accum_ = 0;                         ///< RGBA16F, at least the view's size
    int accumWidth_ = 0, accumHeight_ = 0;
    uint32_t coverVao_ = 0, coverVbo_ = 0;       ///< the covered tiles' runs
};

}  // namespace fx
