#pragma once
// The table behind GlStateGuard (GlStateGuard.h states the contract and lists every entry with
// the value the plugin sets): one row per GL state value, with how to read it, how to set it,
// and the value the plugin pins it to while its GL calls run. Built once per process on first
// use from the current context: its profile (compatibility-only rows only in a compatibility
// context), its version and extensions (clip control, primitive restart fixed index) and its
// limits (one row per clip distance and per draw buffer).
#include <vector>

#include "GlStateRow.h"

namespace fx {

/// The rows for the current context, in capture order (restore runs backwards). Needs the
/// plugin's GL table loaded and a context current.
const std::vector<PinnedGlState>& pinnedGlStates();

/// Counts of the current context's rows (for the report and the tests).
struct PinnedGlStateCount {
    int core = 0, compatibility = 0;
};
PinnedGlStateCount pinnedGlStateCount();

}  // namespace fx
