// No host state reaches the plugin's image. Before every plugin call (the
// plugin's prepareGl, declarePasses and each pass it declared) the host is put into GL's default
// state and then poisoned with one state of PoisonedHostState.h (or all of them at once); after
// the call every poisoned and listed state must read back the host's poisoned value, with no GL
// error, and the frame must equal the clean host's bit for bit, for every technique. ctest runs
// this file twice: in the fx_host's 3.3 core context and, with CUBE_FX_HOST_PROFILE=compat, in a
// compatibility-profile context where the fixed-function leftovers of a legacy engine (alpha
// test, user clip planes, pixel transfer, colour clamping, polygon stipple, LOD bias) exist too.
#include <glad/gl.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "FxTestHost.h"
#include "PoisonedHostState.h"
#include "render/TiledPath.h"
#include "render/PinnedGlState.h"

namespace fxtest {
namespace poisoned_host_test {

constexpr int kW = 160, kH = 120;

const RenderMode kModes[] = {
    modes::kHard,
    modes::kSoft,
    modes::kSpherical,
    {"hard quarter", fx::Technique::Hard, true},
    modes::kSoftQuarter,
    modes::kSphericalQuarter,
    modes::kMega,
    modes::kSoftLit,
    modes::kHardTiled,
    modes::kSoftTiled,
    modes::kSphericalTiled,
    modes::kSoftLitTiled,
    {"spherical lit tiled", fx::Technique::Spherical, false, true, true},
    {"spherical quarter lit", fx::Technique::Spherical, true, true},
    {"from reactions (stateless sparks too)", fx::Technique::FromReaction},
};

std::function<void()> allPoisons() {
    return [] {
        for (const HostPoison& p : hostPoisons()) p.apply();
    };
}

/// The poisons a frame is checked under one at a time. ctest runs this file in the core context
/// and again in the compatibility context; the second run takes one at a time only the poisons its
/// profile adds. The core ones were each checked alone by the first run, and the second still has
/// them in its all-at-once frame, whose image and host state it checks like any other (two poisons
/// cannot undo each other: each sets its own state away from GL's default). That frame failing
/// names no poison: CUBE_FX_HOST_EVERY_POISON=1 takes every one alone, to find it. (Every poison
/// alone in both contexts cost 4.2 times the frames: 98 s of the suite's 365, 198 s of the
/// sanitizers' 748, on two cores.)
std::vector<const HostPoison*> singlePoisons() {
    const char* every = std::getenv("CUBE_FX_HOST_EVERY_POISON");
    const bool all = !osMesaCompatibilityProfile() || (every && std::string(every) == "1");
    std::vector<const HostPoison*> list;
    for (const HostPoison& p : hostPoisons()) {
        if (all || p.compatibility) list.push_back(&p);
    }
    return list;
}

/// The sanitizers' run (scripts/sanitize.sh) sets CUBE_FX_HOST_POISON_STRIDE=4: a test that checks
/// several techniques then takes one poison in four alone through each, the next quarter through
/// the next technique, so that every poison still goes alone through one of its techniques'
/// frames (the stride is capped at their number) and every technique through the all-at-once
/// frame. The plugin's code a poison leads through is the same for every technique; what the
/// sanitizers look for is in that code, not in which technique's image it guards. prepareGl's test
/// has one technique: one poison in four alone there. Unset (the suite): every poison alone
/// through every technique. (Under the sanitizers every poison alone cost 227 s of the stage's
/// 1,051 test seconds.)
int poisonStride() {
    const char* v = std::getenv("CUBE_FX_HOST_POISON_STRIDE");
    const int stride = v ? std::atoi(v) : 1;
    return stride >= 1 && stride <= 16 ? stride : 1;
}

class PoisonedHostTest : public PluginHostTest {
protected:
    PoisonedHostTest() : PluginHostTest(kW, kH) {}
    void SetUp() override {
        PluginHostTest::SetUp();
        single_ = singlePoisons();
        stride_ = poisonStride();
        resetHostState();
        createPlugin(CUBE_SOURCE_DIR "/reactions");
        prepare(nullptr);
    }
    void TearDown() override {
        graph.beforePluginPass = nullptr;
        graph.afterPluginPass = nullptr;
        PluginHostTest::TearDown();
    }

    /// The smoke and sparks every frame shows (no simulation between frames: frames repeat).
    void prepare(const std::function<void()>* poison) {
        simulate(1.0f, 60);
        ASSERT_EQ(plugin->fireReaction("explosion", glm::vec3(-0.5f, 0.8f, 1.5f)), fx::ErrorCode::None);
        simulate(1.0f, 6);
        useWallScene();
        begin(poison);
        fx::Diagnostics diags;
        EXPECT_TRUE(plugin->prepareGl(&diags)) << (diags.empty() ? "" : diags.front().str());
        end("prepareGl");
    }

    // Around every plugin call: clean + poison, then check + clean.
    void begin(const std::function<void()>* poison) {
        resetHostState();
        if (poison) (*poison)();
        drainGlErrors("poisoning");
        errorsBefore_ = glErrorCount();
        snapshot_ = readHostState();
    }
    void end(const std::string& where) {
        drainGlErrors(where.c_str());
        if (glErrorCount() != errorsBefore_) problems_ += where + ": GL error\n";
        const std::string d = diffHostState(snapshot_, readHostState());
        if (!d.empty()) problems_ += where + " changed host state:\n" + d;
        resetHostState();
    }

    /// One frame with `poison` (null: the clean host) before every plugin call.
    Image frame(const std::function<void()>* poison) {
        problems_.clear();
        graph.beforePluginPass = [this, poison] { begin(poison); };
        graph.afterPluginPass = [this](const std::string& pass) { end(pass); };
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
            begin(poison);
            plugin->declarePasses(view, f);
            end("declarePasses");
        });
        graph.beforePluginPass = nullptr;
        graph.afterPluginPass = nullptr;
        return graph.readColor();
    }

    /// Mode `m` set (and prepared, as a host does after changing options: else the first frame
    /// builds the tiled programs while declaring and orders its particles on the CPU), then its
    /// frame for the clean host into *clean: false (and a failure) where it changed host state
    /// or drew nothing, which would leave the poisons proving nothing.
    bool cleanFrame(const RenderMode& m, Image* clean) {
        setMode(m);
        EXPECT_TRUE(plugin->prepareGl(nullptr)) << m.label;
        const Image bare = render(false);
        *clean = frame(nullptr);
        EXPECT_TRUE(problems_.empty()) << m.label << " (clean host):\n" << problems_;
        EXPECT_GT(maxAbsDiff(*clean, bare), 0) << m.label << ": nothing drawn, the test would prove nothing";
        return problems_.empty() && maxAbsDiff(*clean, bare) > 0;
    }
    /// The poisons that go alone through technique `turn` of a test's `turns` (poisonStride).
    std::vector<const HostPoison*> aloneIn(int turn, int turns) const {
        const size_t stride = size_t(std::min(stride_, std::max(turns, 1)));
        std::vector<const HostPoison*> list;
        for (size_t i = 0; i < single_.size(); ++i) {
            if (i % stride == size_t(turn) % stride) list.push_back(single_[i]);
        }
        return list;
    }

    /// A frame under each of `alone`, then under all at once: each must equal `clean` and leave
    /// the host's state as it was. The names of the poisons that reached the image (none, or a
    /// failure), and the all-at-once frame's max difference in *allAtOnce.
    std::vector<std::string> poisonedFrames(const RenderMode& m, const Image& clean,
                                            const std::vector<const HostPoison*>& alone, int* allAtOnce) {
        std::vector<std::string> changed;
        for (const HostPoison* p : alone) {
            const Image img = frame(&p->apply);
            const int diff = maxAbsDiff(img, clean);
            EXPECT_TRUE(problems_.empty()) << m.label << ", poisoned " << p->name << ":\n" << problems_;
            EXPECT_EQ(diff, 0) << m.label << ": poisoned " << p->name << " reached the image";
            if (diff != 0) changed.push_back(p->name);
        }
        const std::function<void()> all = allPoisons();
        const Image img = frame(&all);
        *allAtOnce = maxAbsDiff(img, clean);
        EXPECT_TRUE(problems_.empty()) << m.label << ", all poisons at once:\n" << problems_;
        EXPECT_EQ(*allAtOnce, 0) << m.label << ": all poisons at once reached the image";
        return changed;
    }

    std::vector<const HostPoison*> single_;  // singlePoisons(), once the context is made (SetUp)
    int stride_ = 1;                          // poisonStride()
    std::string problems_;
    HostStateReadback snapshot_;
    int errorsBefore_ = 0;
};

TEST_F(PoisonedHostTest, EveryTechniqueIgnoresEachPoisonedState) {
    const auto& poisons = hostPoisons();
    int compat = 0;
    for (const HostPoison& p : poisons) compat += p.compatibility;
    std::printf("[ measured ] %s context: %zu poisoned states (%zu core, %d compatibility-only), %zu of them one at a time\n",
                osMesaCompatibilityProfile() ? "compatibility" : "core", poisons.size(), poisons.size() - size_t(compat),
                compat, single_.size());
    EXPECT_EQ(compat > 0, osMesaCompatibilityProfile()) << "the compatibility context's run checks its own poisons";
    const fx::PinnedGlStateCount rows = fx::pinnedGlStateCount();
    std::printf("[ measured ] the plugin's guard: %d rows (%d core, %d compatibility-only)\n",
                rows.core + rows.compatibility, rows.core, rows.compatibility);
    EXPECT_GE(rows.core + rows.compatibility, osMesaCompatibilityProfile() ? 80 : 60);
    EXPECT_EQ(rows.compatibility > 0, osMesaCompatibilityProfile());
    std::set<std::string> changedImage;
    std::set<const HostPoison*> aloneSomewhere;
    const int turns = int(std::size(kModes));
    for (int turn = 0; turn < turns; ++turn) {
        const RenderMode& m = kModes[turn];
        Image clean;
        ASSERT_TRUE(cleanFrame(m, &clean));
        if (m.tiled) {
            EXPECT_TRUE(graph.ran(fx::TiledPath::kPass)) << m.label << ": the tiled pass did not run";
        }
        int allAtOnce = 0;
        const std::vector<const HostPoison*> alone = aloneIn(turn, turns);
        aloneSomewhere.insert(alone.begin(), alone.end());
        const std::vector<std::string> changed = poisonedFrames(m, clean, alone, &allAtOnce);
        changedImage.insert(changed.begin(), changed.end());
        std::printf("[ measured ] %-40s %zu of %zu poisons changed the image; all at once: max diff %d\n", m.label,
                    changed.size(), alone.size(), allAtOnce);
    }
    EXPECT_EQ(aloneSomewhere.size(), single_.size()) << "every poison alone through some technique";
    std::string names;
    for (const std::string& n : changedImage) names += "  " + n + "\n";
    std::printf("[ measured ] poisons that changed some technique's image: %zu\n%s", changedImage.size(),
                names.c_str());
}

// The tiled path under each poison. Run again by ctest (PoisonedHostTest.TiledOnTheGpusWay, core
// and compatibility contexts) with the lists and the particles' order on the GPU, as a GPU runs a
// large view (the plugin library reads that from the environment): its bins then wait for its
// passes (TiledPath::deferBins), two of them. The same frame as the clean host's, and the host's
// state back after each pass.
TEST_F(PoisonedHostTest, TiledViewsIgnoreEachPoisonedStateInOneOrTwoPasses) {
    auto set = [](const char* name) {
        const char* v = std::getenv(name);
        return v && std::string(v) == "0";
    };
    const bool gpusWay = set("CUBEFX_TILED_CPU_LISTS") && set("CUBEFX_TILED_GPU_ORDER");
    const RenderMode tiled[] = {modes::kSoftTiled, modes::kSoftLitTiled, modes::kSphericalTiled};
    for (int turn = 0; turn < 3; ++turn) {
        const RenderMode& m = tiled[turn];
        Image clean;
        ASSERT_TRUE(cleanFrame(m, &clean));
        ASSERT_TRUE(graph.ran(fx::TiledPath::kPass)) << m.label;
        ASSERT_EQ(graph.ran(fx::TiledPath::kSetupPass), gpusWay) << m.label << ": binned in its passes only the GPU's way";
        int allAtOnce = 0;
        poisonedFrames(m, clean, aloneIn(turn, 3), &allAtOnce);
    }
}

// The immediate path (Plugin::renderView, API 2) under each poison: the host draws its scene into
// its framebuffer (colour + its own z-buffer), is poisoned, and calls renderView once with the
// depth left in that framebuffer; the plugin copies and linearises it itself. The picture equals
// the clean host's bit for bit and the host's state reads back unchanged.
TEST_F(PoisonedHostTest, TheImmediatePathIgnoresEachPoisonedState) {
    const GLuint fbo = graph.colorFramebuffer();
    auto immediateFrame = [&](const std::function<void()>* poison) {
        problems_.clear();
        resetHostState();
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        scene.drawOpaque(view);
        resetHostState();
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(0, 0, kW, kH);
        if (poison) (*poison)();
        // Where to draw is the call's input, not a leftover: the draw framebuffer and the viewport
        // are put back after the poisons that move them (the read framebuffer, programs, textures
        // and buffers they bind stay poisoned).
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
        glViewport(0, 0, kW, kH);
        drainGlErrors("poisoning");
        errorsBefore_ = glErrorCount();
        snapshot_ = readHostState();
        EXPECT_EQ(plugin->renderView(view, fx::HostDepth{}), fx::ErrorCode::None);
        end("renderView");
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return readFramebuffer(fbo, kW, kH);
    };
    const RenderMode immediate[] = {kModes[0], kModes[1], kModes[2], kModes[4], kModes[6], kModes[7]};
    for (int turn = 0; turn < 6; ++turn) {
        const RenderMode& m = immediate[turn];
        setMode(m);
        const Image clean = immediateFrame(nullptr);
        ASSERT_TRUE(problems_.empty()) << m.label << " (clean host):\n" << problems_;
        ASSERT_GT(maxAbsDiff(clean, render(false)), 0) << m.label << ": nothing drawn, the test would prove nothing";
        int changed = 0;
        const std::vector<const HostPoison*> alone = aloneIn(turn, 6);
        for (const HostPoison* p : alone) {
            const Image img = immediateFrame(&p->apply);
            EXPECT_TRUE(problems_.empty()) << m.label << ", poisoned " << p->name << ":\n" << problems_;
            EXPECT_EQ(maxAbsDiff(img, clean), 0) << m.label << ": poisoned " << p->name << " reached the image";
            changed += maxAbsDiff(img, clean) != 0;
        }
        const std::function<void()> all = allPoisons();
        const Image img = immediateFrame(&all);
        EXPECT_TRUE(problems_.empty()) << m.label << ", all poisons at once:\n" << problems_;
        EXPECT_EQ(maxAbsDiff(img, clean), 0) << m.label << ": all poisons at once reached the image";
        std::printf("[ measured ] renderView %-28s %d of %zu poisons changed the image; all at once: max diff %d\n",
                    m.label, changed, alone.size(), maxAbsDiff(img, clean));
    }
}

// prepareGl (the atlas, ramp and normal uploads, every program) under each poison: a fresh
// plugin per poison, its first frame compared with a plugin prepared by a clean host.
TEST_F(PoisonedHostTest, PrepareGlUnderEachPoisonUploadsTheSameData) {
    const RenderMode& soft = kModes[7];  // lit soft: atlas, normals, ramp and the opacity map all show
    setMode(soft);
    const Image clean = frame(nullptr);
    ASSERT_TRUE(problems_.empty()) << problems_;
    // One technique: the first turn of as many as the stride has (under the sanitizers one in four).
    std::vector<const HostPoison*> list = aloneIn(0, stride_);
    const HostPoison all{"all at once", false, allPoisons()};
    list.push_back(&all);
    int changed = 0;
    for (const HostPoison* p : list) {
        plugin.reset();
        createPlugin(CUBE_SOURCE_DIR "/reactions");
        problems_.clear();
        prepare(&p->apply);
        EXPECT_TRUE(problems_.empty()) << "prepareGl, poisoned " << p->name << ":\n" << problems_;
        setMode(soft);
        const Image img = frame(nullptr);
        const int diff = maxAbsDiff(img, clean);
        EXPECT_EQ(diff, 0) << "prepareGl, poisoned " << p->name << " reached the image";
        if (diff != 0) {
            ++changed;
            std::printf("[ measured ] prepareGl poisoned by %s: max diff %d\n", p->name.c_str(), diff);
        }
    }
    std::printf("[ measured ] prepareGl: %d of %zu poisons changed the image\n", changed, list.size());
}

}  // namespace poisoned_host_test
}  // namespace fxtest
