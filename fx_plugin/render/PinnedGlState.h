#pragma once
// The table behind GlStateGuard (GlStateGuard.h states the contract and lists every entry with
// the value the plugin sets): one row per GL state value, with how to read it, how to set it,
// and the value the plugin pins it to while its GL calls run. Built once per process on first
// use from the current context: its profile (compatibility-only rows only in a compatibility
// context), its version and extensions (clip control, primitive restart fixed index) and its
// limits (one row per clip distance and per draw buffer).
#include <cstdint>
#include <vector>

namespace fx {

/// Up to four numbers of one state value (doubles hold every GLint, GLuint mask and GLfloat
/// exactly).
struct GlStateValue {
    double v[4] = {0.0, 0.0, 0.0, 0.0};
    bool operator==(const GlStateValue& o) const {
        return v[0] == o.v[0] && v[1] == o.v[1] && v[2] == o.v[2] && v[3] == o.v[3];
    }
    bool operator!=(const GlStateValue& o) const { return !(*this == o); }
};

struct PinnedGlState {
    /// What the plugin does with the state inside a guard.
    enum class Pin : uint8_t {
        Value,      ///< set to `pinned` (only when the host's value differs)
        Always,     ///< set to `pinned` every time (capturing other rows moves it: active texture)
        DepthMode,  ///< clip control: origin lower left, depth mode from the guard's DepthConvention
        Restore,    ///< not set: the plugin sets it itself before use (bindings, viewport, scissor
                    ///< box); only captured and restored
    };
    const char* name;
    bool compatibility;  ///< a compatibility-profile-only row
    uint32_t pname;      ///< the enum read / set (enable cap, pixel-store name, ...)
    uint32_t index;      ///< draw buffer, clip distance, texture unit or face, where one applies
    void (*get)(const PinnedGlState&, GlStateValue*);
    void (*set)(const PinnedGlState&, const GlStateValue&);
    Pin pin;
    GlStateValue pinned;
};

/// The rows for the current context, in capture order (restore runs backwards). Needs the
/// plugin's GL table loaded and a context current.
const std::vector<PinnedGlState>& pinnedGlStates();

/// Counts of the current context's rows (for the report and the tests).
struct PinnedGlStateCount {
    int core = 0, compatibility = 0;
};
PinnedGlStateCount pinnedGlStateCount();

}  // namespace fx
