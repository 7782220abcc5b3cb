// The tiled path's lists on the GPU (TileSort.h, cs_particles_tile_sort.glsl): from binParticles' Fill::Pairs
// words, the emit and the stable radix sort write each tile's entries front to back, and they are
// Fill::Entries' lists bit for bit:
//  - on views of 1 tile (no radix pass) up to 1080p (8,160 tiles, four passes), with particles
//    off the view, clipped, across tiles, and a sphere across the near plane in every tile;
//  - with the rows per block TileSort::rowsFor picks and with 1, 3 and 16 (the most) fixed, more
//    pairs than one block and a histogram longer than the scan group (1,024
//    words: over 65,536 pairs), and a second run on the same buffers with fewer pairs;
//  - the words themselves, without GL: pairs written row by row in particle order and sorted
//    stably by tile are the lists (what the shaders do, done on the CPU);
//  - the particles of an unsorted list (TileSort::DepthOrder) sorted on the GPU first: the lists
//    of the list DrawListBuilder::order sorts on the CPU, bit for bit, each entry naming the same
//    particle, with equal depths, -0 and +0, several batches (one drawn unsorted) and one batch.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glad/gl.h>

#include "FxTestHost.h"
#include "render/ShaderLoader.h"
#include "render/DrawList.h"
#include "render/TileSort.h"

namespace fxtest {
namespace tile_sort_test {  // named: the fx_host tests build as unity batches

constexpr GLenum kShaderStorageBuffer = 0x90D2;  // GL 4.3's (the tests' loader is 3.3 core)

fx::ViewInfo viewOf(int width, int height) {
    return makeView(glm::vec3(0.0f, 1.5f, 6.0f), glm::vec3(0.0f, 1.0f, 0.0f), width, height, 0.1f, 500.0f);
}

// `n` particles around the view (some behind the camera, some off its sides), sizes 0.05-`largest`
// m, in two batches of billboards and a last one of spheres whose first sits on the camera (across
// the near plane: every tile).
struct Scene {
    std::vector<fx::ParticleInstance> particles;
    std::vector<fx::TileBins::Range> ranges;
};
Scene sceneOf(int n, float largest, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> across(-6.0f, 6.0f), up(-1.0f, 4.0f), deep(-40.0f, 8.0f), size(0.05f, largest);
    Scene s;
    s.particles.resize(size_t(n));
    for (fx::ParticleInstance& p : s.particles) {
        p.x = across(rng);
        p.y = up(rng);
        p.z = deep(rng);
        p.size = size(rng);
    }
    const int a = n / 3, b = n / 3;
    s.ranges = {{0, a, false}, {a, b, false}, {a + b, n - a - b, true}};
    fx::ParticleInstance& onCamera = s.particles[size_t(a + b)];
    onCamera.x = 0.0f;
    onCamera.y = 1.5f;
    onCamera.z = 6.0f;
    onCamera.size = 1.0f;
    return s;
}

// The emit and the sort on the CPU: pairs row by row in particle order, sorted stably by tile.
std::vector<uint32_t> sortOnCpu(const fx::TileBins& bins) {
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (size_t k = 0; k < bins.particles.size() / 4; ++k) {
        const uint32_t* w = &bins.particles[k * 4];
        EXPECT_EQ(w[2], uint32_t(pairs.size())) << "particle " << k << "'s first pair";
        for (uint32_t y = w[1] & 0xffffu; y <= (w[1] >> 16) && (w[0] & 0xffffu) <= (w[0] >> 16); ++y) {
            for (uint32_t x = w[0] & 0xffffu; x <= (w[0] >> 16); ++x) pairs.emplace_back(y * uint32_t(bins.tilesX) + x, w[3]);
        }
    }
    std::stable_sort(pairs.begin(), pairs.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
    std::vector<uint32_t> entries;
    for (const auto& p : pairs) entries.push_back(p.second);
    return entries;
}

struct Case {
    int width, height, particles;
    float largest;
};
// 1 tile (no pass), 12 (one), 192 (two), 1,320 (three), 8,160 (four); the last two with 66 k and
// 300 k pairs (more than 16 blocks of histogram per scan invocation).
const Case kCases[] = {{16, 16, 40, 2.0f}, {64, 48, 300, 2.0f}, {256, 192, 2000, 2.5f}, {640, 480, 3000, 3.0f},
                       {1920, 1080, 6000, 3.0f}};

TEST(TileSortWords, PairsSortedStablyByTileAreTheLists) {
    for (const Case& c : kCases) {
        SCOPED_TRACE(testing::Message() << c.width << "x" << c.height);
        const Scene s = sceneOf(c.particles, c.largest, 5);
        const fx::ViewInfo view = viewOf(c.width, c.height);
        fx::TileBins lists, words;
        ASSERT_TRUE(fx::binParticles(view, s.particles.data(), s.ranges.data(), 3, nullptr, &lists));
        ASSERT_TRUE(fx::binParticles(view, s.particles.data(), s.ranges.data(), 3, nullptr, &words, fx::Jobs(),
                                     fx::TileBins::Fill::Pairs));
        EXPECT_TRUE(words.entries.empty()) << "Fill::Pairs leaves the lists to the GPU";
        EXPECT_EQ(words.tiles, lists.tiles);
        EXPECT_EQ(words.cover.vertices, lists.cover.vertices);
        EXPECT_EQ(words.entryCount, uint32_t(lists.entries.size()));
        EXPECT_EQ(words.particles, lists.particles);
        EXPECT_EQ(sortOnCpu(words), lists.entries);
    }
}

class TileSortTest : public FxHostTest {
protected:
    fx::ProgramCache programs{fx::snapshotShaderReader(fx::shaderReader(""))};
};

TEST_F(TileSortTest, SortedEntriesAreTheCpuListsBitForBit) {
    std::vector<std::string> errors;
    ASSERT_EQ(programs.build(fx::ProgramCache::tileSortKeys(), &errors), 8) << (errors.empty() ? "" : errors[0]);
    fx::TileSort sort;
    sort.bind(programs);
    ASSERT_TRUE(sort.ok());
    ASSERT_TRUE(sort.orderOk());
    int sortedAtLeastOncePastOneBlock = 0, longestHistogram = 0;
    for (int round = 0; round < 8; ++round) {
        const int rows = round / 2 == 0 ? 0 : round / 2 == 1 ? 1 : round / 2 == 2 ? 3 : fx::TileSort::kMaxRows;
        fx::TileSort::setRows(rows);
        // Every second round on the same (grown) buffers, the cases backwards: fewer pairs than the
        // buffers hold must not read the last run's.
        for (int i = 0; i < int(std::size(kCases)); ++i) {
            const Case& c = kCases[round % 2 == 0 ? i : int(std::size(kCases)) - 1 - i];
            SCOPED_TRACE(testing::Message() << c.width << "x" << c.height << ", round " << round << ", rows " << rows);
            const Scene s = sceneOf(c.particles, c.largest, 7 + unsigned(round));
            const fx::ViewInfo view = viewOf(c.width, c.height);
            fx::TileBins lists, words;
            ASSERT_TRUE(fx::binParticles(view, s.particles.data(), s.ranges.data(), 3, nullptr, &lists));
            ASSERT_TRUE(fx::binParticles(view, s.particles.data(), s.ranges.data(), 3, nullptr, &words, fx::Jobs(),
                                         fx::TileBins::Fill::Pairs));
            ASSERT_TRUE(sort.fits(words));
            const uint32_t buffer = sort.run(words);
            ASSERT_NE(buffer, 0u);
            std::vector<uint32_t> got(words.entryCount);
            glBindBuffer(kShaderStorageBuffer, buffer);
            glGetBufferSubData(kShaderStorageBuffer, 0, GLsizeiptr(got.size() * 4), got.data());
            glBindBuffer(kShaderStorageBuffer, 0);
            ASSERT_EQ(got.size(), lists.entries.size());
            size_t firstDifference = 0;
            while (firstDifference < got.size() && got[firstDifference] == lists.entries[firstDifference]) ++firstDifference;
            EXPECT_EQ(firstDifference, got.size()) << "entries differ from " << firstDifference << " of " << got.size();
            const size_t blockPairs = size_t(fx::TileSort::kGroup) * size_t(fx::TileSort::rowsFor(words.entryCount));
            if (got.size() > blockPairs) ++sortedAtLeastOncePastOneBlock;
            longestHistogram = std::max(longestHistogram, int((got.size() + blockPairs - 1) / blockPairs) * 16);
        }
    }
    fx::TileSort::setRows(0);
    EXPECT_GE(sortedAtLeastOncePastOneBlock, 16) << "the cases sort more than one block";
    EXPECT_GT(longestHistogram, 1024) << "a histogram longer than the scan group";
    // The rows: one up to kTargetBlocks blocks of one row, then as many as spread the pairs over
    // about that many blocks, at most kMaxRows.
    EXPECT_EQ(fx::TileSort::rowsFor(0), 1);
    EXPECT_EQ(fx::TileSort::rowsFor(256 * 1024), 1);
    EXPECT_EQ(fx::TileSort::rowsFor(256 * 1024 + 1), 2);
    EXPECT_EQ(fx::TileSort::rowsFor(520000), 2);
    EXPECT_EQ(fx::TileSort::rowsFor(6000000), 16);
    EXPECT_EQ(fx::TileSort::rowsFor(UINT32_MAX), fx::TileSort::kMaxRows);
    EXPECT_EQ(fx::TileSort::passes(1), 0);
    EXPECT_EQ(fx::TileSort::passes(12), 1);
    EXPECT_EQ(fx::TileSort::passes(8160), 4);
    EXPECT_EQ(fx::TileSort::passes(65536), 4);
    EXPECT_EQ(fx::TileSort::passes(65537), 5);
}

// The particles of a list built without its order, sorted on the GPU (TileSort::DepthOrder): the
// lists are those of the same list sorted on the CPU (DrawListBuilder::order), each entry the
// same particle where the unsorted list holds it (its life is its number), in every batch mix.
TEST_F(TileSortTest, ParticlesSortedOnTheGpuGiveTheCpuOrdersLists) {
    std::vector<std::string> errors;
    ASSERT_EQ(programs.build(fx::ProgramCache::tileSortKeys(), &errors), 8) << (errors.empty() ? "" : errors[0]);
    fx::TileSort sort;
    sort.bind(programs);
    ASSERT_TRUE(sort.orderOk());
    uint32_t instances = 0;
    glGenBuffers(1, &instances);
    const uint64_t orderedBefore = fx::TileSort::gpuOrderedViews();
    int runs = 0;
    for (const Case& c : kCases) {
        for (int mix = 0; mix < 3; ++mix) {
            SCOPED_TRACE(testing::Message() << c.width << "x" << c.height << ", mix " << mix);
            Scene s = sceneOf(c.particles, c.largest, 11 + unsigned(mix));
            const int n = int(s.particles.size());
            for (int i = 0; i < n; ++i) {
                fx::ParticleInstance& p = s.particles[size_t(i)];
                if (i % 7 == 3) p = s.particles[size_t(i - 1)];  // equal depths (the same place)
                p.life = float(i);                               // which particle it is
            }
            // Two spheres across the near plane (in every tile) at depths +0 and -0: 0.1 m either
            // side of the eye, square to the view axis (whose x is 0: the products' signs differ).
            const fx::ViewInfo view = viewOf(c.width, c.height);
            const int zeros = s.ranges[2].first + 1;
            for (int j = 0; j < 2; ++j) {
                fx::ParticleInstance& p = s.particles[size_t(zeros + j)];
                p.x = view.eye.x + (j == 0 ? 0.1f : -0.1f);
                p.y = view.eye.y;
                p.z = view.eye.z;
                p.size = 1.0f;
            }
            const glm::vec3 forward = fx::viewForward(view);
            float depths[2];
            for (int j = 0; j < 2; ++j) {
                const fx::ParticleInstance& p = s.particles[size_t(zeros + j)];
                depths[j] = (p.x - view.eye.x) * forward.x + (p.y - view.eye.y) * forward.y + (p.z - view.eye.z) * forward.z;
            }
            ASSERT_EQ(depths[0], 0.0f);
            ASSERT_EQ(depths[1], 0.0f);
            ASSERT_NE(std::signbit(depths[0]), std::signbit(depths[1])) << "a +0 and a -0";
            // The -0 first in the pool: front to back the tie keeps the later one first, where a
            // key of -0's own bits would put the -0 first.
            if (!std::signbit(depths[0])) std::swap(s.particles[size_t(zeros)].x, s.particles[size_t(zeros + 1)].x);
            fx::DrawList list;
            list.instances.resize(size_t(n));
            std::copy(s.particles.begin(), s.particles.end(), list.instances.begin());
            // mix 0: three batches, the middle one additive; 1: all three back to front; 2: one batch.
            std::vector<fx::TileBins::Range> ranges = s.ranges;
            if (mix == 2) ranges = {{0, n, false}};
            for (size_t b = 0; b < ranges.size(); ++b) {
                fx::DrawBatch batch;
                batch.first = ranges[b].first;
                batch.count = ranges[b].count;
                batch.technique = ranges[b].sphere ? fx::Technique::Spherical : fx::Technique::Soft;
                batch.backToFront = !(mix == 0 && b == 1);
                list.batches.push_back(batch);
            }
            list.orderPending = true;
            const int batchCount = int(ranges.size());
            // The GPU: the unsorted list binned as it lies.
            fx::TileBins words;
            ASSERT_TRUE(fx::binParticles(view, list.instances.data(), ranges.data(), batchCount, nullptr, &words,
                                         fx::Jobs(), fx::TileBins::Fill::Ranges));
            // Ranges: each particle's tile range only, two words (its entry is its place's); the
            // ranges' tiles add up to the entries.
            ASSERT_EQ(words.wordsPerParticle, 2);
            ASSERT_EQ(words.particles.size(), size_t(n) * 2);
            uint64_t counted = 0;
            for (size_t k = 0; k < words.particles.size() / 2; ++k) {
                const uint32_t* w = &words.particles[k * 2];
                counted += (w[0] & 0xffffu) > (w[0] >> 16)
                               ? 0u
                               : ((w[0] >> 16) - (w[0] & 0xffffu) + 1) * ((w[1] >> 16) - (w[1] & 0xffffu) + 1);
            }
            EXPECT_EQ(counted, uint64_t(words.entryCount));
            glBindBuffer(kShaderStorageBuffer, instances);
            glBufferData(kShaderStorageBuffer, GLsizeiptr(size_t(n) * sizeof(fx::ParticleInstance)), list.instances.data(),
                         0x88E0 /* GL_STREAM_DRAW */);
            fx::TileSort::DepthOrder order;
            order.instances = instances;
            order.eye = view.eye;
            order.forward = fx::viewForward(view);
            order.batchCount = batchCount;
            for (int b = 0; b < batchCount; ++b) order.backToFront |= list.batches[size_t(b)].backToFront ? 1u << b : 0u;
            const uint32_t buffer = sort.run(words, fx::Jobs(), &order);
            ASSERT_NE(buffer, 0u);
            std::vector<uint32_t> got(words.entryCount);
            glBindBuffer(kShaderStorageBuffer, buffer);
            glGetBufferSubData(kShaderStorageBuffer, 0, GLsizeiptr(got.size() * 4), got.data());
            glBindBuffer(kShaderStorageBuffer, 0);
            // The CPU: the same list sorted, binned with its lists; each entry renamed to the
            // particle's place in the unsorted list.
            fx::DrawListBuilder builder;
            fx::DrawList sorted = list;
            builder.order(view, &sorted);
            fx::TileBins lists;
            ASSERT_TRUE(fx::binParticles(view, sorted.instances.data(), ranges.data(), batchCount, nullptr, &lists));
            ASSERT_EQ(lists.entries.size(), got.size());
            ASSERT_GT(got.size(), 0u);
            constexpr uint32_t kIndex = (1u << fx::TileBins::kBatchShift) - 1u;
            size_t differ = 0, moved = 0;
            for (size_t e = 0; e < got.size(); ++e) {
                const uint32_t want = lists.entries[e];
                const uint32_t particle = uint32_t(sorted.instances[want & kIndex].life);
                differ += got[e] != ((want & ~kIndex) | particle) ? 1 : 0;
                moved += (want & kIndex) != particle ? 1 : 0;
            }
            EXPECT_EQ(differ, 0u) << "of " << got.size() << " entries";
            EXPECT_GT(moved, got.size() / 4) << "the sort moved too few particles to prove it";
            ++runs;
        }
    }
    glDeleteBuffers(1, &instances);
    EXPECT_EQ(fx::TileSort::gpuOrderedViews(), orderedBefore + uint64_t(runs));
    // The limit: never on a software rasterizer, kOrderParticles elsewhere, setOrderLimit's where set.
    EXPECT_EQ(fx::TileSort::orderLimit(true), UINT32_MAX);
    EXPECT_EQ(fx::TileSort::orderLimit(false), fx::TileSort::kOrderParticles);
    fx::TileSort::setOrderLimit(5);
    EXPECT_EQ(fx::TileSort::orderLimit(true), 5u);
    fx::TileSort::resetOrderLimit();
    EXPECT_EQ(fx::TileSort::orderLimit(false), fx::TileSort::kOrderParticles);
}

// The bins on the GPU (TileSort::binOnGpu, readGpuBins): what binParticles gives with Fill::Ranges,
// bit for bit on this rasterizer: the entry count, the tiles and their runs, and (through run()
// with the particles' order) the lists. Perspective views with and without a reach table (frames
// 0-3 and out of range, buckets clamped both ways), an orthographic one (the corners' path), a
// sphere across the near plane, particles off the view and behind it; views whose rows or columns
// are longer than a group of the grid's sums; then a view with nothing on it, a particle that is not finite (refused, as binParticles refuses it), and the same
// buffers reused by a smaller view after a larger one.
TEST_F(TileSortTest, BinnedOnTheGpuAsOnTheCpu) {
    std::vector<std::string> errors;
    std::vector<fx::ProgramCache::Key> keys = fx::ProgramCache::tileSortKeys();
    for (const fx::ProgramCache::Key& k : fx::ProgramCache::tileBinKeys()) keys.push_back(k);
    ASSERT_EQ(programs.build(keys, &errors), 10) << (errors.empty() ? "" : errors[0]);
    fx::TileSort sort;
    sort.bind(programs);
    ASSERT_TRUE(sort.binsOk());
    uint32_t instances = 0, tiles = 0;
    size_t tileCapacity = 0;
    glGenBuffers(1, &instances);
    fx::BillboardReach reach;
    reach.lodScale = 0.37f;
    reach.buckets = 5;
    for (size_t i = 0; i < reach.table.size(); ++i) reach.table[i] = 0.25f + 0.01f * float(i);
    int compared = 0;
    for (int variant = 0; variant < 4; ++variant) {
        for (int ci = int(std::size(kCases)) - 1; ci >= 0; --ci) {  // large first: the buffers then shrink
            const Case& c = kCases[ci];
            SCOPED_TRACE(testing::Message() << c.width << "x" << c.height << ", variant " << variant);
            Scene s = sceneOf(c.particles, c.largest, 23 + unsigned(variant));
            const int n = int(s.particles.size());
            for (int i = 0; i < n; ++i) s.particles[size_t(i)].frame = float(i % 6) - (i % 11 == 0 ? 1.7f : 0.0f);
            fx::ViewInfo view = viewOf(c.width, c.height);
            if (variant == 2) {
                view.proj = glm::ortho(-8.0f, 8.0f, -6.0f, 6.0f, 0.1f, 500.0f);
                s.ranges[2].sphere = false;  // the tiled path draws spheres under perspective only
            }
            const fx::BillboardReach* withReach = variant == 1 || variant == 3 ? &reach : nullptr;
            fx::TileBins cpu;
            ASSERT_TRUE(fx::binParticles(view, s.particles.data(), s.ranges.data(), 3, withReach, &cpu, fx::Jobs(),
                                         fx::TileBins::Fill::Ranges));
            glBindBuffer(kShaderStorageBuffer, instances);
            glBufferData(kShaderStorageBuffer, GLsizeiptr(size_t(n) * sizeof(fx::ParticleInstance)), s.particles.data(),
                         0x88E0 /* GL_STREAM_DRAW */);
            fx::TileBins gpu;
            ASSERT_EQ(fx::placeBatches(s.ranges.data(), 3, &gpu), n);
            const uint32_t spheres = s.ranges[2].sphere ? 4u : 0u;
            const fx::BillboardReach none;
            ASSERT_TRUE(sort.binOnGpu(view, instances, uint32_t(n), spheres, withReach ? reach : none, gpu, &tiles,
                                      &tileCapacity));
            ASSERT_TRUE(sort.readGpuBins(&gpu));
            EXPECT_EQ(gpu.gpuParticles, uint32_t(n));
            EXPECT_TRUE(gpu.particles.empty());
            EXPECT_EQ(gpu.entryCount, cpu.entryCount);
            EXPECT_EQ(gpu.tilesX, cpu.tilesX);
            EXPECT_EQ(gpu.tilesY, cpu.tilesY);
            EXPECT_EQ(gpu.tiles, cpu.tiles);
            EXPECT_EQ(gpu.cover.vertices, cpu.cover.vertices);
            EXPECT_EQ(gpu.cover.pixels, cpu.cover.pixels);
            ASSERT_GT(cpu.tileCount(), 0);
            ASSERT_FALSE(sort.readGpuBins(&gpu)) << "read once";
            // The lists from either bins, through the particles' order on the GPU.
            fx::TileSort::DepthOrder order;
            order.instances = instances;
            order.eye = view.eye;
            order.forward = fx::viewForward(view);
            order.batchCount = 3;
            order.backToFront = 5u;
            auto listsOf = [&](const fx::TileBins& bins) {
                std::vector<uint32_t> got(bins.entryCount);
                const uint32_t buffer = sort.run(bins, fx::Jobs(), &order);
                EXPECT_NE(buffer, 0u);
                if (!buffer) return got;
                glBindBuffer(kShaderStorageBuffer, buffer);
                glGetBufferSubData(kShaderStorageBuffer, 0, GLsizeiptr(got.size() * 4), got.data());
                glBindBuffer(kShaderStorageBuffer, 0);
                return got;
            };
            // The GPU's words first: the CPU's upload would overwrite them.
            ASSERT_TRUE(sort.binOnGpu(view, instances, uint32_t(n), spheres, withReach ? reach : none, gpu, &tiles,
                                      &tileCapacity));
            ASSERT_TRUE(sort.readGpuBins(&gpu));
            const std::vector<uint32_t> fromGpu = listsOf(gpu);
            const std::vector<uint32_t> fromCpu = listsOf(cpu);
            EXPECT_TRUE(fromGpu == fromCpu) << fromGpu.size() << " entries against " << fromCpu.size();
            // The shade's tiles, where the GPU listed them.
            std::vector<uint32_t> listed(gpu.tiles.size());
            glBindBuffer(kShaderStorageBuffer, tiles);
            glGetBufferSubData(kShaderStorageBuffer, 0, GLsizeiptr(listed.size() * 4), listed.data());
            glBindBuffer(kShaderStorageBuffer, 0);
            EXPECT_TRUE(std::equal(listed.begin(), listed.end(), cpu.tiles.begin()));
            ++compared;
        }
    }
    EXPECT_EQ(compared, 4 * int(std::size(kCases)));
    // Rows and columns longer than a group (1,025 tiles: two cells a lane in the grid's sums).
    for (const glm::ivec2 size : {glm::ivec2(16400, 32), glm::ivec2(32, 16400)}) {
        SCOPED_TRACE(testing::Message() << size.x << "x" << size.y);
        Scene s = sceneOf(3000, 3.0f, 31);
        const fx::ViewInfo view = viewOf(size.x, size.y);
        fx::TileBins cpu, gpu;
        ASSERT_TRUE(fx::binParticles(view, s.particles.data(), s.ranges.data(), 3, nullptr, &cpu, fx::Jobs(),
                                     fx::TileBins::Fill::Ranges));
        ASSERT_GT(cpu.tileCount(), 0);
        glBindBuffer(kShaderStorageBuffer, instances);
        glBufferData(kShaderStorageBuffer, GLsizeiptr(s.particles.size() * sizeof(fx::ParticleInstance)),
                     s.particles.data(), 0x88E0);
        ASSERT_EQ(fx::placeBatches(s.ranges.data(), 3, &gpu), 3000);
        ASSERT_TRUE(sort.binOnGpu(view, instances, 3000u, 4u, fx::BillboardReach{}, gpu, &tiles, &tileCapacity));
        ASSERT_TRUE(sort.readGpuBins(&gpu));
        EXPECT_EQ(gpu.entryCount, cpu.entryCount);
        EXPECT_EQ(gpu.tiles, cpu.tiles);
        EXPECT_EQ(gpu.cover.vertices, cpu.cover.vertices);
    }
    // Nothing on the view: no tiles, no entries.
    {
        Scene s = sceneOf(300, 2.0f, 3);
        for (fx::ParticleInstance& p : s.particles) p.z = 40.0f;  // behind the camera
        const fx::ViewInfo view = viewOf(640, 480);
        glBindBuffer(kShaderStorageBuffer, instances);
        glBufferData(kShaderStorageBuffer, GLsizeiptr(s.particles.size() * sizeof(fx::ParticleInstance)),
                     s.particles.data(), 0x88E0);
        fx::TileBins gpu;
        ASSERT_EQ(fx::placeBatches(s.ranges.data(), 3, &gpu), 300);
        ASSERT_TRUE(sort.binOnGpu(view, instances, 300u, 4u, fx::BillboardReach{}, gpu, &tiles, &tileCapacity));
        ASSERT_TRUE(sort.readGpuBins(&gpu));
        EXPECT_EQ(gpu.entryCount, 0u);
        EXPECT_EQ(gpu.tileCount(), 0);
        EXPECT_TRUE(gpu.cover.vertices.empty());
        // One not finite: refused, and the next view is binned as before (the flag is not kept).
        s = sceneOf(300, 2.0f, 4);
        s.particles[17].size = std::nanf("");
        glBindBuffer(kShaderStorageBuffer, instances);
        glBufferData(kShaderStorageBuffer, GLsizeiptr(s.particles.size() * sizeof(fx::ParticleInstance)),
                     s.particles.data(), 0x88E0);
        ASSERT_TRUE(sort.binOnGpu(view, instances, 300u, 4u, fx::BillboardReach{}, gpu, &tiles, &tileCapacity));
        EXPECT_FALSE(sort.readGpuBins(&gpu));
        fx::TileBins cpu;
        EXPECT_FALSE(fx::binParticles(view, s.particles.data(), s.ranges.data(), 3, nullptr, &cpu, fx::Jobs(),
                                      fx::TileBins::Fill::Ranges));
        s.particles[17].size = 0.5f;
        glBindBuffer(kShaderStorageBuffer, instances);
        glBufferData(kShaderStorageBuffer, GLsizeiptr(s.particles.size() * sizeof(fx::ParticleInstance)),
                     s.particles.data(), 0x88E0);
        ASSERT_TRUE(fx::binParticles(view, s.particles.data(), s.ranges.data(), 3, nullptr, &cpu, fx::Jobs(),
                                     fx::TileBins::Fill::Ranges));
        ASSERT_TRUE(sort.binOnGpu(view, instances, 300u, 4u, fx::BillboardReach{}, gpu, &tiles, &tileCapacity));
        ASSERT_TRUE(sort.readGpuBins(&gpu));
        EXPECT_EQ(gpu.entryCount, cpu.entryCount);
        EXPECT_EQ(gpu.tiles, cpu.tiles);
    }
    glDeleteBuffers(1, &instances);
    glDeleteBuffers(1, &tiles);
}

}  // namespace tile_sort_test
}  // namespace fxtest
