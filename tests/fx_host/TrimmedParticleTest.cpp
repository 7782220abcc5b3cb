// Fewer fragments for the same picture: trimmed billboards (a polygon per atlas frame instead of
// the quad) and the depth test on soft and spherical particles against a reversed-Z host.
//   - every point where the sampler can return alpha > 0 lies inside its frame's polygon, on every
//     mip level the polygon's LOD bucket admits, at several sprite rotations (exhaustive over
//     the texel grid);
//   - the polygons are convex, inside the quad, and leave a stated share of it out;
//   - trimmed and quad images are equal within 1/255 (hard and soft, rotations, near and far);
//   - depth-tested soft/spherical equal untested within 1/255 on a scene that hides some smoke.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <filesystem>
#include <fstream>

#include <glad/gl.h>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <glm/gtc/matrix_transform.hpp>

#include "FxTestHost.h"
#include "../../fx_plugin/render/EmbeddedResources.h"
#include "../../fx_plugin/render/ProgramCache.h"
#include "../../fx_plugin/render/ScreenTiles.h"
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

/// v turned by the angle whose sine and cosine are s and c.
glm::vec2 rotate2(glm::vec2 v, float s, float c) { return {c * v.x - s * v.y, s * v.x + c * v.y}; }
glm::vec2 rotate2(glm::vec2 v, float angle) { return rotate2(v, std::sin(angle), std::cos(angle)); }

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
                // texture point p sits at rotate2(p, -angle) in the same space. Each edge's start
                // and direction once per angle (the same floats as worked out per point).
                std::array<glm::vec2, fx::TrimmedShapes::kMaxVertices> turned{}, edge{};
                for (int i = 0; i < fx::TrimmedShapes::kMaxVertices; ++i) turned[size_t(i)] = rotate2(poly[size_t(i)], -angle);
                for (int v = 0; v < n; ++v) edge[size_t(v)] = glm::normalize(turned[size_t((v + 1) % n)] - turned[size_t(v)]);
                const float sinA = std::sin(-angle), cosA = std::cos(-angle);  // rotate2(p, -angle)
                for (int j = 0; j <= steps; ++j) {
                    for (int i = 0; i <= steps; ++i) {
                        const glm::vec2 p(-1.0f + 2.0f * float(i) / float(steps), -1.0f + 2.0f * float(j) / float(steps));
                        bool any = false;
                        for (int level = 0; level <= topLevel && !any; ++level) any = shapes.sampleSupport(f, level, p);
                        ++checked;
                        if (!any) continue;
                        ++supported;
                        // 1e-5 of the quad's half size: float rounding of the turned corners.
                        const glm::vec2 q = rotate2(p, sinA, cosA);
                        bool inside = true;
                        for (int v = 0; v < n && inside; ++v) {
                            const glm::vec2 a = turned[size_t(v)], e = edge[size_t(v)];
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

// Spherical billboards: the lookup point o.xy / r lies inside the unit disc. Every point of the
// disc where the sampler can return alpha > 0 lies inside the frame's disc polygon, on every
// level its bucket admits (exhaustive over the half-texel grid; rotation turns the disc onto
// itself, so the sprite's angle does not matter here). The inradius the vertex shader grows the
// polygon by is the true distance from the centre to the nearest edge.
TEST(TrimmedShapes, DiscPolygonsHoldEverySampledTexelInsideTheUnitDisc) {
    const AtlasPixels atlas = embeddedAtlas();
    ASSERT_GT(atlas.w, 0);
    fx::TrimmedShapes shapes;
    ASSERT_TRUE(shapes.compute(atlas.rgba.data(), atlas.w, atlas.h, atlas.maxLevel));
    using Clip = fx::TrimmedShapes::Clip;
    const int steps = atlas.w;  // 2 * cell
    for (int f = 0; f < fx::TrimmedShapes::kFrames; ++f) {
        long supported = 0;  // over the disc, in bucket 0
        for (int b = 0; b < shapes.buckets(); ++b) {
            const auto& poly = shapes.polygon(f, b, Clip::Disc);
            const int n = shapes.vertexCount(f, b, Clip::Disc);
            ASSERT_GE(n, 3) << "frame " << f << " bucket " << b;
            ASSERT_LE(n, fx::TrimmedShapes::kMaxVertices);
            const int topLevel = std::min(b, atlas.maxLevel);
            for (int j = 0; j <= steps; ++j) {
                for (int i = 0; i <= steps; ++i) {
                    const glm::vec2 p(-1.0f + 2.0f * float(i) / float(steps), -1.0f + 2.0f * float(j) / float(steps));
                    if (glm::dot(p, p) >= 1.0f) continue;
                    bool any = false;
                    for (int level = 0; level <= topLevel && !any; ++level) any = shapes.sampleSupport(f, level, p);
                    if (!any) continue;
                    if (b == 0) ++supported;
                    ASSERT_TRUE(fx::TrimmedShapes::contains(poly, n, p))
                        << "frame " << f << " bucket " << b << " point (" << p.x << ", " << p.y << ")";
                }
            }
            // Convex and counter-clockwise; the inradius is the nearest edge's distance, rounded
            // down (never more: the shader grows the polygon by margin / inradius).
            double least = 1e30;
            for (int k = 0; k < n; ++k) {
                const glm::dvec2 a(poly[size_t(k)]), c(poly[size_t((k + 1) % n)]), d(poly[size_t((k + 2) % n)]);
                EXPECT_GE((c.x - a.x) * (d.y - a.y) - (c.y - a.y) * (d.x - a.x), -1e-6) << "not convex";
                least = std::min(least, (a.x * c.y - a.y * c.x) / glm::length(c - a));
            }
            const float r = shapes.inradius(f, b, Clip::Disc);
            EXPECT_GT(r, 0.05f) << "the puffs are centred: the centre lies well inside";
            EXPECT_LE(double(r), least);
            EXPECT_GE(double(r), least - 1e-6);
            std::printf("[ measured ] disc frame %d bucket %d: %d vertices, %.3f of the quad, inradius %.3f\n", f,
                        b, n, double(shapes.areaShare(f, b, Clip::Disc)), double(r));
        }
        // The finest bucket really trims: the octagon around the disc covers 0.83 of the quad.
        EXPECT_LT(shapes.areaShare(f, 0, Clip::Disc), 0.7f) << "frame " << f;
        // Every frame has a puff in it, or its polygons would prove little (the disc is 0.785 of
        // the grid's points).
        EXPECT_GT(supported, long(steps) * steps / 4) << "frame " << f;
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

// The billboards' reach table (ScreenTiles.h: BillboardReach) against the vertex shader's bucket
// rule, bucket = clamp(ceil(log2(t) + 0.5), 0, buckets - 1) for texels per pixel t, with t off
// by a relative 1e-6 either way (the GPU's rounding): the entry is never below half the farthest
// vertex of the polygon the shader picks, never above the quad's 0.71, and out-of-range frames
// take the largest of any frame.
TEST(TrimmedShapes, TheReachTableHoldsThePolygonTheShaderPicks) {
    const AtlasPixels atlas = embeddedAtlas();
    ASSERT_GT(atlas.w, 0);
    fx::TrimmedShapes shapes;
    ASSERT_TRUE(shapes.compute(atlas.rgba.data(), atlas.w, atlas.h, atlas.maxLevel));
    const fx::BillboardReach reach = fx::BillboardReach::of(shapes, 1.0f);
    ASSERT_EQ(reach.buckets, shapes.buckets());
    auto shaderBucket = [&](double t) {
        const double lod = std::log2(std::max(t, 1e-6));
        return std::min(std::max(int(std::ceil(lod + 0.5)), 0), shapes.buckets() - 1);
    };
    int checked = 0, exact = 0;
    float tightest = 1.0f, loosest = 0.0f;
    for (int f = 0; f < fx::TrimmedShapes::kFrames; ++f) {
        for (double t = 1e-4; t < 1e4; t *= 1.013) {
            const float entry = reach.at(float(f), float(t));
            for (double wobble : {1.0 - 1e-6, 1.0, 1.0 + 1e-6}) {
                const int b = shaderBucket(t * wobble);
                ASSERT_GE(entry, 0.5f * shapes.reach(f, b)) << "frame " << f << " t " << t;
                ++checked;
            }
            if (entry == 0.5f * shapes.reach(f, shaderBucket(t))) ++exact;
            EXPECT_LE(entry, 0.71f);
            EXPECT_GE(reach.at(-3.0f, float(t)), entry);
            EXPECT_GE(reach.at(std::nanf(""), float(t)), entry);
            EXPECT_GE(reach.at(9.0f, float(t)), entry);
            tightest = std::min(tightest, entry);
            loosest = std::max(loosest, entry);
        }
    }
    std::printf("[ measured ] billboard reach: %.3f to %.3f of the size (the quad's corners: 0.707), %d checks, "
                "%d of them the picked polygon's own reach\n",
                double(tightest), double(loosest), checked, exact);
    EXPECT_LT(tightest, 0.6f);
    // No polygons: no table.
    EXPECT_EQ(fx::BillboardReach::of(fx::TrimmedShapes(), 1.0f).lodScale, 0.0f);
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
    // `w` with technique `t` drawn as `tested` (the 9 particles drawn) and then as `untested`.
    struct WallPictures {
        Image tested, untested;
        bool testedRanQuarter = false;  ///< the tested frame ran the quarter-res particle pass
    };
    void drawTestedAndUntested(TestFrameGraph& graph, WallScene& w, fx::Technique t, WallPictures* out) {
        direct.settings.options.techniqueOverride = t;
        out->tested = draw(graph, w.scene, w.tested);
        ASSERT_EQ(drawn, 9);
        out->testedRanQuarter = graph.ran("particles_quarter");
        out->untested = draw(graph, w.scene, w.untested);
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
        direct.settings.options.techniqueOverride = t;
        direct.settings.shape = fx::ParticleShape::Quad;
        const Image quads = draw(graph, scene, view);
        ASSERT_EQ(drawn, 16);
        direct.settings.shape = fx::ParticleShape::Trimmed;
        const Image trimmed = draw(graph, scene, view);
        writePng(scratchDir() + "/trimmed_" + std::to_string(int(t)) + ".png", trimmed);
        EXPECT_LE(maxAbsDiff(trimmed, quads), 1) << "technique " << int(t);
        // Not vacuous: the smoke is in the picture.
        TestScene bare = scene;
        renderFrame(graph, bare, view, [](fx::FrameBuilder&) {});
        EXPECT_GT(maxAbsDiff(graph.readColor(), trimmed), 40);
    }
}

// Spherical billboards draw their frame's disc polygon, grown by the margins that carry it onto
// the screen (vs_particles.glsl, sphereTrimVertex). Across a 100-degree frustum, centre to
// corners, from spheres 3.4 degrees across (a few pixels: coarse LOD buckets) to 45 degrees
// (sin A 0.38, just inside the polygon's range) and 53 (0.45: the octagon or the box), at 4 m
// and 30 m, with every frame at both and many angles, at full and at quarter resolution, the
// trimmed picture equals the full box's within 1/255, but at a few pixels: the atlas is read from
// the nearest mip level, and where a pixel's level of detail sits at the middle between two, the
// polygon's other rounding may take the other level (measured: 2 pixels of 76,800, up to 12/255,
// with the 3.4-degree spheres). A polygon that missed part of a shape would lose whole pixels of
// opaque white (255/255), and many of them.
// A hard-edged atlas for them: opaque white shapes whose edge is where the alpha drops from 1 to 0
// (a small disc, a turned square, an off-centre blob, a triangle reaching past the unit disc), so
// a fragment the polygon misses costs a whole pixel of smoke, not the faint rim of a puff.
std::string writeHardEdgedAtlas() {
    constexpr int kSize = 256, kCell = kSize / 2;
    std::vector<uint8_t> px(size_t(kSize) * kSize * 4, 0);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const int f = (x / kCell) + 2 * (y / kCell);
            // Texture space of the cell: [-1, 1]^2, +y up.
            const float u = (float(x % kCell) + 0.5f) / kCell * 2.0f - 1.0f;
            const float v = 1.0f - (float(y % kCell) + 0.5f) / kCell * 2.0f;
            bool inside = false;
            if (f == 0) inside = u * u + v * v < 0.2f;
            if (f == 1) inside = std::fabs(u + v) < 1.0f && std::fabs(u - v) < 1.0f;
            if (f == 2) inside = (u - 0.25f) * (u - 0.25f) / 0.5f + (v + 0.1f) * (v + 0.1f) / 0.3f < 1.0f;
            if (f == 3) inside = v > -0.6f && v < 0.9f - 1.7f * std::fabs(u);
            uint8_t* p = &px[(size_t(y) * kSize + size_t(x)) * 4];
            p[0] = p[1] = p[2] = 255;
            p[3] = inside ? 255 : 0;
        }
    }
    const std::string dir = scratchDir() + "/hard_atlas";
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) return std::string();
    const std::string path = dir + "/" + fx::SmokeAtlas::kFileName;
    return stbi_write_png(path.c_str(), kSize, kSize, 4, px.data(), kSize * 4) ? dir : std::string();
}

// Opaque white spherical particles drawn with the hard-edged atlas over an empty scene.
class HardEdgedSphereTest : public TrimmedImageTest {
protected:
    static constexpr int kW = 320, kH = 240;
    HardEdgedSphereTest() {
        hardEdged.desc.particle.colorRamp = {fx::ColorStop{0.0f, glm::vec4(1.0f)}};
        hardEdged.settings.options.techniqueOverride = fx::Technique::Spherical;
    }
    Image drawHardEdged(const fx::ViewInfo& v) {
        renderFrame(graph, scene, v, [&](fx::FrameBuilder& f) { drawn = hardEdged.declare(v, f); });
        return graph.readColor();
    }

    TestFrameGraph graph{kW, kH};
    TestScene scene;
    const std::string atlasDir = writeHardEdgedAtlas();
    DirectParticles hardEdged{&host, std::string(), atlasDir};
};

TEST_F(HardEdgedSphereTest, SphericalPolygonsDrawTheQuadsImageAcrossTheFrustum) {
    ASSERT_FALSE(atlasDir.empty());
    fx::ViewInfo view = makeView(glm::vec3(0.0f), glm::vec3(0, 0, -1), kW, kH);
    view.proj = glm::perspective(glm::radians(100.0f), float(kW) / float(kH), view.nearPlane, view.farPlane);
    const glm::mat4 toWorld = glm::inverse(view.view);
    const float halfY = glm::radians(50.0f), halfX = std::atan(std::tan(halfY) * kW / kH);
    for (bool quarter : {false, true}) {
        hardEdged.settings.options.quarterRes = quarter;
        hardEdged.settings.options.quarterResAlways = quarter;
        for (float sinA : {0.03f, 0.1f, 0.22f, 0.38f, 0.45f}) {
            const float a = std::asin(sinA), step = 2.3f * a;
            std::vector<HandParticle> ps;
            for (float ay = -halfY + a; ay <= halfY - 0.2f * a; ay += step) {
                for (float ax = -halfX + a; ax <= halfX - 0.2f * a; ax += step) {
                    const int i = int(ps.size());
                    const float dist = (i % 2) ? 30.0f : 4.0f;
                    const glm::vec3 dir = glm::normalize(glm::vec3(std::tan(ax), std::tan(ay), -1.0f));
                    HandParticle p;
                    p.position = glm::vec3(toWorld * glm::vec4(dir * dist, 1.0f));
                    p.size = 2.0f * sinA * dist;
                    p.frame = (i / 2) % 4;
                    p.rotation = 0.9f * float(i % 7);
                    ps.push_back(p);
                }
            }
            ASSERT_GE(ps.size(), 4u);
            hardEdged.set(ps);
            hardEdged.settings.shape = fx::ParticleShape::Quad;
            const Image quads = drawHardEdged(view);
            ASSERT_EQ(drawn, int(ps.size()));
            hardEdged.settings.shape = fx::ParticleShape::Trimmed;
            const Image trimmed = drawHardEdged(view);
            writePng(scratchDir() + "/spherical_trimmed_" + std::to_string(int(sinA * 100)) +
                         (quarter ? "_quarter" : "") + ".png", trimmed);
            int beyondOne = 0;  // pixels whose largest channel difference exceeds 1/255
            for (size_t i = 0; i < trimmed.rgba.size(); i += 4) {
                int d = 0;
                for (size_t c = 0; c < 3; ++c) d = std::max(d, std::abs(int(trimmed.rgba[i + c]) - int(quads.rgba[i + c])));
                beyondOne += d > 1 ? 1 : 0;
            }
            EXPECT_LE(beyondOne, 4) << "sin A " << sinA << ", " << ps.size() << " spheres"
                                    << (quarter ? ", quarter res" : "");
            EXPECT_LE(maxAbsDiff(trimmed, quads), 16) << "sin A " << sinA << ", " << ps.size() << " spheres"
                                                      << (quarter ? ", quarter res" : "");
            ASSERT_EQ(graph.ran("particles_quarter"), quarter);
            // Not vacuous: the smoke is in the picture.
            TestScene bare = scene;
            renderFrame(graph, bare, view, [](fx::FrameBuilder&) {});
            EXPECT_GT(maxAbsDiff(graph.readColor(), trimmed), 100) << "sin A " << sinA;
        }
    }
}

// The polygon path really runs: spheres whose frame (0 of the hard-edged atlas) holds a disc of
// 0.45 of the radius shade far fewer fragments than their outline. Counted as fragment shader
// invocations (ARB_pipeline_statistics_query): the spherical shader discards what blends zero, so
// GL_SAMPLES_PASSED sees only the puff, whatever bound drew it; the invocations are every
// fragment the rasteriser hands the shader, and the box and the octagon around the outline would
// hand it all of the outline.
TEST_F(HardEdgedSphereTest, SphericalPolygonLeavesOutTheOutlineAroundASmallPuff) {
    ASSERT_FALSE(atlasDir.empty());
    if (!GLAD_GL_ARB_pipeline_statistics_query) {
        GTEST_SKIP() << "counting the fragments shaded needs ARB_pipeline_statistics_query (llvmpipe has it)";
    }
    const fx::ViewInfo view = makeView(glm::vec3(0.0f), glm::vec3(0, 0, -1), kW, kH);
    const glm::mat4 toWorld = glm::inverse(view.view);
    std::vector<HandParticle> ps;
    for (int i = 0; i < 12; ++i) {
        HandParticle p;
        const glm::vec3 dir = glm::normalize(glm::vec3(-0.5f + 0.33f * float(i % 4), -0.3f + 0.3f * float(i / 4), -1.0f));
        p.position = glm::vec3(toWorld * glm::vec4(dir * 10.0f, 1.0f));
        p.size = 2.0f;  // sin A 0.1
        p.frame = 0;
        p.rotation = 0.5f * float(i);
        ps.push_back(p);
    }
    hardEdged.set(ps);
    const auto samples = [&](bool particles) {
        GLuint query = 0;
        glGenQueries(1, &query);
        glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, query);
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
            if (particles) drawn = hardEdged.declare(view, f);
        });
        glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
        GLuint n = 0;
        glGetQueryObjectuiv(query, GL_QUERY_RESULT, &n);
        glDeleteQueries(1, &query);
        return double(n);
    };
    const double bare = samples(false);
    hardEdged.settings.shape = fx::ParticleShape::Quad;
    const double box = samples(true) - bare;
    ASSERT_EQ(drawn, 12);
    hardEdged.settings.shape = fx::ParticleShape::Trimmed;
    const double polygon = samples(true) - bare;
    std::printf("[ measured ] spherical fragments: box %.0f, polygon %.0f (%.3f)\n", box, polygon, polygon / box);
    // The outline is 12 discs of about 24 px radius. The puff's disc is 0.2 of the outline's area;
    // these spheres (48 px across a 128-texel cell) take LOD bucket 3, whose support reaches
    // 0.25 of the radius further (mip texels of 8 base texels, and their bilinear reach), so the
    // polygon holds about half the outline (0.54 of its samples, counted before the shader
    // discarded what blends zero). The octagon holds all of it. In invocations llvmpipe counts
    // whole 4x4 blocks per triangle, the box's two and the polygon's six: 0.29 of the box here.
    EXPECT_GT(box, 12 * 3.14159 * 22.0 * 22.0);
    EXPECT_LT(polygon, 0.7 * box);
    EXPECT_GT(polygon, 0.15 * box) << "the puff itself is drawn";
}

// A reversed-Z host with a 32-bit float z-buffer: soft and spherical particles are depth-tested
// there. Telling the plugin "standard" for the same buffers turns their test off (the projection
// is the host's either way), so the two pictures must agree: the test only drops fragments that
// shade to nothing.
// Each trimmed billboard drawn alone at full res over a black scene, with a hard fragment shader
// that writes white wherever it runs: every fragment the polygon rasterises lies inside the rect
// screenRect gives it from its reach (BillboardReach, at the renderer's LOD scale for the view),
// for particles of every frame and angle from 0.4 m to 300 m away, from a few pixels to more than
// the view across; the rect is smaller than the quad's box for most, the overdraw estimate
// (footprintPixels, the quads' boxes) the same bit for bit.
class TrimmedBoundTest : public FxHostTest {};

TEST_F(TrimmedBoundTest, NoFragmentOfATrimmedBillboardLiesOutsideItsReachBound) {
    const std::string shaders = scratchDir() + "/every_fragment_white";
    std::error_code ec;
    std::filesystem::remove_all(shaders, ec);
    std::filesystem::copy(CUBE_SOURCE_DIR "/shaders", shaders, ec);
    ASSERT_FALSE(ec) << ec.message();
    {
        std::ofstream fs(shaders + "/fs_particles_hard.glsl");
        fs << "#version 330 core\nlayout(location = 0) out vec4 oColor;\nvoid main() { oColor = vec4(1.0); }\n";
    }
    TestHostAdapter host;
    DirectParticles direct(&host, shaders);
    direct.settings.options.techniqueOverride = fx::Technique::Hard;
    constexpr int kW = 192, kH = 144;
    TestFrameGraph graph(kW, kH);
    TestScene scene;
    scene.sky = glm::vec3(0.0f);
    const fx::ViewInfo view = makeView(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), kW, kH, 0.1f, 1000.0f);
    const AtlasPixels atlas = embeddedAtlas();
    ASSERT_GT(atlas.w, 0);
    fx::TrimmedShapes shapes;
    ASSERT_TRUE(shapes.compute(atlas.rgba.data(), atlas.w, atlas.h, atlas.maxLevel));
    fx::BillboardReach reach = fx::BillboardReach::of(shapes, 1.0f);
    reach.lodScale = float(atlas.w / 2) * 2.0f / (std::fabs(view.proj[1][1]) * float(kH));  // ParticleDraw's
    int particles = 0, tighter = 0, fragments = 0, worstSlack = 1 << 20;
    double reachArea = 0.0, boxArea = 0.0;
    for (int i = 0; i < 96; ++i) {
        const float distance = 0.4f * std::pow(750.0f, float(i % 24) / 23.0f);
        const float size = distance * (0.02f + 0.9f * float((i * 7) % 11) / 10.0f) * (i % 5 == 0 ? 0.15f : 1.0f);
        HandParticle p;
        p.position = glm::vec3(0.3f * distance * std::sin(float(i)), 0.2f * distance * std::cos(1.3f * float(i)), -distance);
        p.size = size;
        p.rotation = 0.37f * float(i);
        p.frame = i % 4;
        direct.set({p});
        int drawn = 0;
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) { drawn = direct.declare(view, f); });
        ASSERT_EQ(drawn, 1);
        const Image image = graph.readColor();
        const fx::ParticleInstance instance{p.position.x, p.position.y, p.position.z, p.size, p.life, p.rotation,
                                            p.fade, float(p.frame)};
        const fx::ScreenRect rect = fx::screenRect(view, &instance, 1, nullptr, fx::Footprint::Billboard, fx::Jobs(), &reach);
        const fx::ScreenRect box = fx::screenRect(view, &instance, 1, nullptr, fx::Footprint::Billboard);
        ASSERT_EQ(rect.whole && !rect.x0 && !rect.y0 && rect.x1 == kW && rect.y1 == kH, box.whole || rect.whole)
            << "particle " << i;
        EXPECT_EQ(rect.footprintPixels, box.footprintPixels) << "particle " << i;
        int outside = 0, drawnPixels = 0;
        int fx0 = kW, fx1 = 0, fy0 = kH, fy1 = 0;
        for (int y = 0; y < kH; ++y) {
            for (int x = 0; x < kW; ++x) {
                if (image.at(x, y)[0] == 0) continue;
                ++drawnPixels;
                fx0 = std::min(fx0, x);
                fx1 = std::max(fx1, x + 1);
                fy0 = std::min(fy0, y);
                fy1 = std::max(fy1, y + 1);
                if (x < rect.x0 || x >= rect.x1 || y < rect.y0 || y >= rect.y1) ++outside;
            }
        }
        EXPECT_EQ(outside, 0) << "particle " << i << " at " << distance << " m, size " << size << " m, frame "
                              << p.frame << ": " << outside << " of " << drawnPixels << " fragments outside";
        if (drawnPixels == 0) continue;
        ++particles;
        fragments += drawnPixels;
        // How close the bound comes to the fragments on its nearest side, where the view does
        // not clip it (the rect's one pixel of slack included).
        if (rect.x0 > 0) worstSlack = std::min(worstSlack, fx0 - rect.x0);
        if (rect.x1 < kW) worstSlack = std::min(worstSlack, rect.x1 - fx1);
        if (rect.y0 > 0) worstSlack = std::min(worstSlack, fy0 - rect.y0);
        if (rect.y1 < kH) worstSlack = std::min(worstSlack, rect.y1 - fy1);
        const double a = double(rect.x1 - rect.x0) * double(rect.y1 - rect.y0);
        const double b = double(box.x1 - box.x0) * double(box.y1 - box.y0);
        reachArea += a;
        boxArea += b;
        if (a < b) ++tighter;
    }
    std::printf("[ measured ] %d trimmed billboards, %d fragments: reach rects %.0f px against the quads' boxes "
                "%.0f px (%.2f), smaller for %d; closest bound to a fragment %d px\n",
                particles, fragments, reachArea, boxArea, reachArea / std::max(boxArea, 1.0), tighter, worstSlack);
    EXPECT_GT(particles, 80);
    EXPECT_GT(tighter, particles / 2);
}

TEST_F(TrimmedImageTest, DepthTestedSoftAndSphericalEqualUntested) {
    constexpr int kW = 200, kH = 150;
    TestFrameGraph graph(kW, kH, true);
    WallScene w = wallScene(kW, kH);
    for (fx::Technique t : {fx::Technique::Soft, fx::Technique::Spherical}) {
        WallPictures p;
        ASSERT_NO_FATAL_FAILURE(drawTestedAndUntested(graph, w, t, &p));
        writePng(scratchDir() + "/depth_tested_" + std::to_string(int(t)) + ".png", p.tested);
        EXPECT_LE(maxAbsDiff(p.tested, p.untested), 1) << "technique " << int(t);
    }
}

// The soft program without pow() takes contrast powers that are whole or half-whole numbers up
// to 16 (the schema allows 0.1 .. 16); anything else goes to the pow() program.
TEST(SoftContrastProgram, HalfWholePowersAreSplitAndOthersUsePow) {
    int whole = -1, half = -1;
    const struct { float p; int whole, half; } cases[] = {{1.0f, 1, 0}, {1.5f, 1, 1}, {2.0f, 2, 0}, {0.5f, 0, 1}, {16.0f, 16, 0}};
    for (const auto& c : cases) {
        ASSERT_TRUE(fx::ProgramCache::halfWholePower(c.p, &whole, &half)) << c.p;
        EXPECT_EQ(whole, c.whole) << c.p;
        EXPECT_EQ(half, c.half) << c.p;
        EXPECT_EQ(fx::ProgramCache::variantFor(fx::Technique::Soft, false, c.p), fx::ProgramCache::Soft);
    }
    for (float p : {0.1f, 1.3f, 2.25f, 15.9f}) {
        EXPECT_FALSE(fx::ProgramCache::halfWholePower(p, &whole, &half)) << p;
        EXPECT_EQ(fx::ProgramCache::variantFor(fx::Technique::Soft, false, p), fx::ProgramCache::SoftGeneralPower);
    }
    // Other techniques do not care.
    EXPECT_EQ(fx::ProgramCache::variantFor(fx::Technique::Hard, false, 1.3f), fx::ProgramCache::HardZBuffer);
}

// Quarter res on a reversed-Z host: the half-res particles are z-tested against the farthest
// scene depth of each 2x2 block. Against a standard host (no half-res z-test), with the same
// buffers and projection, the picture must be the same: the test only drops fragments that
// shade to nothing at half resolution.
TEST_F(TrimmedImageTest, HalfResZTestChangesNoPixel) {
    constexpr int kW = 200, kH = 150;
    TestFrameGraph graph(kW, kH, true);
    WallScene w = wallScene(kW, kH);
    direct.settings.options.quarterRes = true;
    direct.settings.options.quarterResAlways = true;
    for (fx::Technique t : {fx::Technique::Soft, fx::Technique::Spherical, fx::Technique::Hard}) {
        WallPictures p;
        ASSERT_NO_FATAL_FAILURE(drawTestedAndUntested(graph, w, t, &p));
        ASSERT_TRUE(p.testedRanQuarter);
        EXPECT_LE(maxAbsDiff(p.tested, p.untested), 1) << "technique " << int(t);
        TestScene bare = w.scene;
        renderFrame(graph, bare, w.tested, [](fx::FrameBuilder&) {});
        EXPECT_GT(maxAbsDiff(graph.readColor(), p.tested), 40) << "the smoke is in the picture";
    }
}

}  // namespace
}  // namespace fxtest
