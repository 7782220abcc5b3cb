#pragma once
// Four lanes of SSE2 where the target has it (every x86-64 compiler; 32-bit MSVC with
// /arch:SSE2): FX_SSE2 is 1 and <emmintrin.h> is in. Elsewhere FX_SSE2 is 0 and the callers keep
// their one-at-a-time path. Each four-lane path in the plugin gives the same bits as its one-lane
// path (the same operations in the same order, no fused multiply-add: x86-64 has none without
// -mfma), and a test holds it to that: FootprintMath (ScreenTilesTest), ViewFrustum
// (DrawListOrderTest).
#if defined(__SSE2__) || defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 2)
#include <emmintrin.h>
#define FX_SSE2 1
#else
#define FX_SSE2 0
#endif
