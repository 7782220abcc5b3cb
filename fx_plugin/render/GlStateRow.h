#pragma once
// One row of the pinned GL state table (PinnedGlState.h): a GL state value, how to read and set
// it, and what the plugin pins it to; and the readers and writers the rows use, one per kind of
// GL state (an enable cap, a pixel-store value, a per-unit binding, ...), each taking the row
// for its enum and index.
#include <cstdint>

namespace fx {

/// Texture units whose bindings (2D texture, sampler, LOD bias) the table holds: the units the
/// plugin may bind (GlStateGuard::kTextureUnits).
constexpr int kPinnedTextureUnits = 6;

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
        DepthRange, ///< [0, 1], or the HostDepthMappingScope's range for a view's guard
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

namespace pinnedgl {

using Row = PinnedGlState;
using Value = GlStateValue;

// Readers.
void getEnable(const Row&, Value*);
void getEnablei(const Row&, Value*);
void getInts(const Row&, Value*);
void getFloats(const Row&, Value*);
void getBool(const Row&, Value*);
void getPolygonFace(const Row&, Value*);
void getColorMaski(const Row&, Value*);
void getPolygonOffset(const Row&, Value*);
void getSampleCoverage(const Row&, Value*);
void getAlphaFunc(const Row&, Value*);
void getSampleMask(const Row&, Value*);
void getDepthRange(const Row&, Value*);
void getStencilFunc(const Row&, Value*);
void getStencilOp(const Row&, Value*);
void getClipControl(const Row&, Value*);
void getTexture2D(const Row&, Value*);
void getSampler(const Row&, Value*);
void getLodBias(const Row&, Value*);
void getBlendFunc(const Row&, Value*);
void getBlendEquation(const Row&, Value*);

// Writers.
void setEnable(const Row&, const Value&);
void setEnablei(const Row&, const Value&);
void setPixelStore(const Row&, const Value&);
void setPixelTransfer(const Row&, const Value&);
void setPolygonMode(const Row&, const Value&);
void setPolygonFace(const Row&, const Value&);
void setPolygonOffset(const Row&, const Value&);
void setLogicOp(const Row&, const Value&);
void setSampleCoverage(const Row&, const Value&);
void setSampleMask(const Row&, const Value&);
void setStencilFunc(const Row&, const Value&);
void setStencilOp(const Row&, const Value&);
void setStencilMask(const Row&, const Value&);
void setColorMaski(const Row&, const Value&);
void setBlendFunc(const Row&, const Value&);
void setBlendEquation(const Row&, const Value&);
void setBlendColor(const Row&, const Value&);
void setClearColor(const Row&, const Value&);
void setDepthFunc(const Row&, const Value&);
void setDepthMask(const Row&, const Value&);
void setDepthRange(const Row&, const Value&);
void setClipControl(const Row&, const Value&);
void setProvokingVertex(const Row&, const Value&);
void setPointSize(const Row&, const Value&);
void setLineWidth(const Row&, const Value&);
void setRestartIndex(const Row&, const Value&);
void setHint(const Row&, const Value&);
void setClampColor(const Row&, const Value&);
void setAlphaFunc(const Row&, const Value&);
void setViewport(const Row&, const Value&);
void setScissor(const Row&, const Value&);
void setProgram(const Row&, const Value&);
void setVertexArray(const Row&, const Value&);
void setBuffer(const Row&, const Value&);
void setFramebuffer(const Row&, const Value&);
void setActiveTexture(const Row&, const Value&);
void setTexture2D(const Row&, const Value&);
void setSampler(const Row&, const Value&);
void setLodBias(const Row&, const Value&);

/// A value of up to four numbers.
Value val(double a, double b = 0.0, double c = 0.0, double d = 0.0);

}  // namespace pinnedgl
}  // namespace fx
