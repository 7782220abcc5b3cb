// Fewer fragments for the same picture: trimmed billboards (a polygon per atlas frame instead of
// the quad) and the depth test on soft and spherical particles against a reversed-Z host.
//   - every point where the sampler can return alpha > 0 lies inside its frame's polygon, on every
//     mip level the polygon's LOD bucket admits, at several sprite rotations (exhaustive over
//     the texel grid);
//   - the polygons are convex, inside the quad, and leave a stated share of it out;
//   - trimmed and quad images are equal within 1/255 (hard and soft, rotations, near and far);
//   - depth-tested soft/spherical equal untested within 1/255 on a scene that hides some smoke.
#include <cmath>
#include <cstdio>

#include <stb/stb_image.h>

#include "FxTestHost.h"
#include "../../fx_plugin/render/EmbeddedResources.h"
#include "../../fx_plugin/render/ParticlePrograms.h"
#include "../../fx_plugin/render/SmokeAtlas.h"
#include "../../fx_plugin/render/TrimmedShapes.h"

namespace fxtest {
namespace {

struct AtlasPixels {
    int w = 0, h = 0, maxLevel = 0;
    std::vector<uint8_t> rgba;
};

// The embedded atlas, decoded as the renderer decodes it, with the renderer's mip-chain length.
AtlasPixels embeddedAtlas() {
    AtlasPixels a;
    const fx::embedded::Resource* r = fx::embedded::find(fx::SmokeAtlas::kFileName);
    if (!r) return a;
    int channels = 0;
    stbi_uc* p = stbi_load_from_memory(r->data, int(r->size), &a.w, &a.h, &channels, 4);
    if (!p) return a;
    a.rgba.assign(p, p + size_t(a.w) * size_t(a.h) * 4);
    stbi_image_free(p);
    for (int cell = std::min(a.w, a.h) / 2; cell > 8; cell /= 2) ++a.maxLevel;
    return a;
}

glm::vec2 rotate2(glm::vec2 v, float angle) {
    const float s = std::sin(angle), c = std::cos(angle);
    return {c * v.x - s * v.y, s * v.x + c * v.y};
}

TEST(TrimmedShapes, EverySampledTexelWithAlphaLiesInsideItsPolygonAtEveryRotation) {
    const AtlasPixels atlas = embeddedAtlas();
    ASSERT_GT(atlas.w, 0);
    fx::TrimmedShapes shapes;
    ASSERT_TRUE(shapes.compute(atlas.rgba.data(), atlas.w, atlas.h, atlas.maxLevel));
    ASSERT_EQ(shapes.buckets(), atlas.maxLevel + 1);
    const int cell = atlas.w / 2;
    // Texture-space points: every base-level texel centre of the cell and the midpoints between
    // them (the sampler's support changes at half-texel steps of level 0).
    const int steps = 2 * cell;
    long checked = 0, supported = 0;
    for (int f = 0; f < fx::TrimmedShapes::kFrames; ++f) {
        for (int b = 0; b < shapes.buckets(); ++b) {
            const auto& poly = shapes.polygon(f, b);
            const int n = shapes.vertexCount(f, b);
            ASSERT_GE(n, 3) << "frame " << f << " bucket " << b;
            const int topLevel = std::min(b, atlas.maxLevel);
            for (float angle : {0.0f, 0.4f, 1.3f, 2.9f, -2.2f}) {
                // The shader's transform: polygon corners turned by -angle into sprite space; a
                // texture point p sits at rotate2(p, -angle) in the same space.
                std::array<glm::vec2, fx::TrimmedShapes::kMaxVertices> turned{};
                for (int i = 0; i < fx::TrimmedShapes::kMaxVertices; ++i) turned[size_t(i)] = rotate2(poly[size_t(i)], -angle);
                for (int j = 0; j <= steps; ++j) {
                    for (int i = 0; i <= steps; ++i) {
                        const glm::vec2 p(-1.0f + 2.0f * float(i) / float(steps), -1.0f + 2.0f * float(j) / float(steps));
                        bool any = false;
                        for (int level = 0; level <= topLevel && !any; ++level) any = shapes.sampleSupport(f, level, p);
                        ++checked;
                        if (!any) continue;
                        ++supported;
                        // 1e-5 of the quad's half size: float rounding of the turned corners.
                        const glm::vec2 q = rotate2(p, -angle);
                        bool inside = true;
                        for (int v = 0; v < n && inside; ++v) {
                            const glm::vec2 a = turned[size_t(v)], c = turned[size_t((v + 1) % n)];
                            const glm::vec2 e = glm::normalize(c - a);
                            inside = e.x * (q.y - a.y) - e.y * (q.x - a.x) >= -1e-5f;
                        }
                        ASSERT_TRUE(inside) << "frame " << f << " bucket " << b << " angle " << angle
                                            << " point (" << p.x << ", " << p.y << ")";
                    }
                }
            }
        }
    }
    EXPECT_GT(supported, checked / 4) << "the atlas has almost nothing in it: the test would prove little";
}

TEST(TrimmedShapes, PolygonsAreConvexInsideTheQuadAndLeaveOutTheTransparentCorners) {
    const AtlasPixels atlas = embeddedAtlas();
    ASSERT_GT(atlas.w, 0);
    fx::TrimmedShapes shapes;
    ASSERT_TRUE(shapes.compute(atlas.rgba.data(), atlas.w, atlas.h, atlas.maxLevel));
    for (int f = 0; f < fx::TrimmedShapes::kFrames; ++f) {
        for (int b = 0; b < shapes.buckets(); ++b) {
            const auto& p = shapes.polygon(f, b);
            const int n = shapes.vertexCount(f, b);
            ASSERT_GE(n, 3);
            ASSERT_LE(n, fx::TrimmedShapes::kMaxVertices);
            for (int i = 0; i < n; ++i) {
                EXPECT_LE(std::fabs(p[size_t(i)].x), 1.0f);
                EXPECT_LE(std::fabs(p[size_t(i)].y), 1.0f);
                const glm::vec2 a = p[size_t(i)], c = p[size_t((i + 1) % n)], d = p[size_t((i + 2) % n)];
                EXPECT_GE((c.x - a.x) * (d.y - a.y) - (c.y - a.y) * (d.x - a.x), -1e-6f) << "not convex";
            }
            // Padding repeats the last vertex (zero-area fan triangles).
            for (int i = n; i < fx::TrimmedShapes::kMaxVertices; ++i) EXPECT_EQ(p[size_t(i)], p[size_t(n - 1)]);
            std::printf("[ measured ] frame %d bucket %d: %d vertices, %.3f of the quad\n", f, b, n,
                        double(shapes.areaShare(f, b)));
        }
        // The finest bucket must really trim: the frames' alpha covers 52-58 % of their cells.
        EXPECT_LT(shapes.areaShare(f, 0), 0.85f) << "frame " << f;
        // Coarser buckets only grow (they hold more mip levels).
        for (int b = 1; b < shapes.buckets(); ++b) EXPECT_GE(shapes.areaShare(f, b), shapes.areaShare(f, b - 1) - 1e-4f);
    }
}

TEST(TrimmedShapes, RejectsAtlasSizesItCannotSplit) {
    const uint8_t px[4 * 9] = {};
    fx::TrimmedShapes shapes;
    EXPECT_FALSE(shapes.compute(px, 3, 3, 0));
    EXPECT_TRUE(shapes.empty());
    EXPECT_FALSE(shapes.compute(nullptr, 2, 2, 0));
    // An atlas with nothing in a frame gives that frame no fragments at all.
    EXPECT_TRUE(shapes.compute(px, 2, 2, 0));
    EXPECT_EQ(shapes.vertexCount(0, 0), 0);
}

// --- images -----------------------------------------------------------------------------------

class TrimmedImageTest : public FxHostTest {
protected:
    Image draw(TestFrameGraph& graph, TestScene& scene, const fx::ViewInfo& view) {
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { drawn = direct.declare(view, f); });
        return graph.readColor();
    }
    // A reversed-Z scene with a wall that hides some of 9 soft particles, viewed as a
    // reversed-Z host (`tested`) and as a standard one (`untested`) with the same buffers.
    struct WallScene {
        TestScene scene;
        fx::ViewInfo tested, untested;
    };
    WallScene wallScene(int w, int h) {
        WallScene ws;
        ws.scene.reversedZ = true;
        ws.scene.quads = {TestScene::ground(60.0f, glm::vec3(0.2f, 0.22f, 0.2f)),
                          TestScene::wallZ(-1.0f, -1.5f, 1.5f, 0.0f, 2.0f, glm::vec3(0.5f, 0.3f, 0.3f))};
        ws.tested = makeView(glm::vec3(0.5f, 1.8f, 6), glm::vec3(0, 0.8f, -1), w, h);
        useReversedZ(&ws.tested);
        ws.untested = ws.tested;
        ws.untested.depth = fx::DepthConvention::Standard;
        std::vector<HandParticle> ps;
        for (int i = 0; i < 9; ++i) {
            HandParticle p;
            p.position = glm::vec3(-2.0f + 0.5f * float(i), 0.3f + 0.15f * float(i % 3), -2.5f + 0.6f * float(i));
            p.size = 1.4f + 0.2f * float(i % 4);
            p.frame = i % 4;
            p.rotation = 0.5f * float(i);
            ps.push_back(p);
        }
        direct.set(ps);
        direct.desc.render.softness = 0.5f;
        return ws;
    }

    TestHostAdapter host;
    DirectParticles direct{&host};
    int drawn = 0;
};

// Particles of every frame at several angles, near (large on screen, LOD < 0) and far (a few
// dozen pixels, coarse buckets), over a ground they cut into: trimmed equals quads, for the
// billboards' atlas polygons and for the spherical particles' octagons.
TEST_F(TrimmedImageTest, TrimmedShapesDrawTheQuadsImage) {
    constexpr int kW = 256, kH = 192;
    TestFrameGraph graph(kW, kH);
    TestScene scene;
    scene.quads = {TestScene::ground(80.0f, glm::vec3(0.25f, 0.3f, 0.25f))};
    const fx::ViewInfo view = makeView(glm::vec3(0, 2.5f, 9), glm::vec3(0, 1.0f, 0), kW, kH);
    direct.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(0.9f, 0.9f, 0.95f, 0.8f)}};
    std::vector<HandParticle> ps;
    const float angles[] = {0.0f, 0.7f, 2.1f, -1.2f};
    for (int i = 0; i < 16; ++i) {
        HandParticle p;
        p.frame = i % 4;
        p.rotation = angles[(i / 4) % 4];
        p.size = i < 8 ? 3.0f : 0.6f;
        p.position = i < 8 ? glm::vec3(-6.0f + 1.7f * float(i), 1.0f, 0.0f)
                           : glm::vec3(-14.0f + 3.5f * float(i - 8), 0.5f, -40.0f);
        ps.push_back(p);
    }
    direct.set(ps);
    for (fx::Technique t : {fx::Technique::Hard, fx::Technique::Soft, fx::Technique::Spherical}) {
        direct.options.techniqueOverride = t;
        direct.renderer.setParticleShape(fx::ParticleShape::Quad);
        const Image quads = draw(graph, scene, view);
        ASSERT_EQ(drawn, 16);
        direct.renderer.setParticleShape(fx::ParticleShape::Trimmed);
        const Image trimmed = draw(graph, scene, view);
        writePng(scratchDir() + "/trimmed_" + std::to_string(int(t)) + ".png", trimmed);
        EXPECT_LE(maxAbsDiff(trimmed, quads), 1) << "technique " << int(t);
        // Not vacuous: the smoke is in the picture.
        TestScene bare = scene;
        renderFrame(graph, bare, view, [](fx::FrameBuilder&) {});
        EXPECT_GT(maxAbsDiff(graph.readColor(), trimmed), 40);
    }
}

// A reversed-Z host with a 32-bit float z-buffer: soft and spherical particles are depth-tested
// there. Telling the plugin "standard" for the same buffers turns their test off (the projection
// is the host's either way), so the two pictures must agree: the test only drops fragments that
// shade to nothing.
TEST_F(TrimmedImageTest, DepthTestedSoftAndSphericalEqualUntested) {
    constexpr int kW = 200, kH = 150;
    TestFrameGraph graph(kW, kH, true);
    WallScene w = wallScene(kW, kH);
    TestScene& scene = w.scene;
    const fx::ViewInfo& tested = w.tested;
    const fx::ViewInfo& untested = w.untested;
    for (fx::Technique t : {fx::Technique::Soft, fx::Technique::Spherical}) {
        direct.options.techniqueOverride = t;
        const Image a = draw(graph, scene, tested);
        ASSERT_EQ(drawn, 9);
        const Image b = draw(graph, scene, untested);
        writePng(scratchDir() + "/depth_tested_" + std::to_string(int(t)) + ".png", a);
        EXPECT_LE(maxAbsDiff(a, b), 1) << "technique " << int(t);
    }
}

}  // namespace
}  // namespace fxtest

namespace fxtest {
namespace {

// The soft program without pow() takes contrast powers that are whole or half-whole numbers up
// to 16 (the schema allows 0.1 .. 16); anything else goes to the pow() program.
TEST(SoftContrastProgram, HalfWholePowersAreSplitAndOthersUsePow) {
    int whole = -1, half = -1;
    const struct { float p; int whole, half; } cases[] = {{1.0f, 1, 0}, {1.5f, 1, 1}, {2.0f, 2, 0}, {0.5f, 0, 1}, {16.0f, 16, 0}};
    for (const auto& c : cases) {
        ASSERT_TRUE(fx::ParticlePrograms::halfWholePower(c.p, &whole, &half)) << c.p;
        EXPECT_EQ(whole, c.whole) << c.p;
        EXPECT_EQ(half, c.half) << c.p;
        EXPECT_EQ(fx::ParticlePrograms::variantFor(fx::Technique::Soft, false, c.p), fx::ParticlePrograms::Soft);
    }
    for (float p : {0.1f, 1.3f, 2.25f, 15.9f}) {
        EXPECT_FALSE(fx::ParticlePrograms::halfWholePower(p, &whole, &half)) << p;
        EXPECT_EQ(fx::ParticlePrograms::variantFor(fx::Technique::Soft, false, p), fx::ParticlePrograms::SoftGeneralPower);
    }
    // Other techniques do not care.
    EXPECT_EQ(fx::ParticlePrograms::variantFor(fx::Technique::Hard, false, 1.3f), fx::ParticlePrograms::HardZBuffer);
}

}  // namespace
}  // namespace fxtest

namespace fxtest {
namespace {

// Quarter res on a reversed-Z host: the half-res particles are z-tested against the farthest
// scene depth of each 2x2 block. Against a standard host (no half-res z-test), with the same
// buffers and projection, the picture must be the same: the test only drops fragments that
// shade to nothing at half resolution.
TEST_F(TrimmedImageTest, HalfResZTestChangesNoPixel) {
    constexpr int kW = 200, kH = 150;
    TestFrameGraph graph(kW, kH, true);
    WallScene w = wallScene(kW, kH);
    TestScene& scene = w.scene;
    const fx::ViewInfo& tested = w.tested;
    const fx::ViewInfo& untested = w.untested;
    direct.options.quarterRes = true;
    for (fx::Technique t : {fx::Technique::Soft, fx::Technique::Spherical, fx::Technique::Hard}) {
        direct.options.techniqueOverride = t;
        const Image a = draw(graph, scene, tested);
        ASSERT_EQ(drawn, 9);
        ASSERT_TRUE(graph.ran("particles_quarter"));
        const Image b = draw(graph, scene, untested);
        EXPECT_LE(maxAbsDiff(a, b), 1) << "technique " << int(t);
        TestScene bare = scene;
        renderFrame(graph, bare, tested, [](fx::FrameBuilder&) {});
        EXPECT_GT(maxAbsDiff(graph.readColor(), a), 40) << "the smoke is in the picture";
    }
}

}  // namespace
}  // namespace fxtest
