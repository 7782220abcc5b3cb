// TiledPath's rules (TiledPath.h): where it draws (available, wanted, canDraw) and the limits a
// session can set from the environment for measuring on a given GPU (the CPU's lists, deferred bins).
#include "TiledPath.h"

#include <algorithm>
#include <atomic>
#include <climits>
#include <cstdlib>
#include <cstring>

#include "base/EnvSwitch.h"
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

// The A/B switches (EnvSwitch.h): deferred bins, the GPU's bins, the gather in the pass.
EnvSwitch gDeferBins("CUBEFX_TILED_DEFER_BINS",
                     "fx: CUBEFX_TILED_DEFER_BINS is neither 0 nor 1; the tiled path keeps its default (the bins of a "
                     "view the GPU orders are worked out in its pass)");
EnvSwitch gGpuBins("CUBEFX_TILED_GPU_BINS",
                   "fx: CUBEFX_TILED_GPU_BINS is neither 0 nor 1; the tiled path keeps its default (the GPU bins the "
                   "views whose particles it orders)");
EnvSwitch gGatherInPass("CUBEFX_TILED_GATHER_IN_PASS",
                        "fx: CUBEFX_TILED_GATHER_IN_PASS is neither 0 nor 1; the tiled path keeps its default (the "
                        "particles of a view the GPU bins are written in its first pass)");

}  // namespace

bool TiledPath::gpuBins() { return gGpuBins.on(); }
bool TiledPath::gatherInPass() { return gGatherInPass.on(); }
void TiledPath::setGatherInPass(bool on) { gGatherInPass.set(on); }
void TiledPath::resetGatherInPass() { gGatherInPass.reset(); }
const char* TiledPath::gatherInPassProblem() { return gGatherInPass.problem(); }
void TiledPath::setGpuBins(bool on) { gGpuBins.set(on); }
void TiledPath::resetGpuBins() { gGpuBins.reset(); }
const char* TiledPath::gpuBinsProblem() { return gGpuBins.problem(); }

uint32_t TiledPath::cpuListLimit(bool softwareRasterizer) {
    const int64_t set = gCpuListLimit.load(std::memory_order_relaxed);
    if (set >= 0) return uint32_t(set);
    return softwareRasterizer ? kSoftwareCpuListEntries : kCpuListEntries;
}
void TiledPath::setCpuListLimit(uint32_t entries) { gCpuListLimit.store(int64_t(entries), std::memory_order_relaxed); }
void TiledPath::resetCpuListLimit() { gCpuListLimit.store(gCpuListLimitFromEnvironment, std::memory_order_relaxed); }
const char* TiledPath::cpuListLimitProblem() { return gCpuListLimitProblem; }
bool TiledPath::deferBins() { return gDeferBins.on(); }
void TiledPath::setDeferBins(bool on) { gDeferBins.set(on); }
void TiledPath::resetDeferBins() { gDeferBins.reset(); }
const char* TiledPath::deferBinsProblem() { return gDeferBins.problem(); }
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
