// Lit smoke (API 1.2 setSceneLight): the normal atlas, the sun's side of a particle,
// self-shadowing through the opacity map, and stability.
//   - the normal atlas agrees with the alpha atlas (zero normal where alpha is 0, unit elsewhere);
//   - one particle lit from the left is brighter on its left half than unlit, and the other way
//     round from the right; ambient alone only scales the unlit picture (no side preferred);
//   - a thick cloud is darker on the side away from the sun with absorption than without;
//   - two renders of a still frame are byte-identical; lit pictures stay inside the particles.
#include <cmath>
#include <cstdio>

#include <stb/stb_image.h>

#include "FxTestHost.h"
#include "../../fx_plugin/render/EmbeddedResources.h"
#include "../../fx_plugin/render/SmokeAtlas.h"

namespace fxtest {
namespace {

std::vector<uint8_t> decodeEmbedded(const char* name, int* w, int* h) {
    const fx::embedded::Resource* r = fx::embedded::find(name);
    if (!r) return {};
    int channels = 0;
    stbi_uc* p = stbi_load_from_memory(r->data, int(r->size), w, h, &channels, 4);
    if (!p) return {};
    std::vector<uint8_t> out(p, p + size_t(*w) * size_t(*h) * 4);
    stbi_image_free(p);
    return out;
}

TEST(NormalAtlas, ZeroWhereTheAtlasIsEmptyAndUnitLengthElsewhere) {
    int aw = 0, ah = 0, nw = 0, nh = 0;
    const std::vector<uint8_t> alpha = decodeEmbedded(fx::SmokeAtlas::kFileName, &aw, &ah);
    const std::vector<uint8_t> normals = decodeEmbedded(fx::SmokeAtlas::kNormalsFileName, &nw, &nh);
    ASSERT_FALSE(alpha.empty());
    ASSERT_FALSE(normals.empty());
    ASSERT_EQ(aw, nw);
    ASSERT_EQ(ah, nh);
    long empty = 0, filled = 0, tilted = 0;
    double worst = 0.0;
    for (size_t i = 0; i < size_t(aw) * size_t(ah); ++i) {
        const glm::vec3 n = (glm::vec3(normals[i * 4], normals[i * 4 + 1], normals[i * 4 + 2]) - 128.0f) / 127.0f;
        if (alpha[i * 4 + 3] == 0) {
            ++empty;
            ASSERT_EQ(glm::length(n), 0.0f) << "texel " << i;
            continue;
        }
        ++filled;
        // 8-bit components: each within 1/254 of the true value, so the length within 0.015.
        worst = std::max(worst, double(std::fabs(glm::length(n) - 1.0f)));
        ASSERT_NEAR(glm::length(n), 1.0f, 0.015f) << "texel " << i;
        ASSERT_GT(n.z, 0.0f) << "texel " << i << ": faces away from the viewer";
        if (n.z < 0.95f) ++tilted;
    }
    std::printf("[ measured ] %ld empty, %ld filled texels; worst |length - 1| %.4f; %ld tilted > 18 deg\n", empty,
                filled, worst, tilted);
    EXPECT_GT(empty, 0);
    EXPECT_GT(filled, 0);
    EXPECT_GT(tilted, filled / 10) << "the normals are nearly flat: lighting would show no shape";
}

// Sum of luminance over the left and right halves of the picture (column < or >= cx).
struct Halves {
    double left = 0.0, right = 0.0;
    double ratio() const { return left / std::max(right, 1e-9); }
};
Halves halves(const Image& img, int cx) {
    Halves h;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            const uint8_t* p = img.at(x, y);
            const double l = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            (x < cx ? h.left : h.right) += l;
        }
    }
    return h;
}

class LightingTest : public FxHostTest {
protected:
    Image draw(const fx::LightState* light) {
        direct.settings.light = light ? *light : fx::LightState{};
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { drawn = direct.declare(view, f); });
        return graph.readColor();
    }
    static fx::LightState sun(glm::vec3 toSun, glm::vec3 colour, glm::vec3 ambient) {
        fx::LightState l;
        l.on = true;
        l.toSun = glm::normalize(toSun);
        l.sunColor = colour;
        l.ambient = ambient;
        return l;
    }
    static constexpr int kW = 160, kH = 160;
    TestHostAdapter host;
    DirectParticles direct{&host};
    TestFrameGraph graph{kW, kH};
    TestScene scene;
    fx::ViewInfo view = makeView(glm::vec3(0, 1, 5), glm::vec3(0, 1, 0), kW, kH);
    int drawn = 0;
};

// Black sky, nothing else: a pixel is the particle's own premultiplied colour.
TEST_F(LightingTest, TheSunsSideOfAParticleIsBrighterAndAmbientAloneIsEven) {
    scene.sky = glm::vec3(0.0f);
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(0.8f, 0.8f, 0.8f, 0.9f)}};
    direct.desc.lighting.absorption = 0.0f;  // one particle: only its normals decide
    HandParticle p;
    p.position = glm::vec3(0, 1, 0);
    p.size = 2.5f;
    direct.set({p});
    const int cx = int(std::lround(projectToPixel(view, p.position).x));
    const glm::vec3 white(1.0f), grey(0.25f);
    for (fx::Technique t : {fx::Technique::Hard, fx::Technique::Soft, fx::Technique::Spherical}) {
        direct.settings.options.techniqueOverride = t;
        const Image unlit = draw(nullptr);
        ASSERT_EQ(drawn, 1);
        const fx::LightState fromLeft = sun(glm::vec3(-1.0f, 0.1f, 0.25f), white, grey);
        const fx::LightState fromRight = sun(glm::vec3(1.0f, 0.1f, 0.25f), white, grey);
        const Image left = draw(&fromLeft);
        const Image right = draw(&fromRight);
        writePng(scratchDir() + "/lit_left_" + std::to_string(int(t)) + ".png", left);
        writePng(scratchDir() + "/lit_right_" + std::to_string(int(t)) + ".png", right);
        // The atlas puff is not symmetric: compare each lit picture's left/right balance with
        // the unlit one's. Margin 1.3: the sun's side gets at least 30 % more light relatively.
        const double base = halves(unlit, cx).ratio();
        const double l = halves(left, cx).ratio() / base, r = halves(right, cx).ratio() / base;
        std::printf("[ measured ] technique %d: left/right balance x%.3f (sun left), x%.3f (sun right)\n", int(t), l, r);
        EXPECT_GT(l, 1.3) << "technique " << int(t);
        EXPECT_LT(r, 1.0 / 1.3) << "technique " << int(t);
        // Ambient only: the unlit picture scaled by the ambient (0.6), within rounding.
        const fx::LightState ambientOnly = sun(glm::vec3(0, 1, 0), glm::vec3(0.0f), glm::vec3(0.6f));
        const Image even = draw(&ambientOnly);
        int worst = 0;
        for (size_t i = 0; i < even.rgba.size(); ++i) {
            if (i % 4 == 3) continue;
            worst = std::max(worst, std::abs(int(even.rgba[i]) - int(std::lround(unlit.rgba[i] * 0.6))));
        }
        EXPECT_LE(worst, 2) << "technique " << int(t);
        EXPECT_NEAR(halves(even, cx).ratio() / base, 1.0, 0.01) << "technique " << int(t);
    }
}

// A thick cloud lit from +x, seen from +z: with absorption the side away from the sun (left)
// darkens relative to the side toward it, beyond what the normals already do.
TEST_F(LightingTest, AThickCloudShadowsItsFarSide) {
    scene.sky = glm::vec3(0.0f);
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(0.85f, 0.85f, 0.85f, 0.7f)}};
    std::vector<HandParticle> cloud;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) {
                HandParticle p;
                p.position = glm::vec3(-1.2f + 0.6f * float(i), 0.6f + 0.4f * float(j), -0.4f + 0.4f * float(k));
                p.size = 1.2f;
                p.frame = (i + j + k) % 4;
                p.rotation = 0.7f * float(i * 9 + j * 3 + k);
                cloud.push_back(p);
            }
    direct.set(cloud);
    direct.settings.options.techniqueOverride = fx::Technique::Soft;
    const fx::LightState light = sun(glm::vec3(1.0f, 0.15f, 0.0f), glm::vec3(1.0f), glm::vec3(0.3f));
    const int cx = int(std::lround(projectToPixel(view, glm::vec3(0, 1, 0)).x));
    direct.desc.lighting.absorption = 0.0f;
    const Image clear = draw(&light);
    direct.desc.lighting.absorption = 1.0f;
    const Image shadowed = draw(&light);
    ASSERT_EQ(drawn, int(cloud.size()));
    EXPECT_TRUE(graph.ran("smoke_opacity"));
    writePng(scratchDir() + "/cloud_clear.png", clear);
    writePng(scratchDir() + "/cloud_shadowed.png", shadowed);
    // Share of its light each side loses to the smoke between it and the sun.
    const Halves a = halves(clear, cx), b = halves(shadowed, cx);
    const double lossFar = 1.0 - b.left / a.left, lossNear = 1.0 - b.right / a.right;
    std::printf("[ measured ] light lost to self-shadowing: far side %.3f, near side %.3f\n", lossFar, lossNear);
    EXPECT_GT(lossFar, lossNear + 0.1) << "the side away from the sun loses at least 10 points more";
    EXPECT_GT(lossNear, 0.0);
    // Still frame, paused: the same bytes.
    const Image again = draw(&light);
    EXPECT_EQ(maxAbsDiff(again, shadowed), 0);
}

// FrameSettings: the switches are read once, when a view's passes are declared. A caller that
// changes them before the graph runs those passes changes the next frame, not this one.
TEST_F(LightingTest, PendingPassesDrawWithTheSettingsTheirViewWasDeclaredWith) {
    scene.sky = glm::vec3(0.0f);
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(0.8f, 0.8f, 0.8f, 0.9f)}};
    HandParticle p;
    p.position = glm::vec3(0, 1, 0);
    p.size = 2.5f;
    direct.set({p});
    direct.settings.options.techniqueOverride = fx::Technique::Soft;
    const fx::LightState fromLeft = sun(glm::vec3(-1.0f, 0.1f, 0.25f), glm::vec3(1.0f), glm::vec3(0.25f));
    const fx::LightState fromRight = sun(glm::vec3(1.0f, 0.1f, 0.25f), glm::vec3(1.0f), glm::vec3(0.25f));
    const Image left = draw(&fromLeft);
    const Image right = draw(&fromRight);
    ASSERT_EQ(drawn, 1);
    ASSERT_GT(maxAbsDiff(left, right), 0) << "the light's side must show, or this tells nothing";
    direct.settings.light = fromLeft;
    renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
        drawn = direct.declare(view, f);
        direct.settings.light = fromRight;  // after declaring, before the passes run
    });
    EXPECT_EQ(maxAbsDiff(graph.readColor(), left), 0);
}

}  // namespace
}  // namespace fxtest
