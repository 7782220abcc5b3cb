#include "PinnedGlState.h"

#include <algorithm>

#include "render/PrivateGl.h"

namespace fx {
namespace {

using namespace pinnedgl;  // the rows' readers and writers
using Pin = PinnedGlState::Pin;

bool g_compatibility = false;  // the context the table was built for

constexpr GLenum kPrimitiveRestartFixedIndex = 0x8D69;  // GL 4.3: not in the 3.3 loader's header

std::vector<Row> build() {
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    const int version = major * 10 + minor;
    g_compatibility = (profile & GL_CONTEXT_CORE_PROFILE_BIT) == 0;
    const bool clipControl = glClipControl != nullptr && (FXGLAD_GL_ARB_clip_control || version >= 45);
    GLint clipDistances = 0, drawBuffers = 0;
    glGetIntegerv(GL_MAX_CLIP_DISTANCES, &clipDistances);
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &drawBuffers);
    // Bounded so that a guard's saved values fit its fixed array (GL's minimum for both is 8).
    clipDistances = std::clamp(clipDistances, 0, 16);
    drawBuffers = std::clamp(drawBuffers, 1, 16);

    std::vector<Row> rows;
    auto add = [&](const char* name, bool compat, GLenum pname, GLuint index,
                   void (*get)(const Row&, Value*), void (*set)(const Row&, const Value&), Pin pin,
                   Value pinned) {
        if (compat && !g_compatibility) return;
        rows.push_back(Row{name, compat, pname, index, get, set, pin, pinned});
    };
    auto enable = [&](const char* name, GLenum cap, bool on, bool compat = false) {
        add(name, compat, cap, 0, getEnable, setEnable, Pin::Value, val(on ? 1.0 : 0.0));
    };
    auto store = [&](const char* name, GLenum pname, int value) {
        add(name, false, pname, 0, getInts, setPixelStore, Pin::Value, val(value));
    };
    auto transfer = [&](const char* name, GLenum pname, float value) {
        add(name, true, pname, 0, getFloats, setPixelTransfer, Pin::Value, val(value));
    };

    // First: capturing and setting the per-unit rows moves the active unit (restored last).
    add("active texture", false, GL_ACTIVE_TEXTURE, 0, getInts, setActiveTexture, Pin::Always, val(GL_TEXTURE0));
    // Bindings the plugin makes itself before use: restored only.
    add("program", false, GL_CURRENT_PROGRAM, 0, getInts, setProgram, Pin::Restore, val(0));
    add("vertex array", false, GL_VERTEX_ARRAY_BINDING, 0, getInts, setVertexArray, Pin::Restore, val(0));
    add("array buffer", false, GL_ARRAY_BUFFER_BINDING, GL_ARRAY_BUFFER, getInts, setBuffer, Pin::Restore, val(0));
    add("draw framebuffer", false, GL_DRAW_FRAMEBUFFER_BINDING, GL_DRAW_FRAMEBUFFER, getInts, setFramebuffer,
        Pin::Restore, val(0));
    add("read framebuffer", false, GL_READ_FRAMEBUFFER_BINDING, GL_READ_FRAMEBUFFER, getInts, setFramebuffer,
        Pin::Restore, val(0));
    add("viewport", false, GL_VIEWPORT, 0, getInts, setViewport, Pin::Restore, val(0));
    add("scissor box", false, GL_SCISSOR_BOX, 0, getInts, setScissor, Pin::Restore, val(0));
    for (int u = 0; u < kPinnedTextureUnits; ++u) {
        add("texture 2D binding", false, GL_TEXTURE_BINDING_2D, GLuint(u), getTexture2D, setTexture2D, Pin::Value,
            val(0));
        add("sampler binding", false, GL_SAMPLER_BINDING, GLuint(u), getSampler, setSampler, Pin::Value, val(0));
        add("texture LOD bias", true, GL_TEXTURE_LOD_BIAS, GLuint(u), getLodBias, setLodBias, Pin::Value, val(0));
    }
    // Uploads and read-backs: no buffer bound, tightly packed bytes in GL order.
    add("pixel unpack buffer", false, GL_PIXEL_UNPACK_BUFFER_BINDING, GL_PIXEL_UNPACK_BUFFER, getInts, setBuffer,
        Pin::Value, val(0));
    add("pixel pack buffer", false, GL_PIXEL_PACK_BUFFER_BINDING, GL_PIXEL_PACK_BUFFER, getInts, setBuffer,
        Pin::Value, val(0));
    store("unpack swap bytes", GL_UNPACK_SWAP_BYTES, 0);
    store("unpack lsb first", GL_UNPACK_LSB_FIRST, 0);
    store("unpack alignment", GL_UNPACK_ALIGNMENT, 4);
    store("unpack row length", GL_UNPACK_ROW_LENGTH, 0);
    store("unpack skip rows", GL_UNPACK_SKIP_ROWS, 0);
    store("unpack skip pixels", GL_UNPACK_SKIP_PIXELS, 0);
    store("unpack image height", GL_UNPACK_IMAGE_HEIGHT, 0);
    store("unpack skip images", GL_UNPACK_SKIP_IMAGES, 0);
    store("pack swap bytes", GL_PACK_SWAP_BYTES, 0);
    store("pack lsb first", GL_PACK_LSB_FIRST, 0);
    store("pack alignment", GL_PACK_ALIGNMENT, 4);
    store("pack row length", GL_PACK_ROW_LENGTH, 0);
    store("pack skip rows", GL_PACK_SKIP_ROWS, 0);
    store("pack skip pixels", GL_PACK_SKIP_PIXELS, 0);
    store("pack image height", GL_PACK_IMAGE_HEIGHT, 0);
    store("pack skip images", GL_PACK_SKIP_IMAGES, 0);
    transfer("red scale", GL_RED_SCALE, 1.0f);
    transfer("green scale", GL_GREEN_SCALE, 1.0f);
    transfer("blue scale", GL_BLUE_SCALE, 1.0f);
    transfer("alpha scale", GL_ALPHA_SCALE, 1.0f);
    transfer("depth scale", GL_DEPTH_SCALE, 1.0f);
    transfer("red bias", GL_RED_BIAS, 0.0f);
    transfer("green bias", GL_GREEN_BIAS, 0.0f);
    transfer("blue bias", GL_BLUE_BIAS, 0.0f);
    transfer("alpha bias", GL_ALPHA_BIAS, 0.0f);
    transfer("depth bias", GL_DEPTH_BIAS, 0.0f);
    transfer("map colour", GL_MAP_COLOR, 0.0f);
    transfer("map stencil", GL_MAP_STENCIL, 0.0f);
    transfer("index shift", GL_INDEX_SHIFT, 0.0f);
    transfer("index offset", GL_INDEX_OFFSET, 0.0f);
    add("clamp read colour", false, GL_CLAMP_READ_COLOR, 0, getInts, setClampColor, Pin::Value, val(GL_FIXED_ONLY));

    // Primitive assembly and rasterisation.
    enable("rasteriser discard", GL_RASTERIZER_DISCARD, false);
    enable("primitive restart", GL_PRIMITIVE_RESTART, false);
    if (version >= 43) enable("primitive restart fixed index", kPrimitiveRestartFixedIndex, false);
    add("primitive restart index", false, GL_PRIMITIVE_RESTART_INDEX, 0, getInts, setRestartIndex, Pin::Value, val(0));
    add("provoking vertex", false, GL_PROVOKING_VERTEX, 0, getInts, setProvokingVertex, Pin::Value,
        val(GL_LAST_VERTEX_CONVENTION));
    for (int i = 0; i < clipDistances; ++i) {
        add("clip distance / clip plane", false, GLenum(GL_CLIP_DISTANCE0 + i), 0, getEnable, setEnable, Pin::Value,
            val(0));
    }
    if (clipControl) {
        add("clip control", false, GL_CLIP_ORIGIN, 0, getClipControl, setClipControl, Pin::DepthMode,
            val(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE));
    }
    add("depth range", false, GL_DEPTH_RANGE, 0, getDepthRange, setDepthRange, Pin::DepthRange, val(0.0, 1.0));
    enable("depth clamp", GL_DEPTH_CLAMP, false);
    if (g_compatibility) {
        add("polygon mode front", true, GL_POLYGON_MODE, 0, getPolygonFace, setPolygonFace, Pin::Value, val(GL_FILL));
        add("polygon mode back", true, GL_POLYGON_MODE, 1, getPolygonFace, setPolygonFace, Pin::Value, val(GL_FILL));
    } else {
        add("polygon mode", false, GL_POLYGON_MODE, 0, getPolygonFace, setPolygonMode, Pin::Value, val(GL_FILL));
    }
    enable("polygon stipple", GL_POLYGON_STIPPLE, false, true);
    enable("polygon offset fill", GL_POLYGON_OFFSET_FILL, false);
    enable("polygon offset line", GL_POLYGON_OFFSET_LINE, false);
    enable("polygon offset point", GL_POLYGON_OFFSET_POINT, false);
    add("polygon offset factor / units", false, GL_POLYGON_OFFSET_FACTOR, 0, getPolygonOffset, setPolygonOffset,
        Pin::Value, val(0.0, 0.0));
    enable("polygon smooth", GL_POLYGON_SMOOTH, false);
    enable("line smooth", GL_LINE_SMOOTH, false);
    add("line width", false, GL_LINE_WIDTH, 0, getFloats, setLineWidth, Pin::Value, val(1.0));
    enable("program point size", GL_PROGRAM_POINT_SIZE, false);
    add("point size", false, GL_POINT_SIZE, 0, getFloats, setPointSize, Pin::Value, val(1.0));
    enable("cull face", GL_CULL_FACE, false);
    enable("multisample", GL_MULTISAMPLE, true);
    enable("sample coverage", GL_SAMPLE_COVERAGE, false);
    add("sample coverage value / invert", false, GL_SAMPLE_COVERAGE_VALUE, 0, getSampleCoverage, setSampleCoverage,
        Pin::Value, val(1.0, 0.0));
    enable("sample alpha to coverage", GL_SAMPLE_ALPHA_TO_COVERAGE, false);
    enable("sample alpha to one", GL_SAMPLE_ALPHA_TO_ONE, false);
    enable("sample mask", GL_SAMPLE_MASK, false);
    add("sample mask value 0", false, GL_SAMPLE_MASK_VALUE, 0, getSampleMask, setSampleMask, Pin::Value, val(-1.0));
    add("fragment shader derivative hint", false, GL_FRAGMENT_SHADER_DERIVATIVE_HINT, 0, getInts, setHint,
        Pin::Value, val(GL_DONT_CARE));
    add("clamp fragment colour", true, GL_CLAMP_FRAGMENT_COLOR, 0, getInts, setClampColor, Pin::Value,
        val(GL_FIXED_ONLY));
    add("clamp vertex colour", true, GL_CLAMP_VERTEX_COLOR, 0, getInts, setClampColor, Pin::Value, val(GL_TRUE));
    enable("texture cube map seamless", GL_TEXTURE_CUBE_MAP_SEAMLESS, false);

    // Per-fragment operations.
    enable("alpha test", GL_ALPHA_TEST, false, true);
    add("alpha func / ref", true, GL_ALPHA_TEST_FUNC, 0, getAlphaFunc, setAlphaFunc, Pin::Value, val(GL_ALWAYS, 0.0));
    enable("scissor test", GL_SCISSOR_TEST, false);
    enable("stencil test", GL_STENCIL_TEST, false);
    for (GLenum face : {GLenum(GL_FRONT), GLenum(GL_BACK)}) {
        const bool front = face == GL_FRONT;
        add(front ? "stencil func front" : "stencil func back", false, 0, face, getStencilFunc, setStencilFunc,
            Pin::Value, val(GL_ALWAYS, 0.0, -1.0));
        add(front ? "stencil op front" : "stencil op back", false, 0, face, getStencilOp, setStencilOp, Pin::Value,
            val(GL_KEEP, GL_KEEP, GL_KEEP));
        add(front ? "stencil writemask front" : "stencil writemask back", false,
            front ? GL_STENCIL_WRITEMASK : GL_STENCIL_BACK_WRITEMASK, face, getInts, setStencilMask, Pin::Value,
            val(-1.0));
    }
    enable("depth test", GL_DEPTH_TEST, false);
    add("depth func", false, GL_DEPTH_FUNC, 0, getInts, setDepthFunc, Pin::Value, val(GL_LESS));
    add("depth writemask", false, GL_DEPTH_WRITEMASK, 0, getBool, setDepthMask, Pin::Value, val(1.0));
    for (int i = 0; i < drawBuffers; ++i) {
        add("blend enable (draw buffer)", false, GL_BLEND, GLuint(i), getEnablei, setEnablei, Pin::Value, val(0));
        add("colour writemask (draw buffer)", false, GL_COLOR_WRITEMASK, GLuint(i), getColorMaski, setColorMaski,
            Pin::Value, val(1, 1, 1, 1));
    }
    add("blend func", false, GL_BLEND_SRC_RGB, 0, getBlendFunc, setBlendFunc, Pin::Value,
        val(GL_ONE, GL_ZERO, GL_ONE, GL_ZERO));
    add("blend equation", false, GL_BLEND_EQUATION_RGB, 0, getBlendEquation, setBlendEquation, Pin::Value,
        val(GL_FUNC_ADD, GL_FUNC_ADD));
    add("blend colour", false, GL_BLEND_COLOR, 0, getFloats, setBlendColor, Pin::Value, val(0));
    enable("framebuffer sRGB", GL_FRAMEBUFFER_SRGB, false);
    enable("dither", GL_DITHER, false);
    enable("colour logic op", GL_COLOR_LOGIC_OP, false);
    add("logic op", false, GL_LOGIC_OP_MODE, 0, getInts, setLogicOp, Pin::Value, val(GL_COPY));
    add("clear colour", false, GL_COLOR_CLEAR_VALUE, 0, getFloats, setClearColor, Pin::Value, val(0));
    return rows;
}

}  // namespace

const std::vector<PinnedGlState>& pinnedGlStates() {
    static const std::vector<PinnedGlState> rows = build();
    return rows;
}

PinnedGlStateCount pinnedGlStateCount() {
    PinnedGlStateCount c;
    for (const PinnedGlState& r : pinnedGlStates()) (r.compatibility ? c.compatibility : c.core) += 1;
    return c;
}

}  // namespace fx
