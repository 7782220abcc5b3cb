// TiledPath's rules (TiledPath.h): where it draws (available, wanted, canDraw) and the limits a
// session can set from the environment for measuring on a given GPU (the CPU's lists, deferred bins).
#include "TiledPath.h"

#include <algorithm>
#include <atomic>
#include <climits>
#include <cstdlib>
#include <cstring>

#include "render/PrivateGl.h"

namespace fx {
namespace {

// CUBEFX_TILED_CPU_LISTS, read once: a whole number of entries (clamped to 2^32 - 1), else -1 (the
// defaults), with a problem to report where it was set but not a number.
const char* gCpuListLimitProblem = nullptr;
int64_t cpuListLimitFromEnvironment() {
    const char* v = std::getenv("CUBEFX_TILED_CPU_LISTS");
    if (!v || !*v) return -1;
    uint64_t n = 0;
    for (const char* c = v; *c; ++c) {
        if (*c < '0' || *c > '9') {
            gCpuListLimitProblem = "fx: CUBEFX_TILED_CPU_LISTS is not a whole number of list entries; the tiled "
                                   "path keeps its defaults (the GPU writes the lists, on a software rasterizer "
                                   "the CPU up to 131072 entries)";
            return -1;
        }
        n = std::min<uint64_t>(n * 10 + uint64_t(*c - '0'), UINT32_MAX);
    }
    return int64_t(n);
}
static_assert(TiledPath::kSoftwareCpuListEntries == 131072, "the message above names the default");
const int64_t gCpuListLimitFromEnvironment = cpuListLimitFromEnvironment();
std::atomic<int64_t> gCpuListLimit{gCpuListLimitFromEnvironment};  // -1: the defaults

// CUBEFX_TILED_DEFER_BINS, read once: 0 bins every view when it is declared, 1 (or unset) defers
// them where deferBins() says; anything else is reported and ignored.
const char* gDeferBinsProblem = nullptr;
int deferBinsFromEnvironment() {
    const char* v = std::getenv("CUBEFX_TILED_DEFER_BINS");
    if (!v || !*v) return -1;
    if (std::strcmp(v, "0") == 0 || std::strcmp(v, "1") == 0) return v[0] - '0';
    gDeferBinsProblem = "fx: CUBEFX_TILED_DEFER_BINS is neither 0 nor 1; the tiled path keeps its default (the "
                        "bins of a view the GPU orders are worked out in its pass)";
    return -1;
}
const int gDeferBinsFromEnvironment = deferBinsFromEnvironment();
std::atomic<int> gDeferBins{gDeferBinsFromEnvironment};  // -1: the default (on)

// CUBEFX_TILED_GPU_BINS, read once: 0 bins a deferred view on the host's threads, 1 (or unset) on
// the GPU where its programs built; anything else is reported and ignored.
const char* gGpuBinsProblem = nullptr;
int gpuBinsFromEnvironment() {
    const char* v = std::getenv("CUBEFX_TILED_GPU_BINS");
    if (!v || !*v) return -1;
    if (std::strcmp(v, "0") == 0 || std::strcmp(v, "1") == 0) return v[0] - '0';
    gGpuBinsProblem = "fx: CUBEFX_TILED_GPU_BINS is neither 0 nor 1; the tiled path keeps its default (the GPU "
                      "bins the views whose particles it orders)";
    return -1;
}
const int gGpuBinsFromEnvironment = gpuBinsFromEnvironment();
std::atomic<int> gGpuBins{gGpuBinsFromEnvironment};  // -1: the default (on)

}  // namespace

bool TiledPath::gpuBins() { return gGpuBins.load(std::memory_order_relaxed) != 0; }
void TiledPath::setGpuBins(bool on) { gGpuBins.store(on ? 1 : 0, std::memory_order_relaxed); }
void TiledPath::resetGpuBins() { gGpuBins.store(gGpuBinsFromEnvironment, std::memory_order_relaxed); }
const char* TiledPath::gpuBinsProblem() { return gGpuBinsProblem; }

uint32_t TiledPath::cpuListLimit(bool softwareRasterizer) {
    const int64_t set = gCpuListLimit.load(std::memory_order_relaxed);
    if (set >= 0) return uint32_t(set);
    return softwareRasterizer ? kSoftwareCpuListEntries : kCpuListEntries;
}
void TiledPath::setCpuListLimit(uint32_t entries) { gCpuListLimit.store(int64_t(entries), std::memory_order_relaxed); }
void TiledPath::resetCpuListLimit() { gCpuListLimit.store(gCpuListLimitFromEnvironment, std::memory_order_relaxed); }
const char* TiledPath::cpuListLimitProblem() { return gCpuListLimitProblem; }
bool TiledPath::deferBins() { return gDeferBins.load(std::memory_order_relaxed) != 0; }
void TiledPath::setDeferBins(bool on) { gDeferBins.store(on ? 1 : 0, std::memory_order_relaxed); }
void TiledPath::resetDeferBins() { gDeferBins.store(gDeferBinsFromEnvironment, std::memory_order_relaxed); }
const char* TiledPath::deferBinsProblem() { return gDeferBinsProblem; }
bool TiledPath::softwareRasterizer(const char* renderer) {
    if (!renderer) return false;
    for (const char* name : {"llvmpipe", "softpipe", "Software Rasterizer", "SwiftShader", "Basic Render Driver"}) {
        if (std::strstr(renderer, name)) return true;
    }
    return false;
}

bool TiledPath::wanted(const RenderOptions& options) {
    if (options.tiling == Tiling::Off && !options.tiled) return false;
    if (!available()) return false;
    if (options.tiled || options.tiling == Tiling::On) return true;
    return !softwareRasterizer(reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
}

bool TiledPath::available() {
    const bool extensions = FXGLAD_GL_ARB_compute_shader && FXGLAD_GL_ARB_shader_storage_buffer_object &&
                            FXGLAD_GL_ARB_shader_image_load_store;
    return extensions && glDispatchCompute && glMemoryBarrier && glBindImageTexture && glBindBufferBase &&
           glBindBufferRange && glGetInteger64i_v;
}

bool TiledPath::flatW(const glm::mat4& p) {
    return p[0][3] == 0.0f && p[1][3] == 0.0f && p[0][0] * p[1][1] - p[1][0] * p[0][1] != 0.0f;
}

bool TiledPath::canDraw(const ParticleView& v) {
    if (v.list.batches.size() > size_t(kMaxBatches)) return false;
    const glm::mat4& p = v.view.proj;
    // Billboards: a projection whose w does not depend on x and y (perspective, orthographic).
    // Spheres: a perspective one whose x and y are not mixed (their rays' slopes, as the raster
    // path's vertex shader has them).
    const bool flatW = TiledPath::flatW(p);
    const bool perspective = flatW && p[0][1] == 0.0f && p[1][0] == 0.0f && p[2][3] == -1.0f && p[3][3] == 0.0f;
    for (const DrawBatch& b : v.list.batches) {
        const bool billboard = b.technique == Technique::Hard || b.technique == Technique::Soft;
        if (!(billboard && flatW) && !(b.technique == Technique::Spherical && perspective)) return false;
    }
    return flatW;
}

}  // namespace fx
