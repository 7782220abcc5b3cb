// ScreenTiles.h: screenRect's tile runs (the cover the quarter-res downsample, half-res z-fill,
// edge mask and composite are drawn on): they must hold every pixel a particle can change plus
// the upsample's reach, stay inside the view, never overlap, and leave smoke-free tiles out.
// CPU only: no GL context.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render/FootprintMath.h"
#include "render/ScreenTiles.h"
#include "render/TileBins.h"

namespace fx {
namespace {

constexpr int kW = 320, kH = 240;

ViewInfo testView() {
    ViewInfo v;
    v.width = kW;
    v.height = kH;
    v.nearPlane = 0.1f;
    v.farPlane = 500.0f;
    v.eye = glm::vec3(0.0f, 1.5f, 6.0f);
    v.view = glm::lookAt(v.eye, glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    v.proj = glm::perspective(glm::radians(60.0f), float(kW) / float(kH), v.nearPlane, v.farPlane);
    return v;
}

// The runs as a per-pixel count (0, 1, or more where runs overlap), from the vertex list: each
// run is two triangles, the first one's corners (x0, y0), (x1, y0), (x1, y1).
std::vector<int> rasterise(const ScreenTiles& tiles, bool* insideView) {
    std::vector<int> count(size_t(kW * kH), 0);
    *insideView = true;
    for (int r = 0; r < tiles.runs(); ++r) {
        const float* v = tiles.vertices.data() + r * 12;
        const int x0 = int(v[0]), y0 = int(v[1]), x1 = int(v[4]), y1 = int(v[5]);
        if (x0 < 0 || y0 < 0 || x1 > kW || y1 > kH || x0 >= x1 || y0 >= y1) *insideView = false;
        for (int y = std::max(0, y0); y < std::min(kH, y1); ++y) {
            for (int x = std::max(0, x0); x < std::min(kW, x1); ++x) ++count[size_t(y * kW + x)];
        }
    }
    return count;
}

// One particle at (0, 1, 0), in front of testView()'s camera, of edge `size`.
ParticleInstance centredParticle(float size) {
    ParticleInstance p;
    p.x = 0.0f;
    p.y = 1.0f;
    p.z = 0.0f;
    p.size = size;
    return p;
}

// A billboard's pixel bound, computed independently of the renderer: its four view-plane
// corners at 0.71 size from the centre (vs_particles.glsl: a rotated unit square's corners lie
// within 0.5 sqrt(2) size), projected.
void billboardBound(const ViewInfo& view, const ParticleInstance& p, float* x0, float* y0, float* x1, float* y1) {
    const glm::vec4 c = view.view * glm::vec4(p.x, p.y, p.z, 1.0f);
    *x0 = *y0 = 1e30f;
    *x1 = *y1 = -1e30f;
    for (int k = 0; k < 4; ++k) {
        const float r = 0.5f * std::sqrt(2.0f) * p.size;
        const glm::vec4 q = c + glm::vec4(k & 1 ? r : -r, k & 2 ? r : -r, 0.0f, 0.0f);
        const glm::vec4 clip = view.proj * q;
        const float px = (clip.x / clip.w * 0.5f + 0.5f) * kW, py = (clip.y / clip.w * 0.5f + 0.5f) * kH;
        *x0 = std::min(*x0, px);
        *x1 = std::max(*x1, px);
        *y0 = std::min(*y0, py);
        *y1 = std::max(*y1, py);
    }
}

TEST(ScreenTiles, EveryPixelNearAParticleIsCoveredOnceAndRunsStayInsideTheView) {
    const ViewInfo view = testView();
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> across(-4.0f, 4.0f), up(0.0f, 3.0f), deep(-30.0f, 2.0f), size(0.05f, 2.5f);
    for (int trial = 0; trial < 40; ++trial) {
        std::vector<ParticleInstance> particles(1 + trial % 12);
        for (ParticleInstance& p : particles) {
            p.x = across(rng);
            p.y = up(rng);
            p.z = deep(rng);
            p.size = size(rng);
        }
        ScreenTiles tiles;
        const ScreenRect rect = screenRect(
            view, particles.data(), int(particles.size()), &tiles, Footprint::Billboard);
        if (rect.whole && tiles.runs() == 1) continue;  // one reached the near plane: checked below
        bool insideView = false;
        const std::vector<int> count = rasterise(tiles, &insideView);
        ASSERT_TRUE(insideView) << "trial " << trial;
        int64_t covered = 0;
        for (int c : count) {
            ASSERT_LE(c, 1) << "overlapping runs would composite a pixel twice, trial " << trial;
            covered += c;
        }
        EXPECT_EQ(covered, tiles.pixels) << "trial " << trial;
        // Every pixel within 4 px of a particle's bound is covered: the composite's bilinear
        // footprint reaches 2 px, and the half-res texels it reads hold smoke from 2 px further.
        for (const ParticleInstance& p : particles) {
            float x0, y0, x1, y1;
            billboardBound(view, p, &x0, &y0, &x1, &y1);
            const float b = 4.0f;
            for (int y = std::max(0, int(std::floor(y0 - b))); y < std::min(kH, int(std::ceil(y1 + b))); ++y) {
                for (int x = std::max(0, int(std::floor(x0 - b))); x < std::min(kW, int(std::ceil(x1 + b))); ++x) {
                    ASSERT_EQ(count[size_t(y * kW + x)], 1)
                        << "pixel " << x << "," << y << " next to a particle is not covered, trial " << trial;
                }
            }
        }
    }
}

TEST(ScreenTiles, OneSmallParticleCoversOnlyItsOwnTiles) {
    const ViewInfo view = testView();
    const ParticleInstance p = centredParticle(0.3f);
    ScreenTiles tiles;
    screenRect(view, &p, 1, &tiles, Footprint::Billboard);
    float x0, y0, x1, y1;
    billboardBound(view, p, &x0, &y0, &x1, &y1);
    // At most the bound grown by the border, rounded out to whole tiles on each side.
    const float t = float(ScreenTiles::kTileSize), b = float(ScreenTiles::kTileBorder);
    const float w = (std::ceil((x1 + b) / t) - std::floor((x0 - b) / t)) * t;
    const float h = (std::ceil((y1 + b) / t) - std::floor((y0 - b) / t)) * t;
    EXPECT_GT(tiles.pixels, 0);
    EXPECT_LE(double(tiles.pixels), double(w) * h);
    EXPECT_LT(double(tiles.pixels), 0.1 * kW * kH) << "a 0.3 m puff 6 m away covers a small part of the view";
}

TEST(ScreenTiles, BillboardBoundIsInsideTheBoxBound) {
    const ViewInfo view = testView();
    std::vector<ParticleInstance> particles(3);
    particles[0].z = -2.0f, particles[0].size = 2.0f, particles[0].y = 1.0f;
    particles[1].x = 2.0f, particles[1].z = -10.0f, particles[1].size = 1.0f;
    particles[2].x = -3.0f, particles[2].y = 2.0f, particles[2].size = 0.5f;
    ScreenTiles billboard, box;
    screenRect(view, particles.data(), 3, &billboard, Footprint::Billboard);
    screenRect(view, particles.data(), 3, &box, Footprint::Box);
    bool inside = false;
    const std::vector<int> a = rasterise(billboard, &inside), b = rasterise(box, &inside);
    for (size_t i = 0; i < a.size(); ++i) ASSERT_LE(a[i], b[i]) << "pixel " << i;
    EXPECT_LT(billboard.pixels, box.pixels) << "the 2 m puff 8 m away has depth the box counts";
}

TEST(ScreenTiles, NearPlaneGivesTheWholeViewAndNothingInFrontGivesNoRuns) {
    const ViewInfo view = testView();
    const glm::vec3 forward = glm::normalize(glm::vec3(0.0f, 1.0f, 0.0f) - view.eye);
    auto at = [&](float distance, float size) {
        ParticleInstance p;
        const glm::vec3 c = view.eye + distance * forward;
        p.x = c.x, p.y = c.y, p.z = c.z, p.size = size;
        return p;
    };
    // A box 0.15 m ahead with half-size 0.355 m straddles the 0.1 m near plane: the whole view.
    ParticleInstance straddling = at(0.15f, 0.5f);
    ScreenTiles tiles;
    ScreenRect rect =
        screenRect(view, &straddling, 1, &tiles, Footprint::Box);
    EXPECT_TRUE(rect.whole);
    ASSERT_EQ(tiles.runs(), 1);
    EXPECT_EQ(tiles.pixels, int64_t(kW) * kH);
    // A non-finite position: no bound to trust, the whole view.
    ParticleInstance broken = at(3.0f, 0.5f);
    broken.y = std::nanf("");
    rect = screenRect(view, &broken, 1, &tiles, Footprint::Billboard);
    EXPECT_TRUE(rect.whole);
    EXPECT_EQ(tiles.pixels, int64_t(kW) * kH);
    // A billboard lies in one plane: 0.05 m ahead it is wholly clipped by the near plane, and one
    // behind the eye is too. Neither touches the screen.
    for (float distance : {0.05f, -5.0f}) {
        ParticleInstance hidden = at(distance, 0.5f);
        rect = screenRect(view, &hidden, 1, &tiles, Footprint::Billboard);
        EXPECT_FALSE(rect.whole) << distance;
        EXPECT_EQ(rect.x0, rect.x1) << distance;
        EXPECT_EQ(tiles.runs(), 0) << distance;
        EXPECT_EQ(tiles.pixels, 0) << distance;
    }
}

// The rect against the footprint's corners projected one by one (the box: 8 corners, the
// billboard: 4), under a symmetric perspective, an off-centre one, an infinite reversed-Z one
// (whose bound the renderer takes from two depths instead of eight corners) and an orthographic
// projection (which takes the corners): equal to the pixel, the rect's one pixel of slack included.
TEST(ScreenTiles, TheRectIsTheBoundOfTheProjectedCorners) {
    ViewInfo base = testView();
    glm::mat4 reversedInfinite(0.0f);
    {
        const float f = 1.0f / std::tan(glm::radians(30.0f));
        reversedInfinite[0][0] = f / (float(kW) / float(kH));
        reversedInfinite[1][1] = f;
        reversedInfinite[2][3] = -1.0f;
        reversedInfinite[3][2] = base.nearPlane;
    }
    const glm::mat4 projections[4] = {
        base.proj, glm::frustum(-0.02f, 0.1f, -0.05f, 0.04f, base.nearPlane, base.farPlane), reversedInfinite,
        glm::ortho(-8.0f, 8.0f, -6.0f, 6.0f, base.nearPlane, base.farPlane)};
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int compared[4] = {0, 0, 0, 0};
    for (int pi = 0; pi < 4; ++pi) {
        ViewInfo view = base;
        view.proj = projections[pi];
        for (int fp = 0; fp < 2; ++fp) {
            const Footprint footprint = fp ? Footprint::Box : Footprint::Billboard;
            for (int trial = 0; trial < 50; ++trial) {
                std::vector<ParticleInstance> particles(3);
                float lo[2] = {1e30f, 1e30f}, hi[2] = {-1e30f, -1e30f};
                bool clipped = false;
                for (ParticleInstance& p : particles) {
                    p.x = 2.0f * u(rng);
                    p.y = 1.0f + u(rng);
                    p.z = -2.0f + 2.0f * u(rng);
                    p.size = 0.6f + 0.5f * u(rng);
                    const glm::vec3 c(view.view * glm::vec4(p.x, p.y, p.z, 1.0f));
                    const float r = 0.71f * p.size, e = fp ? r : 0.0f;
                    if (c.z + e >= -view.nearPlane) clipped = true;
                    for (int k = 0; k < 8; ++k) {
                        const glm::vec4 clip = view.proj * glm::vec4(c.x + (k & 1 ? r : -r), c.y + (k & 2 ? r : -r),
                                                                     c.z + (k & 4 ? e : -e), 1.0f);
                        for (int a = 0; a < 2; ++a) {
                            lo[a] = std::min(lo[a], clip[a] / clip.w);
                            hi[a] = std::max(hi[a], clip[a] / clip.w);
                        }
                    }
                }
                if (clipped) continue;  // the whole view: tested elsewhere
                const ScreenRect rect = screenRect(view, particles.data(), 3, nullptr, footprint);
                const int x0 = std::max(0, int(std::floor((lo[0] * 0.5f + 0.5f) * kW)) - 1);
                const int y0 = std::max(0, int(std::floor((lo[1] * 0.5f + 0.5f) * kH)) - 1);
                const int x1 = std::min(kW, int(std::ceil((hi[0] * 0.5f + 0.5f) * kW)) + 1);
                const int y1 = std::min(kH, int(std::ceil((hi[1] * 0.5f + 0.5f) * kH)) + 1);
                if (x1 <= x0 || y1 <= y0) continue;  // off screen
                // Rounding may move an edge that lands on a pixel boundary by one pixel, never more.
                EXPECT_NEAR(rect.x0, x0, 1) << pi << " " << fp << " " << trial;
                EXPECT_NEAR(rect.y0, y0, 1) << pi << " " << fp << " " << trial;
                EXPECT_NEAR(rect.x1, x1, 1) << pi << " " << fp << " " << trial;
                EXPECT_NEAR(rect.y1, y1, 1) << pi << " " << fp << " " << trial;
                ++compared[pi];
            }
        }
        EXPECT_GT(compared[pi], 60) << "projection " << pi << ": too few bounds on screen to compare";
    }
}

// The overdraw estimate behind the quarter-res choice: one particle adds its clipped box, a stack
// of them on one spot adds up while the tiles stay those of one, and a particle at the near plane
// makes the bound unbounded (quarter res pays: it may cover the view).
TEST(ScreenTiles, FootprintPixelsAddUpAndDecideQuarterRes) {
    const ViewInfo view = testView();
    const ParticleInstance p = centredParticle(0.5f);
    float x0, y0, x1, y1;
    billboardBound(view, p, &x0, &y0, &x1, &y1);
    const double box = double(x1 - x0) * double(y1 - y0);
    ScreenTiles tiles;
    const ScreenRect one = screenRect(view, &p, 1, &tiles, Footprint::Billboard);
    EXPECT_NEAR(one.footprintPixels, box, 0.01 * box);
    const int64_t oneTiles = tiles.pixels;
    EXPECT_FALSE(quarterResPays(one, tiles)) << "one particle never pays for the composite";

    const std::vector<ParticleInstance> stack(40, p);
    const ScreenRect many = screenRect(view, stack.data(), 40, &tiles, Footprint::Billboard);
    EXPECT_NEAR(many.footprintPixels, 40.0 * box, 0.4 * box);
    EXPECT_EQ(tiles.pixels, oneTiles);
    EXPECT_EQ(quarterResPays(many, tiles), 40.0 * box >= kQuarterResMinOverdraw * double(oneTiles));
    const std::vector<ParticleInstance> deep(400, p);
    EXPECT_TRUE(quarterResPays(screenRect(view, deep.data(), 400, &tiles, Footprint::Billboard), tiles));

    ParticleInstance close = p;
    close.y = view.eye.y;
    close.z = view.eye.z - 0.3f;  // its box (0.35 m deep each way) reaches the near plane
    const ScreenRect near = screenRect(view, &close, 1, &tiles, Footprint::Box);
    EXPECT_TRUE(near.whole);
    EXPECT_TRUE(std::isinf(near.footprintPixels));
    EXPECT_TRUE(quarterResPays(near, tiles));
}

// Particles for the four-lane tests: ordinary ones and extreme ones (not a number or infinite in
// each component, at and behind the near plane, at the eye with -0 and +0, sizes 0, negative,
// tiny and huge, frames out of range), in front of testView()'s camera at (0, 1.5, 6) and around it.
std::vector<ParticleInstance> oddParticles(int count, bool finite) {
    std::mt19937 rng(29);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<ParticleInstance> particles;
    for (int i = 0; i < count; ++i) {
        ParticleInstance p;
        // Finite: 6-66 m ahead, at most 8 m across, so no sphere reaches the near plane and the
        // bound is not the whole view. Else around the eye at z 6 too, up to 64 m across.
        p.x = (finite ? 8.0f : 30.0f) * u(rng);
        p.y = 1.0f + (finite ? 3.0f : 10.0f) * u(rng);
        p.z = finite ? -60.0f * (0.5f + 0.5f * u(rng)) : 6.0f - 60.0f * (0.5f + 0.5f * u(rng));
        p.size = std::exp2((finite ? 3.0f : 6.0f) * u(rng));
        p.frame = 2.0f + 2.5f * u(rng);
        particles.push_back(p);
    }
    const float odd[] = {0.0f, -0.0f, nan, inf, -inf, 1e-30f, -1e-30f, 1e30f, -1e30f, 6.0f, 5.9f, 6.1f, 1e-6f};
    const size_t odds = finite ? 2 : sizeof odd / sizeof odd[0];
    for (size_t i = 0; i < particles.size(); ++i) {
        ParticleInstance& p = particles[i];
        const float v = odd[i % odds];
        switch ((i / 7) % 9) {
            case 0: p.x = v; break;
            case 1: p.y = v; break;
            case 2: p.z = finite ? v - 5.0f : v; break;  // finite: no particle at the near plane
            case 3: p.size = v; break;
            case 4: p.frame = v; break;
            case 5: if (!finite) p.x = 0.0f, p.y = 1.5f, p.z = v; break;  // on the view axis, at the eye and near plane
            default: break;
        }
    }
    return particles;
}

// testView(), or (1) the same with a reversed-Z infinite far plane (clip z = near, clip w = -z).
ViewInfo fourLaneView(int projection) {
    ViewInfo view = testView();
    if (projection == 1) {
        view.proj = glm::perspective(glm::radians(75.0f), float(kW) / float(kH), view.nearPlane, view.farPlane);
        view.proj[2][2] = 0.0f;
        view.proj[3][2] = view.nearPlane;
    }
    return view;
}

BillboardReach fourLaneReach() {
    BillboardReach reach;
    reach.lodScale = 40.0f;
    reach.buckets = 5;
    for (size_t e = 0; e < reach.table.size(); ++e) reach.table[e] = 0.5f + 0.02f * float(e % 11);
    return reach;
}

// Turns the four-lane paths off for a scope.
struct OneLane {
    OneLane() { setFourLanes(false); }
    ~OneLane() { setFourLanes(true); }
};

// FootprintMath::perspectiveLanes (four particles a lane each, where SSE2 exists) against
// perspective<Flat> one at a time: every field of every bound the same bits, for the odd particles
// above, billboards with and without a reach table and spheres, under a finite and an infinite
// reversed-Z far plane; and the tile ranges taken from them (TileRangeOf, grown by a pixel as the
// bins do and by kTileBorder as screenRect does), four lanes against one.
TEST(ScreenTiles, FourAtATimeGiveTheBoundsOneAtATimeGives) {
#if FX_SSE2
    const std::vector<ParticleInstance> particles = oddParticles(4000, false);
    const BillboardReach reach = fourLaneReach();
    for (int projection = 0; projection < 2; ++projection) {
        const ViewInfo view = fourLaneView(projection);
        ASSERT_TRUE(footprint::plainPerspective(view.proj));
        for (int kind = 0; kind < 3; ++kind) {
            const footprint::FootprintMath math(view, kind != 2, kind == 1 ? &reach : nullptr,
                                                kind == 2 ? 0.5f : footprint::kQuadReach);
            int bounded = 0, unbounded = 0, behind = 0, ranges[2] = {0, 0};
            for (size_t i = 0; i + 4 <= particles.size(); i += 4) {
                const footprint::FootprintMath::Lanes q =
                    kind == 2 ? math.perspectiveLanes<false>(&particles[i]) : math.perspectiveLanes<true>(&particles[i]);
                alignas(16) float v[8][4];
                const __m128 rows[8] = {q.x0, q.x1, q.y0, q.y1, q.box[0], q.box[1], q.box[2], q.box[3]};
                for (int r = 0; r < 8; ++r) _mm_store_ps(v[r], rows[r]);
                for (int k = 0; k < 4; ++k) {
                    const ParticleInstance& p = particles[i + size_t(k)];
                    const footprint::Bounds one = kind == 2 ? math.perspective<false>(p) : math.perspective<true>(p);
                    // The same bits, or both not a number (which NaN comes out of inf - inf is the
                    // compiler's choice of operand order; no caller reads an unbounded one's pixels).
                    auto same = [](float a, float b) {
                        return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b));
                    };
                    const float ones[8] = {one.x0, one.x1, one.y0, one.y1, one.box[0], one.box[1], one.box[2], one.box[3]};
                    bool equal = one.state == q.state(k);
                    for (int f = 0; f < 8; ++f) equal = equal && same(ones[f], v[f][k]);
                    ASSERT_TRUE(equal) << "projection " << projection << ", kind " << kind << ", particle " << i + k
                                       << " (" << p.x << ", " << p.y << ", " << p.z << ", size " << p.size << ", frame "
                                       << p.frame << "): x0 " << one.x0 << " / " << v[0][k] << ", x1 " << one.x1 << " / "
                                       << v[1][k] << ", y0 " << one.y0 << " / " << v[2][k] << ", y1 " << one.y1 << " / "
                                       << v[3][k] << ", state " << one.state << " / " << q.state(k);
                    bounded += one.state == footprint::Bounds::Bounded;
                    unbounded += one.state == footprint::Bounds::Unbounded;
                    behind += one.state == footprint::Bounds::Behind;
                }
                for (int b = 0; b < 2; ++b) {
                    const footprint::TileRangeOf rangeOf{kW, kH, (kW + 15) / 16, (kH + 15) / 16,
                                                         b == 0 ? 1 : ScreenTiles::kTileBorder};
                    int32_t lanes[4][4];
                    uint8_t what[4];
                    rangeOf(q, lanes, what);
                    for (int k = 0; k < 4; ++k) {
                        const ParticleInstance& p = particles[i + size_t(k)];
                        int32_t r[4];
                        const uint8_t one = rangeOf(kind == 2 ? math.perspective<false>(p) : math.perspective<true>(p), r);
                        ASSERT_EQ(one, what[k]) << "particle " << i + k << ", border " << rangeOf.border;
                        if (one != footprint::TileRangeOf::Range) continue;
                        ++ranges[b];
                        for (int e = 0; e < 4; ++e) ASSERT_EQ(r[e], lanes[k][e]) << "particle " << i + k;
                    }
                }
            }
            // The cases are all there: not a vacuous comparison.
            EXPECT_GT(bounded, 1000);
            EXPECT_GT(unbounded, 50);
            EXPECT_GT(behind, 50);
            EXPECT_GT(ranges[0], 500);
            EXPECT_GT(ranges[1], 500);
        }
    }
#else
    GTEST_SKIP() << "no SSE2 on this target: the bounds run one particle at a time only";
#endif
}

// screenRect and binParticles with their four lanes against the same calls with one: the rect,
// the footprint pixels, the tile runs, the bins' words, tiles and counts, the same bits. Finite
// particles (with an unbounded one both give the whole view / refuse the view), runs of lengths
// that end in partial groups of four, two batches of billboards and one of spheres.
TEST(ScreenTiles, ScreenRectAndBinsAreTheSameWithOneLane) {
    const std::vector<ParticleInstance> particles = oddParticles(3001, true);
    const BillboardReach reach = fourLaneReach();
    for (int projection = 0; projection < 2; ++projection) {
        const ViewInfo view = fourLaneView(projection);
        for (int kind = 0; kind < 3; ++kind) {
            const Footprint footprint = kind == 2 ? Footprint::Box : Footprint::Billboard;
            const BillboardReach* r = kind == 1 ? &reach : nullptr;
            for (int count : {3001, 1002, 7}) {
                ScreenTiles four, one;
                const ScreenRect a = screenRect(view, particles.data(), count, &four, footprint, Jobs(), r);
                ScreenRect b;
                {
                    OneLane off;
                    b = screenRect(view, particles.data(), count, &one, footprint, Jobs(), r);
                }
                EXPECT_EQ(a.x0, b.x0);
                EXPECT_EQ(a.x1, b.x1);
                EXPECT_EQ(a.y0, b.y0);
                EXPECT_EQ(a.y1, b.y1);
                EXPECT_EQ(a.whole, b.whole);
                EXPECT_EQ(std::memcmp(&a.footprintPixels, &b.footprintPixels, sizeof(double)), 0)
                    << a.footprintPixels << " / " << b.footprintPixels;
                EXPECT_EQ(four.vertices, one.vertices);
                EXPECT_EQ(four.pixels, one.pixels);
                // Not a vacuous comparison: a rect inside the view, and tiles.
                if (count == 7) {
                    EXPECT_FALSE(a.whole);
                }
                EXPECT_GT(four.runs(), 3);
            }
        }
        const TileBins::Range batches[3] = {{0, 1000, false}, {1000, 1001, true}, {2001, 1000, false}};
        for (TileBins::Fill fill : {TileBins::Fill::Entries, TileBins::Fill::Pairs, TileBins::Fill::Ranges}) {
            TileBins four, one;
            ASSERT_TRUE(binParticles(view, particles.data(), batches, 3, &reach, &four, Jobs(), fill));
            {
                OneLane off;
                ASSERT_TRUE(binParticles(view, particles.data(), batches, 3, &reach, &one, Jobs(), fill));
            }
            EXPECT_GT(four.entryCount, 3000u);
            EXPECT_EQ(four.entryCount, one.entryCount);
            EXPECT_EQ(four.particles, one.particles);
            EXPECT_EQ(four.entries, one.entries);
            EXPECT_EQ(four.tiles, one.tiles);
            EXPECT_EQ(four.cover.vertices, one.cover.vertices);
        }
    }
}

TEST(ScreenTiles, ASteadyFrameReusesTheBuffers) {
    const ViewInfo view = testView();
    std::vector<ParticleInstance> particles(20);
    for (int i = 0; i < 20; ++i) {
        particles[size_t(i)].x = -3.0f + 0.3f * float(i);
        particles[size_t(i)].y = 1.0f + 0.05f * float(i);
        particles[size_t(i)].z = -float(i);
        particles[size_t(i)].size = 0.4f;
    }
    ScreenTiles tiles;
    screenRect(view, particles.data(), 20, &tiles, Footprint::Billboard);
    const float* vertices = tiles.vertices.data();
    const int32_t* grid = tiles.grid.data();
    const std::vector<float> first = tiles.vertices;
    screenRect(view, particles.data(), 20, &tiles, Footprint::Billboard);
    EXPECT_EQ(tiles.vertices, first);
    EXPECT_EQ(tiles.vertices.data(), vertices) << "the second frame reallocated the vertices";
    EXPECT_EQ(tiles.grid.data(), grid) << "the second frame reallocated the grid";
}

// The grid is zeroed after each bound only where its particles reached (gridClean), not cleared
// whole before the next: a ScreenTiles kept across bounds of different smoke (a cluster moving,
// nothing in front, bounds only just off the view, a particle at the near plane, a larger view,
// enough particles for several pieces) gives what a new one gives every time, and is all zero
// after each. Leaving out the clean-up, or a row or column of it, fails here.
// `count` particles around (cx, cy, cz), within `spread` on each axis, of sizes 0.25-2.25 `size`.
std::vector<ParticleInstance> cloudOf(std::mt19937& rng, int count, float cx, float cy, float cz, float spread,
                                      float size) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<ParticleInstance> out{size_t(count), ParticleInstance{}};
    for (ParticleInstance& p : out) {
        p.x = cx + spread * u(rng);
        p.y = cy + spread * u(rng);
        p.z = cz + spread * u(rng);
        p.size = size * (1.25f + u(rng));
    }
    return out;
}

TEST(ScreenTiles, AKeptGridGivesWhatANewOneGives) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    auto cloud = [&](int count, float cx, float cy, float cz, float spread, float size) {
        return cloudOf(rng, count, cx, cy, cz, spread, size);
    };
    const ViewInfo small = testView();
    ViewInfo large = testView();
    large.width = 3 * kW + 5;  // not a whole number of tiles
    large.height = 2 * kH + 9;
    struct Step {
        const ViewInfo* view;
        std::vector<ParticleInstance> particles;
    };
    std::vector<ParticleInstance> edge;  // around the left edge, many just outside the view
    for (int i = 0; i < 400; ++i) {
        ParticleInstance p;
        p.z = -2.0f - 20.0f * (0.5f + 0.5f * u(rng));
        p.x = -(6.0f - p.z) * 0.78f - 0.3f * u(rng);  // the frustum's left plane, about
        p.y = 1.0f + 2.0f * u(rng);
        p.size = 0.05f + 0.05f * (1.0f + u(rng));
        edge.push_back(p);
    }
    std::vector<ParticleInstance> nearPlane = cloud(50, 0.0f, 1.0f, 0.0f, 1.0f, 0.3f);
    nearPlane[17].z = 5.95f;
    nearPlane[17].x = 0.0f;
    nearPlane[17].y = 1.5f;
    const std::vector<Step> steps = {
        {&small, cloud(300, -2.0f, 1.0f, 0.0f, 1.0f, 0.3f)},
        {&small, cloud(300, 2.0f, 2.0f, -3.0f, 1.0f, 0.3f)},
        {&small, cloud(40, 0.0f, 1.0f, 20.0f, 1.0f, 0.3f)},  // behind the eye: nothing
        {&small, cloud(200, 0.0f, 0.0f, 0.0f, 0.5f, 0.2f)},
        {&small, edge},
        {&small, cloud(100, 1.0f, 1.0f, -2.0f, 3.0f, 0.5f)},
        {&small, nearPlane},
        {&small, cloud(100, -1.0f, 0.5f, -1.0f, 1.0f, 0.4f)},
        {&large, cloud(300, 3.0f, 0.0f, -4.0f, 2.0f, 0.3f)},
        {&large, cloud(40000, 0.0f, 1.0f, -10.0f, 6.0f, 0.2f)},  // several pieces
        {&large, cloud(500, -4.0f, 2.0f, -6.0f, 1.0f, 0.3f)},
        {&small, oddParticles(3001, true)},
        {&small, cloud(60, 0.5f, 1.5f, 0.0f, 0.2f, 0.1f)},
    };
    ScreenTiles kept;
    int withRuns = 0, edgeRuns = -1, unboundedSteps = 0;
    for (size_t i = 0; i < steps.size(); ++i) {
        const Step& step = steps[i];
        for (Footprint footprint : {Footprint::Billboard, Footprint::Box}) {
            const int count = int(step.particles.size());
            ScreenTiles fresh;
            const ScreenRect a = screenRect(*step.view, step.particles.data(), count, &kept, footprint);
            const ScreenRect b = screenRect(*step.view, step.particles.data(), count, &fresh, footprint);
            EXPECT_EQ(a.x0, b.x0) << "step " << i;
            EXPECT_EQ(a.y0, b.y0) << "step " << i;
            EXPECT_EQ(a.x1, b.x1) << "step " << i;
            EXPECT_EQ(a.y1, b.y1) << "step " << i;
            EXPECT_EQ(a.whole, b.whole) << "step " << i;
            EXPECT_EQ(kept.vertices, fresh.vertices) << "step " << i;
            EXPECT_EQ(kept.pixels, fresh.pixels) << "step " << i;
            const bool unbounded = std::isinf(a.footprintPixels);  // the near plane: the grid left as it was
            unboundedSteps += unbounded ? 1 : 0;
            EXPECT_EQ(kept.gridClean, !unbounded) << "step " << i;
            if (!unbounded) {
                EXPECT_TRUE(std::all_of(kept.grid.begin(), kept.grid.end(), [](int32_t c) { return c == 0; }))
                    << "step " << i << ": the grid was left with marks";
            }
            withRuns += kept.runs() > 0 && !a.whole ? 1 : 0;
            if (i == 4 && footprint == Footprint::Billboard) edgeRuns = kept.runs();
        }
    }
    EXPECT_GE(withRuns, 16) << "most steps bound smoke on part of the view";
    EXPECT_GT(edgeRuns, 0) << "the edge step reaches into the view";
    EXPECT_EQ(unboundedSteps, 1) << "the cube at the near plane";
}


// binParticles (the tiled path): every particle is in each tile its bound touches and in no tile
// farther than a pixel past it, each tile's list runs front to back (the last batch's last
// particle first) with the batch in the entry's top bits, and the cover's runs are exactly the
// tiles that hold particles.
TEST(TileBins, EveryParticleIsInTheTilesItsBoundTouchesFrontToBack) {
    const ViewInfo view = testView();
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> across(-4.0f, 4.0f), up(0.0f, 3.0f), deep(-30.0f, 2.0f), size(0.05f, 2.5f);
    const int tilesX = (kW + ScreenTiles::kTileSize - 1) / ScreenTiles::kTileSize;
    const int tilesY = (kH + ScreenTiles::kTileSize - 1) / ScreenTiles::kTileSize;
    TileBins bins;
    for (int trial = 0; trial < 30; ++trial) {
        std::vector<ParticleInstance> particles(1 + trial % 20);
        for (ParticleInstance& p : particles) {
            p.x = across(rng);
            p.y = up(rng);
            p.z = deep(rng);
            p.size = size(rng);
        }
        // Two batches: the first third, then the rest.
        const int n = int(particles.size()), split = n / 3;
        const TileBins::Range ranges[2] = {{0, split}, {split, n - split}};
        ASSERT_TRUE(binParticles(view, particles.data(), ranges, 2, nullptr, &bins)) << "trial " << trial;
        // Where each particle is expected: the bound of its corners at 0.71 size (ScreenTiles'
        // kQuadReach) grown by a pixel, everything left of the view in the first tile, right of
        // it in the last.
        std::vector<std::vector<uint32_t>> expected(size_t(tilesX * tilesY));
        for (int i = n - 1; i >= 0; --i) {
            const ParticleInstance& p = particles[size_t(i)];
            const glm::vec4 c = view.view * glm::vec4(p.x, p.y, p.z, 1.0f);
            if (-c.z < view.nearPlane) continue;  // clipped: binned nowhere
            float lo[2] = {1e30f, 1e30f}, hi[2] = {-1e30f, -1e30f};
            for (int k = 0; k < 4; ++k) {
                const float r = 0.71f * p.size;
                const glm::vec4 clip = view.proj * (c + glm::vec4(k & 1 ? r : -r, k & 2 ? r : -r, 0.0f, 0.0f));
                const float px[2] = {(clip.x / clip.w * 0.5f + 0.5f) * kW, (clip.y / clip.w * 0.5f + 0.5f) * kH};
                for (int a = 0; a < 2; ++a) {
                    lo[a] = std::min(lo[a], px[a] - 1.0f);
                    hi[a] = std::max(hi[a], px[a] + 1.0f);
                }
            }
            if (hi[0] < 0.0f || hi[1] < 0.0f || lo[0] > float(kW) || lo[1] > float(kH)) continue;
            const float t = float(ScreenTiles::kTileSize);
            const int tx0 = std::max(0, int(std::floor(lo[0] / t))), tx1 = std::min(tilesX - 1, int(std::floor(hi[0] / t)));
            const int ty0 = std::max(0, int(std::floor(lo[1] / t))), ty1 = std::min(tilesY - 1, int(std::floor(hi[1] / t)));
            const uint32_t entry = uint32_t(i) | (uint32_t(i >= split ? 1 : 0) << TileBins::kBatchShift);
            for (int ty = std::min(ty0, tilesY - 1); ty <= ty1; ++ty) {
                for (int tx = std::min(tx0, tilesX - 1); tx <= tx1; ++tx) expected[size_t(ty * tilesX + tx)].push_back(entry);
            }
        }
        std::vector<std::vector<uint32_t>> got(size_t(tilesX * tilesY));
        int64_t coverPixels = 0;
        for (int k = 0; k < bins.tileCount(); ++k) {
            const uint32_t* t = &bins.tiles[size_t(k) * 4];
            ASSERT_LT(int(t[0]), tilesX);
            ASSERT_LT(int(t[1]), tilesY);
            ASSERT_GT(t[3], 0u) << "a listed tile holds particles";
            got[size_t(t[1] * tilesX + t[0])].assign(bins.entries.begin() + t[2], bins.entries.begin() + t[2] + t[3]);
            coverPixels += int64_t(std::min(kW, int(t[0] + 1) * ScreenTiles::kTileSize) - int(t[0]) * ScreenTiles::kTileSize) *
                           (std::min(kH, int(t[1] + 1) * ScreenTiles::kTileSize) - int(t[1]) * ScreenTiles::kTileSize);
        }
        for (size_t k = 0; k < got.size(); ++k) {
            EXPECT_EQ(got[k], expected[k]) << "tile " << k % size_t(tilesX) << "," << k / size_t(tilesX) << ", trial " << trial;
        }
        EXPECT_EQ(bins.cover.pixels, coverPixels) << "the cover is the tiles with particles, trial " << trial;
        bool insideView = false;
        for (int c : rasterise(bins.cover, &insideView)) ASSERT_LE(c, 1);
        EXPECT_TRUE(insideView);
    }
}

// The bins keep their first grid zero between calls (TileBins::cleanCells) and sum and walk only
// the box of the particles' ranges: TileBins kept across views of different smoke (clusters
// moving, a larger view, enough particles for several pieces, a view refused for a particle with
// no bound, nothing on screen) give what new ones give, every Fill, every time.
TEST(TileBins, KeptBinsGiveWhatNewOnesGive) {
    std::mt19937 rng(5);
    const ViewInfo small = testView();
    ViewInfo large = testView();
    large.width = 2 * kW + 7;
    large.height = 3 * kH + 3;
    struct Step {
        const ViewInfo* view;
        std::vector<ParticleInstance> particles;
        bool refused;
    };
    std::vector<ParticleInstance> noBound = cloudOf(rng, 3000, 1.0f, 1.0f, -3.0f, 2.0f, 0.2f);
    noBound[2500].y = std::numeric_limits<float>::infinity();  // after the first piece's marks
    // Small clusters inside the view (none reaches its last row or column, where a mark left
    // behind would never be read), at different places; their boxes overlap one another's edges.
    const std::vector<Step> steps = {
        {&small, cloudOf(rng, 200, -1.5f, 1.5f, -4.0f, 0.4f, 0.05f), false},
        {&small, cloudOf(rng, 300, 1.0f, 0.5f, -4.0f, 0.4f, 0.05f), false},
        {&small, cloudOf(rng, 300, -0.5f, 1.0f, -4.0f, 0.6f, 0.05f), false},
        {&small, noBound, true},
        {&small, cloudOf(rng, 50, 0.5f, 1.5f, -5.0f, 0.3f, 0.05f), false},
        {&small, cloudOf(rng, 80, 0.0f, 0.8f, -4.0f, 0.3f, 0.05f), false},
        {&large, cloudOf(rng, 9000, 0.0f, 1.0f, -6.0f, 1.5f, 0.05f), false},  // several pieces
        {&large, cloudOf(rng, 100, 1.0f, 0.5f, -4.0f, 0.5f, 0.05f), false},
        {&small, cloudOf(rng, 40, 0.0f, 1.0f, 20.0f, 1.0f, 0.3f), false},  // behind the eye: nothing
        {&small, cloudOf(rng, 400, -0.5f, 1.2f, -4.0f, 0.8f, 0.05f), false},
    };
    int withTiles = 0, lastRow = -1;
    for (TileBins::Fill fill : {TileBins::Fill::Entries, TileBins::Fill::Pairs, TileBins::Fill::Ranges}) {
        TileBins kept;
        for (size_t i = 0; i < steps.size(); ++i) {
            const Step& step = steps[i];
            const int n = int(step.particles.size());
            const TileBins::Range batches[2] = {{0, n / 3, false}, {n / 3, n - n / 3, true}};
            TileBins fresh;
            const bool a = binParticles(*step.view, step.particles.data(), batches, 2, nullptr, &kept, Jobs(), fill);
            const bool b = binParticles(*step.view, step.particles.data(), batches, 2, nullptr, &fresh, Jobs(), fill);
            ASSERT_EQ(a, !step.refused) << "step " << i;
            ASSERT_EQ(b, a) << "step " << i;
            if (!a) continue;
            EXPECT_EQ(kept.entryCount, fresh.entryCount) << "step " << i;
            EXPECT_EQ(kept.particles, fresh.particles) << "step " << i;
            EXPECT_EQ(kept.entries, fresh.entries) << "step " << i;
            EXPECT_EQ(kept.tiles, fresh.tiles) << "step " << i;
            EXPECT_EQ(kept.cover.vertices, fresh.cover.vertices) << "step " << i;
            withTiles += kept.tileCount() > 0 ? 1 : 0;
            for (int t = 0; t < kept.tileCount(); ++t) lastRow = std::max(lastRow, int(kept.tiles[size_t(t) * 4 + 1]));
            if (step.view == &small) {
                for (int t = 0; t < kept.tileCount(); ++t) {
                    EXPECT_LT(int(kept.tiles[size_t(t) * 4 + 1]), kept.tilesY - 1) << "step " << i;
                    EXPECT_LT(int(kept.tiles[size_t(t) * 4]), kept.tilesX - 1) << "step " << i;
                }
            }
        }
    }
    EXPECT_EQ(withTiles, 3 * 8) << "every step but the refused one and the one behind the eye bins tiles";
    EXPECT_LT(lastRow, large.height / ScreenTiles::kTileSize) << "no step's smoke reaches the view's last row";
}

TEST(TileBins, AParticleWithNoBoundOrTooManyBatchesRefuseTheView) {
    const ViewInfo view = testView();
    ParticleInstance p = centredParticle(1.0f);
    TileBins bins;
    const TileBins::Range one{0, 1};
    ASSERT_TRUE(binParticles(view, &p, &one, 1, nullptr, &bins));
    EXPECT_GT(bins.tileCount(), 0);
    p.x = std::nanf("");
    EXPECT_FALSE(binParticles(view, &p, &one, 1, nullptr, &bins)) << "a position that is not a number";
    p = centredParticle(1.0f);
    p.z = 10.0f;  // behind the camera: clipped, binned nowhere
    ASSERT_TRUE(binParticles(view, &p, &one, 1, nullptr, &bins));
    EXPECT_EQ(bins.tileCount(), 0);
    EXPECT_TRUE(bins.entries.empty());
    EXPECT_TRUE(bins.cover.vertices.empty());
    std::vector<TileBins::Range> many(65, TileBins::Range{0, 0});
    many[0] = one;
    EXPECT_FALSE(binParticles(view, &p, many.data(), 65, nullptr, &bins)) << "64 batches fit the entries' 6 bits";
}

}  // namespace
}  // namespace fx
