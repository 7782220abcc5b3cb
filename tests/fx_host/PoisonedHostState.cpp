// PoisonedHostState.h: the poisons (the read-back and the reset: HostStateReadback.cpp).
#include <cmath>
#include <cstdio>

#include "FxTestHost.h"
#include "PoisonedHostGl.h"
#include "PoisonedHostState.h"

namespace fxtest {
namespace {

namespace phg = poisoned_host_gl;

// The poisons' own objects are made the first time a poison applies, which may be after other
// poisons (all at once): what making them binds is put back, and the unpack buffer is not used.
GLuint ownBuffer() {  // bound to GL_PIXEL_PACK_BUFFER by a poison: too small for any read-back
    static GLuint b = 0;
    if (!b) {
        GLint saved = 0;
        glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &saved);
        glGenBuffers(1, &b);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, b);
        glBufferData(GL_PIXEL_PACK_BUFFER, 16, nullptr, GL_STREAM_READ);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(saved));
    }
    return b;
}

// `upload` run with GL's default unpack state, whatever earlier poisons set, which is then put
// back: no unpack buffer (a null pointer is then no data, not offset 0 of the buffer), and
// alignment 4, no skips, no swaps (Mesa 22's bitmap unpack with GL_UNPACK_SKIP_PIXELS 3 corrupts
// its heap: ASan sees it).
template <class F>
void withDefaultUnpack(F&& upload) {
    const GLenum unpack[] = {GL_PIXEL_UNPACK_BUFFER_BINDING, GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST,
                             GL_UNPACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS};
    GLint saved[7] = {};
    for (int i = 0; i < 7; ++i) glGetIntegerv(unpack[i], &saved[i]);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    for (int i = 1; i < 7; ++i) glPixelStorei(unpack[i], unpack[i] == GL_UNPACK_ALIGNMENT ? 4 : 0);
    upload();
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, GLuint(saved[0]));
    for (int i = 1; i < 7; ++i) glPixelStorei(unpack[i], saved[i]);
}

GLuint ownTexture() {  // 4 x 4 RGBA8, contents undefined
    static GLuint t = 0;
    if (!t) {
        GLint texture = 0;
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
        glGenTextures(1, &t);
        glBindTexture(GL_TEXTURE_2D, t);
        withDefaultUnpack([] { glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr); });
        glBindTexture(GL_TEXTURE_2D, GLuint(texture));
    }
    return t;
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
    for (const auto& s : phg::kPixelStores) {
        const GLenum e = s.second;
        const bool isAlignment = e == GL_UNPACK_ALIGNMENT || e == GL_PACK_ALIGNMENT;
        const bool isFlag = e == GL_UNPACK_SWAP_BYTES || e == GL_UNPACK_LSB_FIRST || e == GL_PACK_SWAP_BYTES ||
                            e == GL_PACK_LSB_FIRST;
        add(s.first, [e, isAlignment, isFlag] { glPixelStorei(e, isAlignment ? 8 : isFlag ? 1 : 3); });
    }
    add("clamp read colour", [] { glClampColor(GL_CLAMP_READ_COLOR, GL_TRUE); });
    add("rasteriser discard", [] { glEnable(GL_RASTERIZER_DISCARD); });
    enable("primitive restart", GL_PRIMITIVE_RESTART);
    if (phg::glVersion() >= 43) enable("primitive restart fixed index", phg::kPrimitiveRestartFixedIndex);
    add("primitive restart index", [] { glPrimitiveRestartIndex(2); });
    add("provoking vertex", [] { glProvokingVertex(GL_FIRST_VERTEX_CONVENTION); });
    GLint clipDistances = 0;
    glGetIntegerv(GL_MAX_CLIP_DISTANCES, &clipDistances);
    for (GLint i = 0; i < clipDistances; ++i) {
        add("clip distance " + std::to_string(i), [i] { glEnable(GLenum(GL_CLIP_DISTANCE0 + i)); });
    }
    if (phg::compat().clipControl) {
        add("clip control", [] { phg::compat().clipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE); });
    }
    add("depth range", [] { glDepthRange(0.25, 0.75); });
    if (phg::glVersion() >= 43) {
        // What the tiled path binds: ranges of a host buffer on storage bindings 1, 4 (its
        // sort's last) and 5 (lit smoke's shapes), the generic binding, a host texture on image unit 0.
        add("shader storage buffers", [] {
            glBindBufferRange(phg::kShaderStorageBuffer, 1, ownBuffer(), 0, 16);
            glBindBufferBase(phg::kShaderStorageBuffer, 3, ownBuffer());
            glBindBufferRange(phg::kShaderStorageBuffer, 4, ownBuffer(), 0, 8);
            glBindBufferRange(phg::kShaderStorageBuffer, 5, ownBuffer(), 0, 16);
            glBindBuffer(phg::kShaderStorageBuffer, ownBuffer());
        });
        add("image unit 0", [] { phg::compat().bindImageTexture(0, ownTexture(), 0, GL_FALSE, 0, phg::kReadWrite, phg::kRgba8); });
    }
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
    add("alpha test (GREATER 0.5)", [] { glEnable(phg::kAlphaTest); phg::compat().alphaFunc(GL_GREATER, 0.5f); }, true);
    add("alpha func / ref", [] { phg::compat().alphaFunc(GL_LESS, 0.25f); }, true);
    add("polygon stipple (empty pattern)", [] {
        static const GLubyte empty[128] = {};
        withDefaultUnpack([] { phg::compat().polygonStipple(empty); });
        glEnable(phg::kPolygonStipple);
    }, true);
    add("user clip plane 0 (clips everything)", [] {
        const GLdouble plane[4] = {0.0, 0.0, 0.0, -1.0};
        phg::compat().clipPlane(phg::kClipPlane0, plane);
        glEnable(phg::kClipPlane0);
    }, true);
    add("clamp fragment colour", [] { glClampColor(phg::kClampFragmentColor, GL_TRUE); }, true);
    add("clamp vertex colour", [] { glClampColor(phg::kClampVertexColor, GL_FALSE); }, true);
    const std::pair<const char*, GLenum> transfers[] = {
        {"red scale", phg::kRedScale},     {"green scale", phg::kGreenScale}, {"blue scale", phg::kBlueScale},
        {"alpha scale", phg::kAlphaScale}, {"depth scale", phg::kDepthScale}, {"red bias", phg::kRedBias},
        {"green bias", phg::kGreenBias},   {"blue bias", phg::kBlueBias},     {"alpha bias", phg::kAlphaBias},
        {"depth bias", phg::kDepthBias},   {"map colour", phg::kMapColor},    {"map stencil", phg::kMapStencil},
        {"index shift", phg::kIndexShift}, {"index offset", phg::kIndexOffset}};
    for (const auto& t : transfers) {
        const GLenum e = t.second;
        const bool flag = e == phg::kMapColor || e == phg::kMapStencil;
        add(t.first, [e, flag] { phg::compat().pixelTransferf(e, flag ? 1.0f : 0.25f); }, true);
    }
    for (int u = 0; u < phg::kUnits; ++u) {
        add("texture LOD bias unit " + std::to_string(u), [u] {
            glActiveTexture(GLenum(GL_TEXTURE0 + u));
            phg::compat().texEnvf(phg::kTextureFilterControl, phg::kTextureLodBias, 3.0f);
        }, true);
    }
    return p;
}

}  // namespace

const std::vector<HostPoison>& hostPoisons() {
    static const std::vector<HostPoison> p = buildPoisons();
    return p;
}

}  // namespace fxtest
