#pragma once
// Four lanes of SSE2 where the target has it (every x86-64 compiler; 32-bit MSVC with
// /arch:SSE2): FX_SSE2 is 1 and <emmintrin.h> is in. Elsewhere FX_SSE2 is 0 and the callers keep
// their one-at-a-time path. Each four-lane path in the plugin gives the same bits as its one-lane
// path (the same operations in the same order, no fused multiply-add: x86-64 has none without
// -mfma), and the tests hold it to that: FootprintMath's lanes against its one-lane functions,
// screenRect and binParticles against themselves with the four lanes turned off (setFourLanes;
// ScreenTilesTest), ViewFrustum's lanes and the draw list's cull against the one-lane frustum
// test (DrawListOrderTest).
#include <atomic>

#if defined(__SSE2__) || defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 2)
#include <emmintrin.h>
#define FX_SSE2 1
#else
#define FX_SSE2 0
#endif

// The four-lane helpers are long enough that compilers call them rather than inline them into
// their loops, keeping their vectors in memory across the call; forced inline they stay in
// registers (bench_draw BM_TileBins, BM_ScreenRect).
#if defined(__GNUC__) || defined(__clang__)
#define FX_LANES_INLINE inline __attribute__((always_inline))
#elif defined(_MSC_VER)
#define FX_LANES_INLINE __forceinline
#else
#define FX_LANES_INLINE inline
#endif

namespace fx {

inline std::atomic<bool>& fourLanesSwitch() {
    static std::atomic<bool> on{true};
    return on;
}
/// Whether the four-lane paths run: FX_SSE2 and not turned off.
inline bool fourLanes() { return FX_SSE2 && fourLanesSwitch().load(std::memory_order_relaxed); }
/// Tests: off runs the one-lane paths only, to compare the two.
inline void setFourLanes(bool on) { fourLanesSwitch().store(on, std::memory_order_relaxed); }

}  // namespace fx
