// PoisonedHostState.h: the poisons, the read-back and the reset. The tests' glad is 3.3 core:
// compatibility-only entry points and enums are fetched and defined here by hand.
#include <glad/gl.h>

#include <cmath>
#include <cstdio>

#include "FxTestHost.h"
#include "PoisonedHostState.h"

namespace fxtest {
namespace {

// Compatibility-profile enums (not in the core header).
constexpr GLenum kAlphaTest = 0x0BC0, kAlphaTestFunc = 0x0BC1, kAlphaTestRef = 0x0BC2;
constexpr GLenum kPolygonStipple = 0x0B42, kClipPlane0 = 0x3000;
constexpr GLenum kClampVertexColor = 0x891A, kClampFragmentColor = 0x891B;
constexpr GLenum kMapColor = 0x0D10, kMapStencil = 0x0D11, kIndexShift = 0x0D12, kIndexOffset = 0x0D13;
constexpr GLenum kRedScale = 0x0D14, kRedBias = 0x0D15, kGreenScale = 0x0D18, kGreenBias = 0x0D19;
constexpr GLenum kBlueScale = 0x0D1A, kBlueBias = 0x0D1B, kAlphaScale = 0x0D1C, kAlphaBias = 0x0D1D;
constexpr GLenum kDepthScale = 0x0D1E, kDepthBias = 0x0D1F;
constexpr GLenum kTextureFilterControl = 0x8500, kTextureLodBias = 0x8501;
constexpr GLenum kPrimitiveRestartFixedIndex = 0x8D69;
constexpr int kUnits = 6;  // GlStateGuard::kTextureUnits

struct Compat {
    void (*alphaFunc)(GLenum, GLfloat) = nullptr;
    void (*pixelTransferf)(GLenum, GLfloat) = nullptr;
    void (*texEnvf)(GLenum, GLenum, GLfloat) = nullptr;
    void (*getTexEnvfv)(GLenum, GLenum, GLfloat*) = nullptr;
    void (*clipPlane)(GLenum, const GLdouble*) = nullptr;
    void (*polygonStipple)(const GLubyte*) = nullptr;
    void (*clipControl)(GLenum, GLenum) = nullptr;
};

template <typename F>
void load(F* fn, const char* name) {
    *fn = reinterpret_cast<F>(osMesaProcAddress()(name));
}

const Compat& compat() {
    static const Compat c = [] {
        Compat k;
        load(&k.alphaFunc, "glAlphaFunc");
        load(&k.pixelTransferf, "glPixelTransferf");
        load(&k.texEnvf, "glTexEnvf");
        load(&k.getTexEnvfv, "glGetTexEnvfv");
        load(&k.clipPlane, "glClipPlane");
        load(&k.polygonStipple, "glPolygonStipple");
        load(&k.clipControl, "glClipControl");
        return k;
    }();
    return c;
}

int glVersion() {
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    return major * 10 + minor;
}

GLuint ownBuffer() {  // bound to GL_PIXEL_PACK_BUFFER by a poison: too small for any read-back
    static GLuint b = 0;
    if (!b) {
        glGenBuffers(1, &b);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, b);
        glBufferData(GL_PIXEL_PACK_BUFFER, 16, nullptr, GL_STREAM_READ);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    }
    return b;
}

std::vector<HostPoison> buildPoisons() {
    const bool compatProfile = osMesaCompatibilityProfile();
    std::vector<HostPoison> p;
    auto add = [&](std::string name, std::function<void()> fn, bool compatOnly = false) {
        if (!compatOnly || compatProfile) p.push_back(HostPoison{std::move(name), compatOnly, std::move(fn)});
    };
    auto enable = [&](const char* name, GLenum cap, bool compatOnly = false) {
        add(name, [cap] { glEnable(cap); }, compatOnly);
    };
    // Bindings: the fx_host's dirty host (program, VAO with an element buffer, textures on units
    // 0-7, samplers, framebuffers, a too-small unpack buffer...) and the rest one at a time.
    add("dirty bindings (applyDirtyHostState)", applyDirtyHostState);
    add("active texture", [] { glActiveTexture(GL_TEXTURE4); });
    add("pixel pack buffer", [] { glBindBuffer(GL_PIXEL_PACK_BUFFER, ownBuffer()); });
    const std::pair<const char*, GLenum> stores[] = {
        {"unpack swap bytes", GL_UNPACK_SWAP_BYTES}, {"unpack lsb first", GL_UNPACK_LSB_FIRST},
        {"unpack alignment", GL_UNPACK_ALIGNMENT},   {"unpack row length", GL_UNPACK_ROW_LENGTH},
        {"unpack skip rows", GL_UNPACK_SKIP_ROWS},   {"unpack skip pixels", GL_UNPACK_SKIP_PIXELS},
        {"unpack image height", GL_UNPACK_IMAGE_HEIGHT}, {"unpack skip images", GL_UNPACK_SKIP_IMAGES},
        {"pack swap bytes", GL_PACK_SWAP_BYTES},     {"pack lsb first", GL_PACK_LSB_FIRST},
        {"pack alignment", GL_PACK_ALIGNMENT},       {"pack row length", GL_PACK_ROW_LENGTH},
        {"pack skip rows", GL_PACK_SKIP_ROWS},       {"pack skip pixels", GL_PACK_SKIP_PIXELS},
        {"pack image height", GL_PACK_IMAGE_HEIGHT}, {"pack skip images", GL_PACK_SKIP_IMAGES}};
    for (const auto& s : stores) {
        const GLenum e = s.second;
        const bool isAlignment = e == GL_UNPACK_ALIGNMENT || e == GL_PACK_ALIGNMENT;
        const bool isFlag = e == GL_UNPACK_SWAP_BYTES || e == GL_UNPACK_LSB_FIRST || e == GL_PACK_SWAP_BYTES ||
                            e == GL_PACK_LSB_FIRST;
        add(s.first, [e, isAlignment, isFlag] { glPixelStorei(e, isAlignment ? 8 : isFlag ? 1 : 3); });
    }
    add("clamp read colour", [] { glClampColor(GL_CLAMP_READ_COLOR, GL_TRUE); });
    add("rasteriser discard", [] { glEnable(GL_RASTERIZER_DISCARD); });
    enable("primitive restart", GL_PRIMITIVE_RESTART);
    if (glVersion() >= 43) enable("primitive restart fixed index", kPrimitiveRestartFixedIndex);
    add("primitive restart index", [] { glPrimitiveRestartIndex(2); });
    add("provoking vertex", [] { glProvokingVertex(GL_FIRST_VERTEX_CONVENTION); });
    GLint clipDistances = 0;
    glGetIntegerv(GL_MAX_CLIP_DISTANCES, &clipDistances);
    for (GLint i = 0; i < clipDistances; ++i) {
        add("clip distance " + std::to_string(i), [i] { glEnable(GLenum(GL_CLIP_DISTANCE0 + i)); });
    }
    if (compat().clipControl) {
        add("clip control", [] { compat().clipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE); });
    }
    add("depth range", [] { glDepthRange(0.25, 0.75); });
    enable("depth clamp", GL_DEPTH_CLAMP);
    if (compatProfile) {
        add("polygon mode front", [] { glPolygonMode(GL_FRONT, GL_LINE); }, true);
        add("polygon mode back", [] { glPolygonMode(GL_BACK, GL_POINT); }, true);
    } else {
        add("polygon mode", [] { glPolygonMode(GL_FRONT_AND_BACK, GL_LINE); });
    }
    add("polygon offset fill (units -1e5)", [] { glEnable(GL_POLYGON_OFFSET_FILL); glPolygonOffset(0.0f, -1e5f); });
    add("polygon offset line", [] { glEnable(GL_POLYGON_OFFSET_LINE); glPolygonOffset(0.0f, -1e5f); });
    add("polygon offset point", [] { glEnable(GL_POLYGON_OFFSET_POINT); glPolygonOffset(0.0f, -1e5f); });
    add("polygon offset factor / units", [] { glPolygonOffset(4.0f, 1e5f); });
    enable("polygon smooth", GL_POLYGON_SMOOTH);
    enable("line smooth", GL_LINE_SMOOTH);
    add("line width", [] { glLineWidth(3.0f); });
    enable("program point size", GL_PROGRAM_POINT_SIZE);
    add("point size", [] { glPointSize(5.0f); });
    add("cull face (FRONT_AND_BACK)", [] { glEnable(GL_CULL_FACE); glCullFace(GL_FRONT_AND_BACK); });
    add("multisample", [] { glDisable(GL_MULTISAMPLE); });
    add("sample coverage (0, invert)", [] { glEnable(GL_SAMPLE_COVERAGE); glSampleCoverage(0.0f, GL_TRUE); });
    add("sample coverage value / invert", [] { glSampleCoverage(0.25f, GL_TRUE); });
    enable("sample alpha to coverage", GL_SAMPLE_ALPHA_TO_COVERAGE);
    enable("sample alpha to one", GL_SAMPLE_ALPHA_TO_ONE);
    add("sample mask (0)", [] { glEnable(GL_SAMPLE_MASK); glSampleMaski(0, 0u); });
    add("sample mask value 0", [] { glSampleMaski(0, 0x5u); });
    add("fragment shader derivative hint", [] { glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_FASTEST); });
    enable("texture cube map seamless", GL_TEXTURE_CUBE_MAP_SEAMLESS);
    add("scissor test", [] { glEnable(GL_SCISSOR_TEST); glScissor(3, 5, 7, 11); });
    add("scissor box", [] { glScissor(3, 5, 7, 11); });
    add("stencil test (NEVER)", [] { glEnable(GL_STENCIL_TEST); glStencilFunc(GL_NEVER, 1, 0xFFu); });
    add("stencil func front", [] { glStencilFuncSeparate(GL_FRONT, GL_NEVER, 1, 0x0Fu); });
    add("stencil func back", [] { glStencilFuncSeparate(GL_BACK, GL_LESS, 2, 0xF0u); });
    add("stencil op front", [] { glStencilOpSeparate(GL_FRONT, GL_REPLACE, GL_INCR, GL_INVERT); });
    add("stencil op back", [] { glStencilOpSeparate(GL_BACK, GL_ZERO, GL_DECR, GL_REPLACE); });
    add("stencil writemask front", [] { glStencilMaskSeparate(GL_FRONT, 0x0Fu); });
    add("stencil writemask back", [] { glStencilMaskSeparate(GL_BACK, 0xF0u); });
    add("depth test (GREATER)", [] { glEnable(GL_DEPTH_TEST); glDepthFunc(GL_GREATER); });
    add("depth func", [] { glDepthFunc(GL_NEVER); });
    add("depth writemask", [] { glDepthMask(GL_FALSE); });
    GLint drawBuffers = 0;
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &drawBuffers);
    for (GLint i = 0; i < drawBuffers; ++i) {
        add("blend enable " + std::to_string(i) + " (ZERO, SRC_COLOR)", [i] {
            glEnablei(GL_BLEND, GLuint(i));
            glBlendFunc(GL_ZERO, GL_SRC_COLOR);
        });
        add("colour writemask " + std::to_string(i), [i] { glColorMaski(GLuint(i), GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE); });
    }
    add("blend func", [] { glBlendFuncSeparate(GL_SRC_ALPHA, GL_DST_COLOR, GL_ONE_MINUS_DST_ALPHA, GL_SRC_COLOR); });
    add("blend equation", [] { glBlendEquationSeparate(GL_FUNC_REVERSE_SUBTRACT, GL_MAX); });
    add("blend colour", [] { glBlendColor(0.1f, 0.2f, 0.3f, 0.4f); });
    enable("framebuffer sRGB", GL_FRAMEBUFFER_SRGB);
    add("dither", [] { glDisable(GL_DITHER); });
    add("colour logic op (XOR)", [] { glEnable(GL_COLOR_LOGIC_OP); glLogicOp(GL_XOR); });
    add("logic op", [] { glLogicOp(GL_INVERT); });
    add("clear colour", [] { glClearColor(0.25f, 0.5f, 0.75f, 0.125f); });
    add("viewport", [] { glViewport(1, 2, 33, 44); });

    // Compatibility profile only.
    add("alpha test (GREATER 0.5)", [] { glEnable(kAlphaTest); compat().alphaFunc(GL_GREATER, 0.5f); }, true);
    add("alpha func / ref", [] { compat().alphaFunc(GL_LESS, 0.25f); }, true);
    add("polygon stipple (empty pattern)", [] {
        // The pattern is unpacked with GL's default unpack state, whatever earlier poisons set
        // (Mesa 22's bitmap unpack with GL_UNPACK_SKIP_PIXELS 3 corrupts its heap: ASan sees it).
        static const GLubyte empty[128] = {};
        const GLenum unpack[] = {GL_PIXEL_UNPACK_BUFFER_BINDING, GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST,
                                 GL_UNPACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS};
        GLint saved[7] = {};
        for (int i = 0; i < 7; ++i) glGetIntegerv(unpack[i], &saved[i]);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        for (int i = 1; i < 7; ++i) glPixelStorei(unpack[i], unpack[i] == GL_UNPACK_ALIGNMENT ? 4 : 0);
        compat().polygonStipple(empty);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, GLuint(saved[0]));
        for (int i = 1; i < 7; ++i) glPixelStorei(unpack[i], saved[i]);
        glEnable(kPolygonStipple);
    }, true);
    add("user clip plane 0 (clips everything)", [] {
        const GLdouble plane[4] = {0.0, 0.0, 0.0, -1.0};
        compat().clipPlane(kClipPlane0, plane);
        glEnable(kClipPlane0);
    }, true);
    add("clamp fragment colour", [] { glClampColor(kClampFragmentColor, GL_TRUE); }, true);
    add("clamp vertex colour", [] { glClampColor(kClampVertexColor, GL_FALSE); }, true);
    const std::pair<const char*, GLenum> transfers[] = {
        {"red scale", kRedScale},     {"green scale", kGreenScale}, {"blue scale", kBlueScale},
        {"alpha scale", kAlphaScale}, {"depth scale", kDepthScale}, {"red bias", kRedBias},
        {"green bias", kGreenBias},   {"blue bias", kBlueBias},     {"alpha bias", kAlphaBias},
        {"depth bias", kDepthBias},   {"map colour", kMapColor},    {"map stencil", kMapStencil},
        {"index shift", kIndexShift}, {"index offset", kIndexOffset}};
    for (const auto& t : transfers) {
        const GLenum e = t.second;
        const bool flag = e == kMapColor || e == kMapStencil;
        add(t.first, [e, flag] { compat().pixelTransferf(e, flag ? 1.0f : 0.25f); }, true);
    }
    for (int u = 0; u < kUnits; ++u) {
        add("texture LOD bias unit " + std::to_string(u), [u] {
            glActiveTexture(GLenum(GL_TEXTURE0 + u));
            compat().texEnvf(kTextureFilterControl, kTextureLodBias, 3.0f);
        }, true);
    }
    return p;
}

}  // namespace

const std::vector<HostPoison>& hostPoisons() {
    static const std::vector<HostPoison> p = buildPoisons();
    return p;
}

HostStateReadback readHostState() {
    HostStateReadback r;
    auto ints = [&](const char* name, GLenum e, int n) {
        GLint v[4] = {};
        glGetIntegerv(e, v);
        r[name].assign(v, v + n);
    };
    auto floats = [&](const char* name, GLenum e, int n) {
        GLfloat v[4] = {};
        glGetFloatv(e, v);
        r[name].assign(v, v + n);
    };
    const GLenum enables[] = {GL_RASTERIZER_DISCARD, GL_PRIMITIVE_RESTART, GL_DEPTH_CLAMP, GL_POLYGON_OFFSET_FILL,
                              GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT, GL_POLYGON_SMOOTH, GL_LINE_SMOOTH,
                              GL_PROGRAM_POINT_SIZE, GL_CULL_FACE, GL_MULTISAMPLE, GL_SAMPLE_COVERAGE,
                              GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_MASK,
                              GL_TEXTURE_CUBE_MAP_SEAMLESS, GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_DEPTH_TEST,
                              GL_FRAMEBUFFER_SRGB, GL_DITHER, GL_COLOR_LOGIC_OP};
    for (GLenum e : enables) r["enable 0x" + std::to_string(e)] = {double(glIsEnabled(e))};
    if (glVersion() >= 43) r["enable fixed index"] = {double(glIsEnabled(kPrimitiveRestartFixedIndex))};
    GLint clipDistances = 0, drawBuffers = 0;
    glGetIntegerv(GL_MAX_CLIP_DISTANCES, &clipDistances);
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &drawBuffers);
    for (GLint i = 0; i < clipDistances; ++i) {
        r["clip distance " + std::to_string(i)] = {double(glIsEnabled(GLenum(GL_CLIP_DISTANCE0 + i)))};
    }
    for (GLint i = 0; i < drawBuffers; ++i) {
        GLboolean m[4] = {};
        glGetBooleani_v(GL_COLOR_WRITEMASK, GLuint(i), m);
        r["colour writemask " + std::to_string(i)] = {double(m[0]), double(m[1]), double(m[2]), double(m[3])};
        r["blend enable " + std::to_string(i)] = {double(glIsEnabledi(GL_BLEND, GLuint(i)))};
    }
    const std::pair<const char*, GLenum> singles[] = {
        {"active texture", GL_ACTIVE_TEXTURE}, {"program", GL_CURRENT_PROGRAM}, {"vertex array", GL_VERTEX_ARRAY_BINDING},
        {"array buffer", GL_ARRAY_BUFFER_BINDING}, {"draw framebuffer", GL_DRAW_FRAMEBUFFER_BINDING},
        {"read framebuffer", GL_READ_FRAMEBUFFER_BINDING}, {"pack buffer", GL_PIXEL_PACK_BUFFER_BINDING},
        {"unpack buffer", GL_PIXEL_UNPACK_BUFFER_BINDING}, {"unpack swap bytes", GL_UNPACK_SWAP_BYTES},
        {"unpack lsb first", GL_UNPACK_LSB_FIRST}, {"unpack alignment", GL_UNPACK_ALIGNMENT},
        {"unpack row length", GL_UNPACK_ROW_LENGTH}, {"unpack skip rows", GL_UNPACK_SKIP_ROWS},
        {"unpack skip pixels", GL_UNPACK_SKIP_PIXELS}, {"unpack image height", GL_UNPACK_IMAGE_HEIGHT},
        {"unpack skip images", GL_UNPACK_SKIP_IMAGES}, {"pack swap bytes", GL_PACK_SWAP_BYTES},
        {"pack lsb first", GL_PACK_LSB_FIRST}, {"pack alignment", GL_PACK_ALIGNMENT},
        {"pack row length", GL_PACK_ROW_LENGTH}, {"pack skip rows", GL_PACK_SKIP_ROWS},
        {"pack skip pixels", GL_PACK_SKIP_PIXELS}, {"pack image height", GL_PACK_IMAGE_HEIGHT},
        {"pack skip images", GL_PACK_SKIP_IMAGES}, {"clamp read colour", GL_CLAMP_READ_COLOR},
        {"primitive restart index", GL_PRIMITIVE_RESTART_INDEX}, {"provoking vertex", GL_PROVOKING_VERTEX},
        {"cull face mode", GL_CULL_FACE_MODE}, {"front face", GL_FRONT_FACE},
        {"derivative hint", GL_FRAGMENT_SHADER_DERIVATIVE_HINT}, {"stencil func", GL_STENCIL_FUNC},
        {"stencil ref", GL_STENCIL_REF}, {"stencil value mask", GL_STENCIL_VALUE_MASK},
        {"stencil fail", GL_STENCIL_FAIL}, {"stencil zfail", GL_STENCIL_PASS_DEPTH_FAIL},
        {"stencil zpass", GL_STENCIL_PASS_DEPTH_PASS}, {"stencil writemask", GL_STENCIL_WRITEMASK},
        {"stencil back func", GL_STENCIL_BACK_FUNC}, {"stencil back ref", GL_STENCIL_BACK_REF},
        {"stencil back value mask", GL_STENCIL_BACK_VALUE_MASK}, {"stencil back fail", GL_STENCIL_BACK_FAIL},
        {"stencil back zfail", GL_STENCIL_BACK_PASS_DEPTH_FAIL}, {"stencil back zpass", GL_STENCIL_BACK_PASS_DEPTH_PASS},
        {"stencil back writemask", GL_STENCIL_BACK_WRITEMASK}, {"depth func", GL_DEPTH_FUNC},
        {"depth writemask", GL_DEPTH_WRITEMASK}, {"logic op", GL_LOGIC_OP_MODE},
        {"blend src rgb", GL_BLEND_SRC_RGB}, {"blend dst rgb", GL_BLEND_DST_RGB},
        {"blend src alpha", GL_BLEND_SRC_ALPHA}, {"blend dst alpha", GL_BLEND_DST_ALPHA},
        {"blend eq rgb", GL_BLEND_EQUATION_RGB}, {"blend eq alpha", GL_BLEND_EQUATION_ALPHA}};
    for (const auto& s : singles) ints(s.first, s.second, 1);
    ints("polygon mode", GL_POLYGON_MODE, 2);
    ints("viewport", GL_VIEWPORT, 4);
    ints("scissor box", GL_SCISSOR_BOX, 4);
    floats("polygon offset factor", GL_POLYGON_OFFSET_FACTOR, 1);
    floats("polygon offset units", GL_POLYGON_OFFSET_UNITS, 1);
    floats("line width", GL_LINE_WIDTH, 1);
    floats("point size", GL_POINT_SIZE, 1);
    floats("sample coverage value", GL_SAMPLE_COVERAGE_VALUE, 1);
    ints("sample coverage invert", GL_SAMPLE_COVERAGE_INVERT, 1);
    floats("depth range", GL_DEPTH_RANGE, 2);
    floats("blend colour", GL_BLEND_COLOR, 4);
    floats("clear colour", GL_COLOR_CLEAR_VALUE, 4);
    GLint mask = 0;
    glGetIntegeri_v(GL_SAMPLE_MASK_VALUE, 0, &mask);
    r["sample mask value 0"] = {double(mask)};
    if (compat().clipControl) {
        ints("clip origin", GL_CLIP_ORIGIN, 1);
        ints("clip depth mode", GL_CLIP_DEPTH_MODE, 1);
    }
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    const bool compatProfile = osMesaCompatibilityProfile();
    for (int u = 0; u < 8; ++u) {
        glActiveTexture(GLenum(GL_TEXTURE0 + u));
        ints(("texture unit " + std::to_string(u)).c_str(), GL_TEXTURE_BINDING_2D, 1);
        ints(("sampler unit " + std::to_string(u)).c_str(), GL_SAMPLER_BINDING, 1);
        if (compatProfile && u < kUnits) {
            GLfloat bias = 0.0f;
            compat().getTexEnvfv(kTextureFilterControl, kTextureLodBias, &bias);
            r["LOD bias unit " + std::to_string(u)] = {double(bias)};
        }
    }
    glActiveTexture(GLenum(active));
    if (compatProfile) {
        r["alpha test"] = {double(glIsEnabled(kAlphaTest))};
        r["polygon stipple"] = {double(glIsEnabled(kPolygonStipple))};
        ints("alpha func", kAlphaTestFunc, 1);
        floats("alpha ref", kAlphaTestRef, 1);
        ints("clamp fragment colour", kClampFragmentColor, 1);
        ints("clamp vertex colour", kClampVertexColor, 1);
        const GLenum transfers[] = {kRedScale,  kGreenScale, kBlueScale, kAlphaScale, kDepthScale,
                                    kRedBias,   kGreenBias,  kBlueBias,  kAlphaBias,  kDepthBias,
                                    kMapColor,  kMapStencil, kIndexShift, kIndexOffset};
        for (GLenum e : transfers) floats(("pixel transfer 0x" + std::to_string(e)).c_str(), e, 1);
    }
    return r;
}

std::string diffHostState(const HostStateReadback& before, const HostStateReadback& after) {
    std::string out;
    for (const auto& b : before) {
        const auto a = after.find(b.first);
        if (a == after.end() || a->second == b.second) continue;
        out += b.first + ":";
        for (double v : b.second) out += " " + std::to_string(v);
        out += " ->";
        for (double v : a->second) out += " " + std::to_string(v);
        out += "\n";
    }
    return out;
}

void resetHostState() {
    applyDefaultHostState();
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    for (GLenum e : {GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS,
                     GL_UNPACK_SKIP_PIXELS, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES, GL_PACK_SWAP_BYTES,
                     GL_PACK_LSB_FIRST, GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS,
                     GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_IMAGES}) {
        glPixelStorei(e, 0);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glClampColor(GL_CLAMP_READ_COLOR, GL_FIXED_ONLY);
    for (GLenum e : {GL_RASTERIZER_DISCARD, GL_PRIMITIVE_RESTART, GL_DEPTH_CLAMP, GL_POLYGON_OFFSET_FILL,
                     GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT, GL_POLYGON_SMOOTH, GL_LINE_SMOOTH,
                     GL_PROGRAM_POINT_SIZE, GL_SAMPLE_COVERAGE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE,
                     GL_SAMPLE_MASK, GL_TEXTURE_CUBE_MAP_SEAMLESS, GL_FRAMEBUFFER_SRGB, GL_COLOR_LOGIC_OP}) {
        glDisable(e);
    }
    if (glVersion() >= 43) glDisable(kPrimitiveRestartFixedIndex);
    glEnable(GL_MULTISAMPLE);
    glEnable(GL_DITHER);
    glPrimitiveRestartIndex(0);
    glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
    GLint clipDistances = 0, drawBuffers = 0;
    glGetIntegerv(GL_MAX_CLIP_DISTANCES, &clipDistances);
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &drawBuffers);
    for (GLint i = 0; i < clipDistances; ++i) glDisable(GLenum(GL_CLIP_DISTANCE0 + i));
    for (GLint i = 0; i < drawBuffers; ++i) {
        glDisablei(GL_BLEND, GLuint(i));
        glColorMaski(GLuint(i), GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
    if (compat().clipControl) compat().clipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glDepthRange(0.0, 1.0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glPolygonOffset(0.0f, 0.0f);
    glLineWidth(1.0f);
    glPointSize(1.0f);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glSampleCoverage(1.0f, GL_FALSE);
    glSampleMaski(0, ~0u);
    glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_DONT_CARE);
    glStencilFunc(GL_ALWAYS, 0, ~0u);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilMask(~0u);
    glDepthMask(GL_TRUE);
    glBlendColor(0.0f, 0.0f, 0.0f, 0.0f);
    glLogicOp(GL_COPY);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    if (osMesaCompatibilityProfile()) {
        glDisable(kAlphaTest);
        compat().alphaFunc(GL_ALWAYS, 0.0f);
        glDisable(kPolygonStipple);
        glDisable(kClipPlane0);
        glClampColor(kClampFragmentColor, GL_FIXED_ONLY);
        glClampColor(kClampVertexColor, GL_TRUE);
        for (GLenum e : {kRedScale, kGreenScale, kBlueScale, kAlphaScale, kDepthScale}) compat().pixelTransferf(e, 1.0f);
        for (GLenum e : {kRedBias, kGreenBias, kBlueBias, kAlphaBias, kDepthBias, kMapColor, kMapStencil, kIndexShift,
                         kIndexOffset}) {
            compat().pixelTransferf(e, 0.0f);
        }
        for (int u = 0; u < kUnits; ++u) {
            glActiveTexture(GLenum(GL_TEXTURE0 + u));
            compat().texEnvf(kTextureFilterControl, kTextureLodBias, 0.0f);
        }
        glActiveTexture(GL_TEXTURE0);
    }
}

}  // namespace fxtest
