// The host's own z-buffer as the plugin's linear depth (fx_plugin/render/DepthLinearizer.h,
// DepthMapping.h). Per convention (GL and D3D-style projections, ZERO_TO_ONE, reversed-Z, infinite
// far plane, orthographic, non-default depth ranges) planes at known distances are drawn into a
// depth texture of each format (16, 24, 32F, 24_8) and into the default framebuffer; the
// linearised depth is compared per pixel with the distance ray-cast through the pixel centre.
//
// Tolerance per pixel, derived (DepthMapping.h): |dt/dd|(t) * e_d + t * e_shader, where
//   e_d, the window-depth error: one quantum 1/(2^b - 1) for a b-bit unorm buffer (half for the
//       rounding, half for the rasteriser's float arithmetic before it), 4 ulp of d for 32F; plus
//       2 ulp of 1 (2^-23) where the window transform adds an offset (GL clip control or a depth
//       range): the rasteriser computes n + (f - n) (ndc + 1) / 2 in float, so a window depth near
//       0 that comes out of 1 - (...) (glDepthRange(1, 0)) carries an absolute error, not a relative one;
//   e_shader, the float evaluation of (A + B d) / (C + D d): 4 ulp per operation, scaled by the
//       cancellation (|A| + |B d|) / |A + B d| and (|C| + |D d|) / |C + D d|.
// The test prints the largest error measured against that bound for every case.
#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "FxTestHost.h"
#include "../../fx_plugin/render/DepthMapping.h"
#include "../../fx_plugin/render/GlStateGuard.h"
#include "../../fx_plugin/render/DepthLinearizer.h"

namespace fxtest {
namespace host_depth {  // named: the fx_host tests build as unity batches

constexpr int kW = 96, kH = 32, kStrip = 12;
constexpr float kNear = 0.5f, kFar = 200.0f;
constexpr float kDistances[6] = {1.0f, 2.5f, 6.0f, 15.0f, 40.0f, 120.0f};
constexpr float kTiltNear = 3.0f, kTiltFar = 30.0f;  // strip 6: a plane tilted from 3 m (bottom) to 30 m (top)
// Strip 7: nothing drawn.

struct Convention {
    const char* name;
    glm::mat4 proj;
    fx::DepthMapping mapping;
    fx::DepthConvention expected;
};

glm::mat4 infiniteReversedZeroToOne(float fovY, float aspect, float n) {
    // ndc = n / t: near at 1, infinity at 0 (the usual reversed-Z with a float buffer).
    const float f = 1.0f / std::tan(fovY / 2.0f);
    glm::mat4 p(0.0f);
    p[0][0] = f / aspect;
    p[1][1] = f;
    p[2][3] = -1.0f;
    p[3][2] = n;
    return p;
}

std::vector<Convention> conventions() {
    const float fov = glm::radians(60.0f), aspect = float(kW) / float(kH);
    const float oh = 8.0f, ow = oh * aspect;
    fx::DepthMapping gl, zo, range, flipped;
    zo.clipZeroToOne = true;
    range.rangeNear = 0.2f;
    range.rangeFar = 0.9f;
    flipped.rangeNear = 1.0f;
    flipped.rangeFar = 0.0f;
    using C = fx::DepthConvention;
    return {
        {"gl_perspective", glm::perspectiveRH_NO(fov, aspect, kNear, kFar), gl, C::Standard},
        // Irrlicht 1.8: a D3D-style [0, 1] matrix drawn with GL's clip control: window z in [0.5, 1].
        {"d3d_perspective_gl_clip", glm::perspectiveRH_ZO(fov, aspect, kNear, kFar), gl, C::Standard},
        {"d3d_perspective_zero_to_one", glm::perspectiveRH_ZO(fov, aspect, kNear, kFar), zo, C::Standard},
        {"reversed_zero_to_one", glm::perspectiveRH_ZO(fov, aspect, kFar, kNear), zo, C::ReversedZ},
        {"infinite_far_gl", glm::infinitePerspectiveRH(fov, aspect, kNear), gl, C::Standard},
        {"infinite_reversed_zero_to_one", infiniteReversedZeroToOne(fov, aspect, kNear), zo, C::ReversedZ},
        {"ortho_gl", glm::orthoRH_NO(-ow, ow, -oh, oh, kNear, kFar), gl, C::Standard},
        {"ortho_zero_to_one", glm::orthoRH_ZO(-ow, ow, -oh, oh, kNear, kFar), zo, C::Standard},
        {"gl_perspective_range_0.2_0.9", glm::perspectiveRH_NO(fov, aspect, kNear, kFar), range, C::Standard},
        {"gl_perspective_range_1_0", glm::perspectiveRH_NO(fov, aspect, kNear, kFar), flipped, C::ReversedZ},
    };
}

struct Format {
    const char* name;
    GLenum internal, format, type, attachment;
    int bits;  ///< unorm bits; 0 = float
};

const Format kFormats[] = {
    {"DEPTH16", GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, GL_DEPTH_ATTACHMENT, 16},
    {"DEPTH24", GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, GL_DEPTH_ATTACHMENT, 24},
    {"DEPTH32F", GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, GL_DEPTH_ATTACHMENT, 0},
    {"DEPTH24_STENCIL8", GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, GL_DEPTH_STENCIL_ATTACHMENT, 24},
};

void clipControl(bool zeroToOne) {
    using ClipControlFn = void (*)(GLenum, GLenum);
    static const auto fn = reinterpret_cast<ClipControlFn>(osMesaProcAddress()("glClipControl"));
    constexpr GLenum kLowerLeft = 0x8CA1, kNegativeOneToOne = 0x935E, kZeroToOne = 0x935F;
    ASSERT_TRUE(fn != nullptr) << "glClipControl (GL 4.5 / ARB_clip_control) is missing";
    fn(kLowerLeft, zeroToOne ? kZeroToOne : kNegativeOneToOne);
}

GLuint planeProgram() {
    static GLuint p = 0;
    if (p) return p;
    const char* vs = "#version 330 core\nlayout(location = 0) in vec3 aPos;\nuniform mat4 uProj;\n"
                     "void main() { gl_Position = uProj * vec4(aPos, 1.0); }\n";
    const char* fs = "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n";
    p = compileTestProgram(vs, fs);
    return p;
}

double ndcOf(const glm::mat4& p, double t) {
    return (-double(p[2][2]) * t + p[3][2]) / (-double(p[2][3]) * t + p[3][3]);
}

// The view-space point that lands on pixel coordinate (px, py) (window, 0..kW) at distance t.
glm::dvec3 pointAt(const glm::mat4& p, double px, double py, double t) {
    const glm::dmat4 inv = glm::inverse(glm::dmat4(p));
    const glm::dvec4 q = inv * glm::dvec4(2.0 * px / kW - 1.0, 2.0 * py / kH - 1.0, ndcOf(p, t), 1.0);
    return glm::dvec3(q) / q.w;
}

// The scene's vertices (view space = world space: the camera sits at the origin looking down -Z).
std::vector<glm::vec3> sceneVertices(const glm::mat4& p) {
    std::vector<glm::vec3> v;
    auto quad = [&](glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d) {
        for (glm::dvec3 x : {a, b, c, a, c, d}) v.emplace_back(x);
    };
    for (int i = 0; i < 6; ++i) {
        const double x0 = i * kStrip, x1 = (i + 1) * kStrip, t = kDistances[i];
        quad(pointAt(p, x0, 0, t), pointAt(p, x1, 0, t), pointAt(p, x1, kH, t), pointAt(p, x0, kH, t));
    }
    const double x0 = 6 * kStrip, x1 = 7 * kStrip;
    quad(pointAt(p, x0, 0, kTiltNear), pointAt(p, x1, 0, kTiltNear), pointAt(p, x1, kH, kTiltFar),
         pointAt(p, x0, kH, kTiltFar));
    return v;
}

// Distance along the view direction of the scene at pixel (x, y)'s centre; 0 = nothing there.
double rayCast(const glm::mat4& p, int x, int y) {
    const int strip = x / kStrip;
    if (strip < 6) return kDistances[strip];
    if (strip > 6) return 0.0;
    // The tilted plane through its four corners; the ray through the pixel centre.
    const double x0 = 6 * kStrip, x1 = 7 * kStrip;
    const glm::dvec3 a = pointAt(p, x0, 0, kTiltNear), b = pointAt(p, x1, 0, kTiltNear),
                     c = pointAt(p, x0, kH, kTiltFar);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const glm::dvec3 r0 = pointAt(p, x + 0.5, y + 0.5, 1.0), r1 = pointAt(p, x + 0.5, y + 0.5, 2.0);
    const double u = glm::dot(n, a - r0) / glm::dot(n, r1 - r0);
    return -(r0 + u * (r1 - r0)).z;
}

// The derived bound (see the top of the file).
double tolerance(const Convention& c, int bits, double t) {
    const double d = fx::windowDepthOf(c.proj, c.mapping, t);
    const bool offset = !c.mapping.clipZeroToOne || c.mapping.rangeNear != 0.0f;
    const double rasterFloat = offset ? std::ldexp(1.0, -23) : 0.0;
    const double ed = (bits > 0 ? 1.0 / (std::ldexp(1.0, bits) - 1.0) : std::ldexp(std::abs(d), -22)) + rasterFloat;
    const fx::LinearizeCoefficients k = fx::linearizeCoefficients(c.proj, c.mapping);
    const double num = std::abs(k.a) + std::abs(k.b * d), den = std::abs(k.c) + std::abs(k.d * d);
    const double cancel = num / std::abs(k.a + k.b * d) + den / std::abs(k.c + k.d * d);
    const double eShader = std::ldexp(1.0, -22) * (1.0 + cancel);
    return fx::depthSlope(c.proj, c.mapping, t) * ed + t * eShader;
}

struct Measured {
    double worstRatio = 0.0;  ///< max |error| / tolerance over drawn pixels
    double worstError = 0.0;  ///< metres, at that pixel
    double worstAt = 0.0;     ///< its distance
    int checked = 0;
};

class HostDepthTest : public FxHostTest {
protected:
    void SetUp() override {
        FxHostTest::SetUp();
        buildLinearizeProgram(&programs);
        ASSERT_TRUE(depth.bind(programs));
        glGenTextures(1, &linearTex);
        glBindTexture(GL_TEXTURE_2D, linearTex);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, kW, kH, 0, GL_RED, GL_FLOAT, nullptr);
        glGenFramebuffers(1, &linearFbo);
        glBindFramebuffer(GL_FRAMEBUFFER, linearFbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, linearTex, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    void TearDown() override {
        depth.releaseGl();
        glDeleteFramebuffers(1, &linearFbo);
        glDeleteTextures(1, &linearTex);
        FxHostTest::TearDown();
    }

    // Draws the scene into the bound framebuffer the way a host with `c` would.
    static void drawScene(const Convention& c) {
        const bool reversed = c.expected == fx::DepthConvention::ReversedZ;
        glViewport(0, 0, kW, kH);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(GL_TRUE);
        glDepthFunc(reversed ? GL_GREATER : GL_LESS);
        glClearDepth(reversed ? 0.0 : 1.0);
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        clipControl(c.mapping.clipZeroToOne);
        glDepthRange(c.mapping.rangeNear, c.mapping.rangeFar);
        const std::vector<glm::vec3> v = sceneVertices(c.proj);
        GLuint vao = 0, vbo = 0;
        glGenVertexArrays(1, &vao);
        glGenBuffers(1, &vbo);
        glBindVertexArray(vao);
        glBindBuffer(GL_ARRAY_BUFFER, vbo);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(glm::vec3)), v.data(), GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
        glUseProgram(planeProgram());
        glUniformMatrix4fv(glGetUniformLocation(planeProgram(), "uProj"), 1, GL_FALSE, &c.proj[0][0]);
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(v.size()));
        glUseProgram(0);
        glBindVertexArray(0);
        glDeleteBuffers(1, &vbo);
        glDeleteVertexArrays(1, &vao);
        clipControl(false);
        glDepthRange(0.0, 1.0);
        glDepthFunc(GL_LESS);
        glDisable(GL_DEPTH_TEST);
    }

    // A framebuffer of an RGBA8 colour texture and a depth texture of `f`, left bound.
    static void makeDepthTarget(const Format& f, GLuint* tex, GLuint* colour, GLuint* fbo) {
        glGenTextures(1, tex);
        glBindTexture(GL_TEXTURE_2D, *tex);
        glTexImage2D(GL_TEXTURE_2D, 0, GLint(f.internal), kW, kH, 0, f.format, f.type, nullptr);
        glGenTextures(1, colour);
        glBindTexture(GL_TEXTURE_2D, *colour);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kW, kH, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glBindTexture(GL_TEXTURE_2D, 0);
        glGenFramebuffers(1, fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, *fbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, *colour, 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, f.attachment, GL_TEXTURE_2D, *tex, 0);
    }
    static void freeDepthTarget(GLuint tex, GLuint colour, GLuint fbo) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &fbo);
        glDeleteTextures(1, &tex);
        glDeleteTextures(1, &colour);
    }

    std::vector<float> readLinear() {
        std::vector<float> out(size_t(kW) * kH);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, linearFbo);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, 0, kW, kH, GL_RED, GL_FLOAT, out.data());
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        return out;
    }

    // Checks every pixel away from the strips' edges; returns the figures.
    // `tiltedToo` false: the tilted strip is left out (a multisample resolve keeps one sample per
    // pixel, which lies off the pixel centre, so on a slope it is not the centre's depth).
    Measured check(const Convention& c, int bits, const std::string& what, bool tiltedToo = true) {
        const std::vector<float> got = readLinear();
        Measured m;
        for (int y = 1; y < kH - 1; ++y) {
            for (int x = 0; x < kW; ++x) {
                if (x % kStrip == 0 || x % kStrip == kStrip - 1) continue;  // edge rules
                if (!tiltedToo && x / kStrip == 6) continue;
                const double want = rayCast(c.proj, x, y);
                const float v = got[size_t(y) * kW + size_t(x)];
                if (want == 0.0) {
                    EXPECT_GE(v, kFar) << what << " pixel " << x << "," << y << ": nothing drawn there";
                    continue;
                }
                const double tol = tolerance(c, bits, want), err = std::abs(double(v) - want);
                EXPECT_LE(err, tol) << what << " pixel " << x << "," << y << ": want " << want << " m, got " << v;
                ++m.checked;
                if (err / tol > m.worstRatio) {
                    m.worstRatio = err / tol;
                    m.worstError = err;
                    m.worstAt = want;
                }
            }
        }
        std::printf("  %-34s %-26s worst %.3f of the bound (%.3g m at %.1f m), %d px\n", c.name, what.c_str(),
                    m.worstRatio, m.worstError, m.worstAt, m.checked);
        return m;
    }

    fx::ProgramCache programs{fx::snapshotShaderReader(fx::shaderReader(""))};
    fx::DepthLinearizer depth;
    GLuint linearTex = 0, linearFbo = 0;
};

TEST_F(HostDepthTest, MappingRoundTripsAndNamesTheConvention) {
    for (const Convention& c : conventions()) {
        SCOPED_TRACE(c.name);
        EXPECT_TRUE(fx::validDepthMapping(c.proj, c.mapping));
        EXPECT_EQ(fx::conventionOf(c.proj, c.mapping), c.expected);
        for (double t : {0.6, 1.0, 7.0, 55.0, 190.0}) {
            const double d = fx::windowDepthOf(c.proj, c.mapping, t);
            EXPECT_NEAR(fx::linearDepthOf(c.proj, c.mapping, d), t, 1e-9 * t);
            const double lo = std::min(c.mapping.rangeNear, c.mapping.rangeFar);
            const double hi = std::max(c.mapping.rangeNear, c.mapping.rangeFar);
            EXPECT_TRUE(d >= lo - 1e-12 && d <= hi + 1e-12) << "t " << t << " lands outside the range: " << d;
        }
    }
    // Irrlicht's case: a [0, 1] matrix under GL's clip control uses window depths [0.5, 1] only.
    const Convention irr = conventions()[1];
    EXPECT_NEAR(fx::windowDepthOf(irr.proj, irr.mapping, kNear), 0.5, 1e-9);
    fx::DepthMapping bad;
    bad.rangeNear = bad.rangeFar = 0.5f;
    EXPECT_FALSE(fx::validDepthMapping(irr.proj, bad));
    glm::mat4 flat(1.0f);  // z_ndc = w: no distance in the depth at all
    flat[2][2] = 0.0f;
    EXPECT_FALSE(fx::validDepthMapping(flat, fx::DepthMapping{}));
    // The identity is a valid (orthographic) projection: ndc z = -t.
    EXPECT_TRUE(fx::validDepthMapping(glm::mat4(1.0f), fx::DepthMapping{}));
}

TEST_F(HostDepthTest, DepthTexturesOfEveryFormatLinearisePerConvention) {
    for (const Format& f : kFormats) {
        GLuint tex = 0, colour = 0, fbo = 0;
        makeDepthTarget(f, &tex, &colour, &fbo);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);  // as a host may leave it
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);  // a shadow map's
        glBindTexture(GL_TEXTURE_2D, 0);
        ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE)) << f.name;
        {
            fx::GlStateGuard guard;
            EXPECT_EQ(fx::DepthLinearizer::textureFormat(tex), f.internal) << f.name;
            EXPECT_EQ(fx::supportedDepthFormat(f.internal), f.internal);
        }
        for (const Convention& c : conventions()) {
            glBindFramebuffer(GL_FRAMEBUFFER, fbo);
            drawScene(c);
            {
                fx::GlStateGuard guard;
                depth.linearize(tex, c.proj, c.mapping, kFar, linearFbo, kW, kH);
            }
            check(c, f.bits, std::string(f.name) + " texture");
            // (c): the same z-buffer as "the framebuffer bound for drawing": copied, then linearised.
            {
                fx::GlStateGuard guard;
                const uint32_t format = fx::DepthLinearizer::framebufferDepthFormat(fbo);
                EXPECT_NE(format, 0u) << f.name;
                const uint32_t copy = depth.copyFramebufferDepth(fbo, 0, 0, kW, kH, format);
                depth.linearize(copy, c.proj, c.mapping, kFar, linearFbo, kW, kH);
            }
            check(c, f.bits, std::string(f.name) + " bound FBO copy");
            drainGlErrors(c.name);
        }
        freeDepthTarget(tex, colour, fbo);
    }
}

// The linearise program is the cache's: a shader reload swaps a new cache in and deletes the old
// programs; bind() then takes the new build, and the pass draws with it (a stale name would
// raise a GL error, which the fixture checks, and leave the target unwritten).
TEST_F(HostDepthTest, TheLinearizerTakesTheProgramOfASwappedCache) {
    const Convention c = conventions()[0];
    const Format& f = kFormats[1];  // DEPTH24
    GLuint tex = 0, colour = 0, fbo = 0;
    makeDepthTarget(f, &tex, &colour, &fbo);
    ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    drawScene(c);
    {
        fx::ProgramCache reloaded(fx::snapshotShaderReader(fx::shaderReader("")));
        buildLinearizeProgram(&reloaded);
        programs.swap(reloaded);
    }  // the old programs are deleted here, as at the end of Renderers::reload
    {
        fx::GlStateGuard guard;
        ASSERT_TRUE(depth.bind(programs));
        depth.linearize(tex, c.proj, c.mapping, kFar, linearFbo, kW, kH);
    }
    EXPECT_GT(check(c, f.bits, "after a swap").checked, 0);
    freeDepthTarget(tex, colour, fbo);
}

TEST_F(HostDepthTest, DefaultFramebufferDepthIsCopiedAndLinearised) {
    ASSERT_TRUE(resizeDefaultFramebuffer(kW, kH));
    {
        fx::GlStateGuard guard;
        EXPECT_EQ(fx::DepthLinearizer::framebufferDepthFormat(0), uint32_t(GL_DEPTH24_STENCIL8));  // OSMesa: 24 + 8
        EXPECT_EQ(fx::DepthLinearizer::framebufferSamples(0), 0);
    }
    for (const Convention& c : conventions()) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        drawScene(c);
        {
            fx::GlStateGuard guard;
            const uint32_t copy = depth.copyFramebufferDepth(0, 0, 0, kW, kH, GL_DEPTH24_STENCIL8);
            depth.linearize(copy, c.proj, c.mapping, kFar, linearFbo, kW, kH);
        }
        check(c, 24, "default framebuffer copy");
    }
    EXPECT_EQ(depth.copies(), int(conventions().size()));
    ASSERT_TRUE(resizeDefaultFramebuffer(4, 4));
}

// A multisampled host framebuffer (what an engine with MSAA draws into): the copy is a depth
// resolve (a blit), since glCopyTexSubImage2D refuses a multisampled source.
TEST_F(HostDepthTest, MultisampledFramebufferDepthIsResolvedAndLinearised) {
    struct Ms {
        const char* name;
        GLenum depth;
        int bits;
    };
    for (const Ms& ms : {Ms{"MSAA4 DEPTH24_STENCIL8", GL_DEPTH24_STENCIL8, 24}, Ms{"MSAA4 DEPTH32F", GL_DEPTH_COMPONENT32F, 0}}) {
        GLuint rb[2] = {}, fbo = 0;
        glGenRenderbuffers(2, rb);
        glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, kW, kH);
        glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, ms.depth, kW, kH);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glGenFramebuffers(1, &fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER,
                                  ms.depth == GL_DEPTH24_STENCIL8 ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                                  GL_RENDERBUFFER, rb[1]);
        ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE)) << ms.name;
        uint32_t format = 0;
        int samples = 0;
        {
            fx::GlStateGuard guard;
            format = fx::DepthLinearizer::framebufferDepthFormat(fbo);
            samples = fx::DepthLinearizer::framebufferSamples(fbo);
        }
        EXPECT_EQ(format, uint32_t(ms.depth)) << ms.name;
        EXPECT_EQ(samples, 4) << ms.name;
        for (const Convention& c : conventions()) {
            glBindFramebuffer(GL_FRAMEBUFFER, fbo);
            drawScene(c);
            {
                fx::GlStateGuard guard;
                const uint32_t copy = depth.copyFramebufferDepth(fbo, 0, 0, kW, kH, format, samples);
                depth.linearize(copy, c.proj, c.mapping, kFar, linearFbo, kW, kH);
            }
            check(c, ms.bits, ms.name, /*tiltedToo=*/false);
            drainGlErrors(c.name);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &fbo);
        glDeleteRenderbuffers(2, rb);
    }
}

}  // namespace host_depth
}  // namespace fxtest
