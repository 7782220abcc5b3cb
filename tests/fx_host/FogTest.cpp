// The host's fog on the smoke (fx::ViewInfo::fog) and drawing the smoke in distance slices around
// the host's own blended geometry (fx::ViewInfo::slice).
//
// Fog: a particle and a quad at the same depth get the same fog factor. The quad is the
// reference: drawn with GL's fixed-function fog where the context is a compatibility one (the
// ctest entry FogTest.CompatibilityProfile), else with GL's fog formula written out in the test's
// own shader. The particle is opaque white (an all-white atlas, a white ramp of alpha 1) over a
// black sky, so its fogged colour f + (1 - f) fogColour must equal the white quad's.
#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "FxTestHost.h"
#include "PoisonedHostGl.h"
#include "../../fx_plugin/render/MegaRenderer.h"

namespace fxtest {
namespace fog {  // named: the fx_host tests build as unity batches

constexpr int kW = 96, kH = 96;
// Compatibility-profile enums (the tests' glad is 3.3 core; the entry points: PoisonedHostGl.h).
constexpr GLenum kFog = 0x0B60, kFogDensity = 0x0B62, kFogStart = 0x0B63, kFogEnd = 0x0B64,
                 kFogMode = 0x0B65, kFogColor = 0x0B66, kExp = 0x0800, kExp2 = 0x0801, kLinear = 0x2601,
                 kProjection = 0x1701, kModelView = 0x1700, kQuads = 0x0007;

// GL's fog, written out from the specification (not the plugin's shader): c = |z_eye|.
const char* kQuadVs = R"(#version 330 core
layout(location = 0) in vec3 aPos;
uniform mat4 uView, uProj;
out float vEyeZ;
void main() {
    vec4 eye = uView * vec4(aPos, 1.0);
    vEyeZ = eye.z;
    gl_Position = uProj * eye;
})";
const char* kQuadFs = R"(#version 330 core
in float vEyeZ;
uniform vec4 uColor;
uniform int uMode;
uniform vec3 uFogColor;
uniform vec3 uFogParams;
out vec4 oColor;
void main() {
    float c = abs(vEyeZ);
    float f = 1.0;
    if (uMode == 1) f = (uFogParams.y - c) / (uFogParams.y - uFogParams.x);
    if (uMode == 2) f = exp(-uFogParams.z * c);
    if (uMode == 3) f = exp(-(uFogParams.z * c) * (uFogParams.z * c));
    f = clamp(f, 0.0, 1.0);
    oColor = vec4(mix(uFogColor, uColor.rgb, f), uColor.a);
})";

/// An all-white, opaque smoke atlas in a folder of its own: every particle texel is (1, 1, 1, 1).
std::string whiteAtlasDir() {
    const std::string dir = scratchDir() + "/white_atlas";
    static bool written = false;
    if (!written) {
        std::error_code ignored;
        std::filesystem::create_directories(dir, ignored);
        Image img;
        img.width = img.height = 64;
        img.rgba.assign(size_t(64 * 64 * 4), 255);
        written = writePng(dir + "/smoke_atlas.png", img);
    }
    return dir;
}

class FogTest : public FxHostTest {
protected:
    FogTest() {
        scene.sky = glm::vec3(0.0f);
        direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(1.0f)}};
        direct.desc.render.nearFade = 0.0f;
        direct.settings.shape = fx::ParticleShape::Quad;
        quadProgram_ = compileTestProgram(kQuadVs, kQuadFs);
        glGenVertexArrays(1, &vao_);
        glGenBuffers(1, &vbo_);
    }
    ~FogTest() override {
        glDeleteBuffers(1, &vbo_);
        glDeleteVertexArrays(1, &vao_);
        glDeleteProgram(quadProgram_);
    }

    /// The scene, then the particles of `v` (the whole view unless slices are given).
    Image drawParticles(const fx::ViewInfo& v) {
        renderFrame(graph, scene, v, [&](fx::FrameBuilder& f) { drawn = direct.declare(v, f); });
        return graph.readColor();
    }

    /// A quad facing the camera at view distance `d` (x, y in [-h, h]) of `colour`, fogged by
    /// `fog`, blended (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) into the bound framebuffer: fixed-function
    /// in a compatibility context when `fixedFunction`, else the formula shader.
    void drawQuad(const fx::ViewInfo& v, float d, float h, glm::vec4 colour, const fx::Fog& fog, bool fixedFunction) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDisable(GL_DEPTH_TEST);
        if (fixedFunction) {
            const poisoned_host_gl::Compat& ff = poisoned_host_gl::compat();
            glUseProgram(0);
            ff.matrixMode(kProjection);
            ff.loadMatrixf(&v.proj[0][0]);
            ff.matrixMode(kModelView);
            ff.loadMatrixf(&v.view[0][0]);
            if (fog.on()) {
                glEnable(kFog);
                const GLint mode = fog.mode == fx::Fog::Mode::Linear ? kLinear
                                   : fog.mode == fx::Fog::Mode::Exp  ? kExp
                                                                     : kExp2;
                ff.fogi(kFogMode, mode);
                ff.fogf(kFogStart, fog.start);
                ff.fogf(kFogEnd, fog.end);
                ff.fogf(kFogDensity, fog.density);
                const GLfloat c[4] = {fog.color.x, fog.color.y, fog.color.z, 1.0f};
                ff.fogfv(kFogColor, c);
            }
            ff.color4f(colour.r, colour.g, colour.b, colour.a);
            ff.begin(kQuads);
            ff.vertex3f(-h, -h, -d);
            ff.vertex3f(h, -h, -d);
            ff.vertex3f(h, h, -d);
            ff.vertex3f(-h, h, -d);
            ff.end();
            glDisable(kFog);
            ff.matrixMode(kProjection);
            const glm::mat4 identity(1.0f);
            ff.loadMatrixf(&identity[0][0]);
            ff.matrixMode(kModelView);
            ff.loadMatrixf(&identity[0][0]);
        } else {
            const float q[12] = {-h, -h, -d, h, -h, -d, -h, h, -d, h, h, -d};
            glBindVertexArray(vao_);
            glBindBuffer(GL_ARRAY_BUFFER, vbo_);
            glBufferData(GL_ARRAY_BUFFER, sizeof q, q, GL_STREAM_DRAW);
            glEnableVertexAttribArray(0);
            glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
            glUseProgram(quadProgram_);
            glUniformMatrix4fv(glGetUniformLocation(quadProgram_, "uView"), 1, GL_FALSE, &v.view[0][0]);
            glUniformMatrix4fv(glGetUniformLocation(quadProgram_, "uProj"), 1, GL_FALSE, &v.proj[0][0]);
            glUniform4f(glGetUniformLocation(quadProgram_, "uColor"), colour.r, colour.g, colour.b, colour.a);
            glUniform1i(glGetUniformLocation(quadProgram_, "uMode"), int(fog.mode));
            glUniform3f(glGetUniformLocation(quadProgram_, "uFogColor"), fog.color.x, fog.color.y, fog.color.z);
            glUniform3f(glGetUniformLocation(quadProgram_, "uFogParams"), fog.start, fog.end, fog.density);
            glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
            glUseProgram(0);
            glBindVertexArray(0);
            glBindBuffer(GL_ARRAY_BUFFER, 0);
        }
        glDisable(GL_BLEND);
    }

    /// The fogged white quad at distance `d` over the black sky, as a host fogs its geometry.
    Image referenceQuad(const fx::ViewInfo& v, float d, const fx::Fog& fog) {
        renderFrame(graph, scene, v, [&](fx::FrameBuilder& f) {
            f.addPass("reference_quad", {}, {f.sceneColor()}, [&, d, fog](fx::PassContext& ctx) {
                ctx.bindForDraw(f.sceneColor());
                drawQuad(v, d, 4.0f, glm::vec4(1.0f), fog, osMesaCompatibilityProfile());
            });
        });
        return graph.readColor();
    }

    static fx::Fog fogOf(fx::Fog::Mode mode) {
        fx::Fog fog;
        fog.mode = mode;
        fog.color = glm::vec3(0.2f, 0.5f, 0.9f);
        fog.start = 3.0f;
        fog.end = 21.0f;
        fog.density = mode == fx::Fog::Mode::Exp ? 0.06f : 0.07f;
        return fog;
    }

    TestHostAdapter host;
    DirectParticles direct{&host, std::string(), whiteAtlasDir()};
    TestFrameGraph graph{kW, kH};
    TestScene scene;
    fx::ViewInfo view = makeView(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), kW, kH);
    int drawn = 0;

private:
    GLuint quadProgram_ = 0, vao_ = 0, vbo_ = 0;
};

const RenderMode kWays[] = {modes::kHard, modes::kSoft, modes::kSpherical, modes::kSoftQuarter};

int centreDiff(const Image& a, const Image& b) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a.at(kW / 2, kH / 2)[c]) - int(b.at(kW / 2, kH / 2)[c])));
    return worst;
}

TEST_F(FogTest, AFoggedParticleGetsTheFogFactorOfAFoggedQuadAtItsDepth) {
    std::printf("[ measured ] reference quad: %s\n",
                osMesaCompatibilityProfile() ? "fixed-function fog (compatibility context)" : "GL's formula in a shader");
    for (fx::Fog::Mode mode : {fx::Fog::Mode::Linear, fx::Fog::Mode::Exp, fx::Fog::Mode::Exp2}) {
        for (float d : {6.0f, 12.0f, 18.0f}) {
            fx::ViewInfo v = view;
            v.fog = fogOf(mode);
            const Image quad = referenceQuad(v, d, v.fog);
            HandParticle p;
            p.position = glm::vec3(0.0f, 0.0f, -d);
            p.size = 2.0f;
            direct.set({p});
            for (const RenderMode& way : kWays) {
                direct.setMode(way);
                const Image clear = drawParticles(view);
                const Image fogged = drawParticles(v);
                ASSERT_EQ(drawn, 1);
                const uint8_t* q = quad.at(kW / 2, kH / 2);
                const uint8_t* s = fogged.at(kW / 2, kH / 2);
                // Without fog the particle is white: the comparison is about the fog alone.
                EXPECT_EQ(clear.at(kW / 2, kH / 2)[0], 255) << way.label;
                std::printf("[ measured ] fog %d at %4.1f m, %-9s quad (%3d %3d %3d) particle (%3d %3d %3d)\n",
                            int(mode), double(d), way.label, q[0], q[1], q[2], s[0], s[1], s[2]);
                EXPECT_LE(centreDiff(fogged, quad), 1) << "fog " << int(mode) << " at " << d << " m, " << way.label;
            }
        }
    }
    direct.settings.options = fx::RenderOptions{};
}

TEST_F(FogTest, FogOffIsThePictureWithoutFogBitForBit) {
    HandParticle p;
    p.position = glm::vec3(0.3f, 0.0f, -10.0f);
    p.size = 3.0f;
    direct.set({p});
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(0.7f, 0.6f, 0.5f, 0.6f)}};
    for (const RenderMode& way : kWays) {
        direct.setMode(way);
        const Image plain = drawParticles(view);
        fx::ViewInfo off = view;
        off.fog = fogOf(fx::Fog::Mode::Exp2);
        off.fog.mode = fx::Fog::Mode::Off;  // every other field set: the mode alone decides
        EXPECT_EQ(maxAbsDiff(drawParticles(off), plain), 0) << way.label;
        fx::ViewInfo on = view;
        on.fog = fogOf(fx::Fog::Mode::Exp2);
        EXPECT_GT(maxAbsDiff(drawParticles(on), plain), 20) << way.label << ": fog changed nothing";
    }
}

// Additive smoke is light: fog dims it to nothing and never tints it with the fog colour.
TEST_F(FogTest, AdditiveSmokeFadesWithDistanceAndTakesNoFogColour) {
    direct.desc.render.blend = fx::BlendMode::Additive;
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(0.9f, 0.6f, 0.3f, 1.0f)}};
    HandParticle p;
    p.position = glm::vec3(0.0f, 0.0f, -12.0f);
    p.size = 2.0f;
    direct.set({p});
    direct.settings.options.techniqueOverride = fx::Technique::Soft;
    const Image plain = drawParticles(view);
    fx::ViewInfo v = view;
    v.fog = fogOf(fx::Fog::Mode::Linear);  // f = (21 - 12) / 18 = 0.5
    const Image fogged = drawParticles(v);
    for (int c = 0; c < 3; ++c) {
        const int expected = int(std::lround(plain.at(kW / 2, kH / 2)[c] * 0.5));
        EXPECT_LE(std::abs(int(fogged.at(kW / 2, kH / 2)[c]) - expected), 1) << "channel " << c;
    }
    v.fog.end = 10.0f;  // past the fog's end: nothing left
    v.fog.start = 2.0f;
    const Image gone = drawParticles(v);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(gone.at(kW / 2, kH / 2)[c], 0) << "channel " << c;
}

// Mega-particles are fogged at the cloud's front (between the sphere's front and its centre at
// the centre pixel): with a black fog colour the pixel is the unfogged one times f there.
TEST_F(FogTest, MegaCloudsAreFoggedAtTheirFront) {
    HandParticle p;
    p.position = glm::vec3(0.0f, 0.0f, -12.0f);
    p.size = 3.0f;
    direct.set({p});
    direct.settings.options.techniqueOverride = fx::Technique::Mega;
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(1.0f, 1.0f, 1.0f, 0.8f)}};
    direct.desc.render.technique = fx::Technique::Mega;
    fx::MegaRenderer mega(fx::RendererConfig{&host, "", "", nullptr, fx::Jobs()}, direct.programs);
    auto draw = [&](const fx::ViewInfo& v) {
        fx::ParticleBatch batch;
        batch.pool = &direct.pool;
        batch.desc = &direct.desc;
        batch.time = 1.25f;
        renderFrame(graph, scene, v, [&](fx::FrameBuilder& f) { drawn = mega.declarePasses(v, f, &batch, 1, direct.settings); });
        return graph.readColor();
    };
    const Image plain = draw(view);
    ASSERT_EQ(drawn, 1);
    fx::ViewInfo v = view;
    v.fog = fogOf(fx::Fog::Mode::Exp);
    v.fog.color = glm::vec3(0.0f);
    const Image fogged = draw(v);
    const float fFront = std::exp(-v.fog.density * (12.0f - 1.5f)), fCentre = std::exp(-v.fog.density * 12.0f);
    const int u = plain.at(kW / 2, kH / 2)[0], s = fogged.at(kW / 2, kH / 2)[0];
    std::printf("[ measured ] mega centre: unfogged %d, fogged %d, f from %.3f (centre) to %.3f (front)\n", u, s,
                double(fCentre), double(fFront));
    EXPECT_GT(u, 40);
    EXPECT_GE(s, int(std::floor(u * fCentre)) - 1);
    EXPECT_LE(s, int(std::ceil(u * fFront)) + 1);
}

// ---- distance slices ---------------------------------------------------------------------------

// A half-transparent red pane at 10 m between smoke at 5 m (left of centre) and at 15 m (right):
// drawn as a host with its own blended geometry does it, far slice, pane, near slice, the near
// smoke lies over the pane and the far smoke under it. Expected pixels by blending in that order
// on the CPU; the one-call path (every particle, then the pane) gets the near smoke wrong.
TEST_F(FogTest, SlicesOrderTheSmokeWithTheHostsBlendedPane) {
    const float a = 0.6f;  // the smoke's opacity: the blending order shows in every channel
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(1.0f, 1.0f, 1.0f, a)}};
    HandParticle nearP, farP;
    nearP.position = glm::vec3(-0.9f, 0.0f, -5.0f);
    nearP.size = 1.2f;
    farP.position = glm::vec3(2.7f, 0.0f, -15.0f);
    farP.size = 3.6f;
    direct.set({nearP, farP});
    const glm::vec4 pane(1.0f, 0.0f, 0.0f, 0.5f);
    const int nearX = int(std::lround(projectToPixel(view, nearP.position).x));
    const int farX = int(std::lround(projectToPixel(view, farP.position).x));
    const int y = kH / 2;
    ASSERT_LT(nearX, kW / 2);
    ASSERT_GT(farX, kW / 2);
    // Straight "over" blends on black: smoke (white, a) and the pane (red, 0.5).
    auto over = [](glm::vec3 dst, glm::vec3 src, float alpha) { return src * alpha + dst * (1.0f - alpha); };
    const glm::vec3 black(0.0f), white(1.0f), red(1.0f, 0.0f, 0.0f);
    const glm::vec3 nearExpected = over(over(black, red, pane.a), white, a);  // pane, then smoke over it
    const glm::vec3 farExpected = over(over(black, white, a), red, pane.a);   // smoke, then the pane

    auto paneStep = [&](fx::FrameBuilder& f) {
        f.addPass("glass_pane", {}, {f.sceneColor()}, [&](fx::PassContext& ctx) {
            ctx.bindForDraw(f.sceneColor());
            drawQuad(view, 10.0f, 6.0f, pane, fx::Fog{}, false);
        });
    };
    auto worstAt = [&](const Image& img, int x, glm::vec3 expected) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(img.at(x, y)[c]) - int(std::lround(expected[c] * 255.0f))));
        return worst;
    };
    auto check = [&](const Image& img, int x, glm::vec3 expected, const char* what, const char* way) {
        const int worst = worstAt(img, x, expected);
        return ::testing::AssertionResult(worst <= 2) << way << ": " << what << " off by " << worst << "/255 (" << int(img.at(x, y)[0])
                                                      << " " << int(img.at(x, y)[1]) << " " << int(img.at(x, y)[2]) << ")";
    };
    for (const RenderMode& way : kWays) {
        direct.setMode(way);
        fx::ViewInfo farSlice = view, nearSlice = view;
        farSlice.slice = fx::DistanceSlice{10.0f, 0.0f};
        nearSlice.slice = fx::DistanceSlice{0.0f, 10.0f};
        int drawnFar = 0, drawnNear = 0;
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
            drawnFar = direct.declare(farSlice, f);
            paneStep(f);
            drawnNear = direct.declare(nearSlice, f);
        });
        const Image sliced = graph.readColor();
        writePng("/tmp/fx_host_slices_" + std::string(way.label) + ".png", sliced);
        EXPECT_EQ(drawnFar, 1) << way.label;
        EXPECT_EQ(drawnNear, 1) << way.label;
        EXPECT_TRUE(check(sliced, nearX, nearExpected, "near smoke over the pane", way.label));
        EXPECT_TRUE(check(sliced, farX, farExpected, "far smoke under the pane", way.label));

        // One call for all the smoke, then the pane: the near smoke ends up under it.
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
            direct.declare(view, f);
            paneStep(f);
        });
        const Image oneCall = graph.readColor();
        writePng("/tmp/fx_host_slices_one_call_" + std::string(way.label) + ".png", oneCall);
        std::printf("[ measured ] %-9s slices: near smoke off by %d/255, far by %d/255; one call: near off by %d/255\n",
                    way.label, worstAt(sliced, nearX, nearExpected), worstAt(sliced, farX, farExpected),
                    worstAt(oneCall, nearX, nearExpected));
        EXPECT_FALSE(check(oneCall, nearX, nearExpected, "one call", way.label)) << way.label << ": the test cannot tell";
        EXPECT_TRUE(check(oneCall, farX, farExpected, "one call, far smoke", way.label));
    }
    direct.settings.options = fx::RenderOptions{};
}

TEST_F(FogTest, ASliceDrawsOnlyTheParticlesInItsRange) {
    std::vector<HandParticle> ps;
    for (int i = 0; i < 8; ++i) {
        HandParticle p;
        p.position = glm::vec3(float(i % 3) - 1.0f, 0.0f, -(3.0f + 2.0f * float(i)));  // 3, 5, ... 17 m
        p.size = 1.0f;
        ps.push_back(p);
    }
    direct.set(ps);
    auto count = [&](fx::DistanceSlice s) {
        fx::ViewInfo v = view;
        v.slice = s;
        drawParticles(v);
        return drawn;
    };
    EXPECT_EQ(count({0.0f, 0.0f}), 8);
    EXPECT_EQ(count({0.0f, 9.0f}), 3);    // 3, 5, 7
    EXPECT_EQ(count({9.0f, 0.0f}), 5);    // 9 .. 17
    EXPECT_EQ(count({7.0f, 11.0f}), 2);   // 7, 9: the lower end in, the upper one out
    EXPECT_EQ(count({20.0f, 30.0f}), 0);
}

}  // namespace fog
}  // namespace fxtest
