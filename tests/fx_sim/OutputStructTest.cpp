// The structs the plugin writes for a 2.1 host (fx/fx.h: "Every struct the plugin writes ...
// begins with size"): filled up to the size the host set and not a byte past it; a size the
// library does not know, smaller or larger than its own struct, is refused with nothing written.
// Each out-pointer points into a buffer poisoned past (and, for refusals, in) the struct. The 2.0
// host of the same rule is tests/era/Api20Host.c.
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fx/fx.h"

namespace {

constexpr unsigned char kPoison = 0xA5;
constexpr size_t kGuard = 64;

/// An output struct of type T in a poisoned buffer with kGuard bytes after it.
template <class T>
struct Guarded {
    alignas(alignof(std::max_align_t)) unsigned char bytes[sizeof(T) + kGuard];
    explicit Guarded(uint32_t size) {
        std::memset(bytes, kPoison, sizeof bytes);
        std::memcpy(bytes, &size, sizeof size);  // every such struct begins with its size
    }
    T* out() { return reinterpret_cast<T*>(bytes); }
    /// The bytes from `from` on that are no longer the poison.
    size_t writtenFrom(size_t from) const {
        size_t n = 0;
        for (size_t i = from; i < sizeof bytes; ++i) n += bytes[i] != kPoison;
        return n;
    }
};

struct Host {
    std::vector<std::string> errors;
};
void* noGl(void*, const char*) { return nullptr; }
void hostLog(void* user, int level, const char* message) {
    if (level == FX_LOG_ERROR) static_cast<Host*>(user)->errors.push_back(message);
}
int twoWheels(void*) { return 2; }
// A standing burnout: both rear wheels spin on asphalt.
void spinningWheel(void*, int index, fxWheelContact* out) {
    std::memset(out, 0, sizeof *out);
    out->position[0] = index == 0 ? -0.8f : 0.8f;
    out->slip = 1.0f;
    out->grounded = 1;
    out->rear = 1;
}

class OutputStructTest : public ::testing::Test {
protected:
    void SetUp() override {
        api = fxGetApi(FX_API_VERSION);
        ASSERT_NE(api, nullptr);
        callbacks = FX_DESC_INIT(fxHostCallbacks);
        callbacks.user = &host;
        callbacks.getProcAddress = noGl;
        callbacks.log = hostLog;
        callbacks.wheelCount = twoWheels;
        callbacks.wheel = spinningWheel;
        fxPluginDesc desc = FX_DESC_INIT(fxPluginDesc);
        desc.host = &callbacks;
        plugin = api->create(&desc, nullptr);
        ASSERT_NE(plugin, nullptr);
        ASSERT_TRUE(api->loadReactions(plugin, CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml", nullptr));
        for (int i = 0; i < 30; ++i) ASSERT_EQ(api->continueReaction(plugin, 0, 1.0f / 60.0f, nullptr), FX_ERROR_NONE);
    }
    void TearDown() override { api->destroy(plugin); }

    /// What every refused size must give: the named code, one error logged, nothing written
    /// (the size field the host set included).
    template <class T, class Call>
    void expectRefusedSizes(const char* function, Call call) {
        for (uint32_t size : {uint32_t(0), uint32_t(sizeof(T) - 4), uint32_t(sizeof(T) + 8)}) {
            host.errors.clear();
            Guarded<T> g(size);
            EXPECT_EQ(call(g.out()), FX_ERROR_BAD_DESCRIPTOR) << function << " size " << size;
            EXPECT_EQ(g.writtenFrom(sizeof(uint32_t)), 0u) << function << " size " << size;
            ASSERT_EQ(host.errors.size(), 1u) << function << " size " << size;
            EXPECT_NE(host.errors[0].find(std::string("error[BadDescriptor] ") + function), std::string::npos)
                << host.errors[0];
        }
    }

    Host host;
    fxHostCallbacks callbacks{};
    const fxApi* api = nullptr;
    fxPlugin* plugin = nullptr;
};

TEST_F(OutputStructTest, SizedStatsMatchTheDeprecatedOnesAndStopAtTheStruct) {
    Guarded<fxStats2> s(sizeof(fxStats2));
    ASSERT_EQ(api->stats2(plugin, s.out()), FX_ERROR_NONE);
    EXPECT_EQ(s.writtenFrom(sizeof(fxStats2)), 0u);
    fxStats old;
    api->stats(plugin, &old);
    const fxStats2& c = *s.out();
    EXPECT_EQ(c.size, sizeof(fxStats2));
    EXPECT_EQ(c.reactions, 1);
    EXPECT_GT(c.particlesAlive, 0);
    EXPECT_EQ(c.reactions, old.reactions);
    EXPECT_EQ(c.particlesAlive, old.particlesAlive);
    EXPECT_EQ(c.particleCapacity, old.particleCapacity);
    EXPECT_EQ(c.particlesDrawn, old.particlesDrawn);
    EXPECT_EQ(c.reloads, old.reloads);
    EXPECT_EQ(c.reloadErrors, old.reloadErrors);
    EXPECT_EQ(c.apiErrors, old.apiErrors);

    Guarded<fxParticleCheck2> k(sizeof(fxParticleCheck2));
    ASSERT_EQ(api->checkParticles2(plugin, k.out()), FX_ERROR_NONE);
    EXPECT_EQ(k.writtenFrom(sizeof(fxParticleCheck2)), 0u);
    EXPECT_EQ(k.out()->alive, c.particlesAlive);
    EXPECT_EQ(k.out()->capacity, c.particleCapacity);
    EXPECT_EQ(k.out()->nonFinite, 0);
}

TEST_F(OutputStructTest, SizedReactionStatsAndKeysMatchTheDeprecatedOnes) {
    Guarded<fxReactionStats2> r(sizeof(fxReactionStats2));
    ASSERT_EQ(api->reactionStats2(plugin, 0, r.out()), FX_ERROR_NONE);
    EXPECT_EQ(r.writtenFrom(sizeof(fxReactionStats2)), 0u);
    fxReactionStats old;
    ASSERT_EQ(api->reactionStats(plugin, 0, &old), FX_ERROR_NONE);
    EXPECT_STREQ(r.out()->name, old.name);
    EXPECT_STREQ(r.out()->technique, old.technique);
    EXPECT_EQ(r.out()->alive, old.alive);
    EXPECT_EQ(r.out()->emitted, old.emitted);
    EXPECT_GT(r.out()->emitted, 0u);

    // A bad index is refused: nothing written (the 2.0 entry cleared its struct).
    Guarded<fxReactionStats2> bad(sizeof(fxReactionStats2));
    EXPECT_EQ(api->reactionStats2(plugin, 99, bad.out()), FX_ERROR_INDEX_OUT_OF_RANGE);
    EXPECT_EQ(bad.writtenFrom(sizeof(uint32_t)), 0u);

    ASSERT_GT(api->reactionKeyCount(plugin), 0);
    Guarded<fxReactionKeyInfo2> key(sizeof(fxReactionKeyInfo2));
    ASSERT_EQ(api->reactionKey2(plugin, 0, key.out()), FX_ERROR_NONE);
    EXPECT_EQ(key.writtenFrom(sizeof(fxReactionKeyInfo2)), 0u);
    fxReactionKeyInfo oldKey;
    ASSERT_EQ(api->reactionKey(plugin, 0, &oldKey), FX_ERROR_NONE);
    EXPECT_EQ(key.out()->key, oldKey.key);  // the same strings: they live as long as the plugin
    EXPECT_EQ(key.out()->kind, oldKey.kind);
    EXPECT_EQ(key.out()->choiceCount, oldKey.choiceCount);
    EXPECT_EQ(key.out()->help, oldKey.help);

    // A bad key index is refused: nothing written.
    Guarded<fxReactionKeyInfo2> badKey(sizeof(fxReactionKeyInfo2));
    EXPECT_EQ(api->reactionKey2(plugin, 9999, badKey.out()), FX_ERROR_INDEX_OUT_OF_RANGE);
    EXPECT_EQ(badKey.writtenFrom(sizeof(uint32_t)), 0u);
}

TEST_F(OutputStructTest, ASizeSmallerOrLargerThanTheLibrarysStructIsRefusedAndNothingWritten) {
    expectRefusedSizes<fxStats2>("stats2", [&](fxStats2* o) { return api->stats2(plugin, o); });
    expectRefusedSizes<fxParticleCheck2>("checkParticles2",
                                         [&](fxParticleCheck2* o) { return api->checkParticles2(plugin, o); });
    expectRefusedSizes<fxReactionStats2>("reactionStats2",
                                         [&](fxReactionStats2* o) { return api->reactionStats2(plugin, 0, o); });
    expectRefusedSizes<fxReactionKeyInfo2>("reactionKey2",
                                           [&](fxReactionKeyInfo2* o) { return api->reactionKey2(plugin, 0, o); });
    // The size is checked before the view: no GL and no view needed to see it refused.
    expectRefusedSizes<fxSmokeShadow2>(
        "declareShadowPasses2", [&](fxSmokeShadow2* o) { return api->declareShadowPasses2(plugin, nullptr, nullptr, o); });

    // Null out: refused, like every out-pointer of the table.
    EXPECT_EQ(api->stats2(plugin, nullptr), FX_ERROR_NULL_ARGUMENT);
    EXPECT_EQ(api->checkParticles2(plugin, nullptr), FX_ERROR_NULL_ARGUMENT);
    EXPECT_EQ(api->reactionStats2(plugin, 0, nullptr), FX_ERROR_NULL_ARGUMENT);
    EXPECT_EQ(api->reactionKey2(plugin, 0, nullptr), FX_ERROR_NULL_ARGUMENT);
    EXPECT_EQ(api->declareShadowPasses2(plugin, nullptr, nullptr, nullptr), FX_ERROR_NULL_ARGUMENT);
}

TEST_F(OutputStructTest, ARefusedShadowDeclarationWritesNothing) {
    // Unlike declareShadowPasses (2.0), which cleared its struct before refusing.
    Guarded<fxSmokeShadow2> s(sizeof(fxSmokeShadow2));
    EXPECT_EQ(api->declareShadowPasses2(plugin, nullptr, nullptr, s.out()), FX_ERROR_NULL_ARGUMENT);
    EXPECT_EQ(s.writtenFrom(sizeof(uint32_t)), 0u);
}

TEST_F(OutputStructTest, RenderOptionsCarryTheShapeAndAreWrittenOnlyUpToTheHostsSize) {
    fxRenderOptions set = FX_DESC_INIT(fxRenderOptions);
    set.techniqueOverride = FX_TECHNIQUE_HARD;
    set.particleShape = FX_SHAPE_QUAD;
    ASSERT_EQ(api->setRenderOptions(plugin, &set), FX_ERROR_NONE);
    EXPECT_EQ(api->particleShape(plugin), FX_SHAPE_QUAD);  // the deprecated getter sees the same

    Guarded<fxRenderOptions> all(sizeof(fxRenderOptions));
    api->getRenderOptions(plugin, all.out());
    EXPECT_EQ(all.writtenFrom(sizeof(fxRenderOptions)), 0u);
    EXPECT_EQ(all.out()->size, sizeof(fxRenderOptions));
    EXPECT_EQ(all.out()->techniqueOverride, FX_TECHNIQUE_HARD);
    EXPECT_EQ(all.out()->particleShape, FX_SHAPE_QUAD);

    // Smaller than the library's struct: 2.0's size gets 2.0's fields; the shape, past it, is not
    // written.
    const size_t size20 = offsetof(fxRenderOptions, particleShape);
    Guarded<fxRenderOptions> old{uint32_t(size20)};
    api->getRenderOptions(plugin, old.out());
    EXPECT_EQ(old.writtenFrom(size20), 0u);
    EXPECT_EQ(old.out()->size, size20);
    EXPECT_EQ(old.out()->techniqueOverride, FX_TECHNIQUE_HARD);

    // Larger, or a size the library does not know: the 2.0 fields, as 2.0 wrote whatever the size.
    Guarded<fxRenderOptions> large(uint32_t(sizeof(fxRenderOptions) + 8));
    api->getRenderOptions(plugin, large.out());
    EXPECT_EQ(large.writtenFrom(size20), 0u);
    EXPECT_EQ(large.out()->size, sizeof(fxRenderOptions) + 8);
    EXPECT_EQ(large.out()->techniqueOverride, FX_TECHNIQUE_HARD);
    EXPECT_TRUE(host.errors.empty());
}

TEST_F(OutputStructTest, SetRenderOptionsSetsTheShapeOnlyFromA21SizeAndRefusesABadOneWhole) {
    fxRenderOptions set = FX_DESC_INIT(fxRenderOptions);
    set.particleShape = FX_SHAPE_QUAD;
    ASSERT_EQ(api->setRenderOptions(plugin, &set), FX_ERROR_NONE);

    // A 2.0 host's struct ends before the shape: the shape stays as it was.
    fxRenderOptions set20 = FX_DESC_INIT(fxRenderOptions);
    set20.size = uint32_t(offsetof(fxRenderOptions, particleShape));
    set20.quarterRes = 1;
    set20.particleShape = 77;  // past its size: not read
    ASSERT_EQ(api->setRenderOptions(plugin, &set20), FX_ERROR_NONE);
    fxRenderOptions back = FX_DESC_INIT(fxRenderOptions);
    api->getRenderOptions(plugin, &back);
    EXPECT_EQ(back.particleShape, FX_SHAPE_QUAD);
    EXPECT_EQ(back.quarterRes, 1);

    // A bad shape refuses the whole call: the technique beside it is not set either.
    fxRenderOptions bad = FX_DESC_INIT(fxRenderOptions);
    bad.techniqueOverride = FX_TECHNIQUE_SOFT;
    bad.particleShape = 2;
    EXPECT_EQ(api->setRenderOptions(plugin, &bad), FX_ERROR_INVALID_VALUE);
    api->getRenderOptions(plugin, &back);
    EXPECT_EQ(back.techniqueOverride, FX_TECHNIQUE_FROM_REACTION);
    EXPECT_EQ(back.particleShape, FX_SHAPE_QUAD);
    EXPECT_EQ(back.quarterRes, 1);
    ASSERT_EQ(host.errors.size(), 1u);
    EXPECT_NE(host.errors[0].find("error[InvalidValue] setRenderOptions: particleShape = 2"), std::string::npos)
        << host.errors[0];
}

// quarterResAlways (2.1) reads back as set; a 2.0 host's size leaves it as it was, like the shape.
TEST_F(OutputStructTest, QuarterResAlwaysIsSetFromA21SizeAndKeptByA20One) {
    fxRenderOptions back = FX_DESC_INIT(fxRenderOptions);
    api->getRenderOptions(plugin, &back);
    EXPECT_EQ(back.quarterResAlways, 0) << "quarter res only where it pays, by default";

    fxRenderOptions set = FX_DESC_INIT(fxRenderOptions);
    set.quarterRes = 1;
    set.quarterResAlways = 1;
    ASSERT_EQ(api->setRenderOptions(plugin, &set), FX_ERROR_NONE);
    api->getRenderOptions(plugin, &back);
    EXPECT_EQ(back.quarterResAlways, 1);
    EXPECT_EQ(back.quarterRes, 1);

    fxRenderOptions set20 = FX_DESC_INIT(fxRenderOptions);
    set20.size = uint32_t(offsetof(fxRenderOptions, particleShape));
    set20.quarterRes = 1;
    set20.quarterResAlways = 0;  // past its size: not read
    ASSERT_EQ(api->setRenderOptions(plugin, &set20), FX_ERROR_NONE);
    api->getRenderOptions(plugin, &back);
    EXPECT_EQ(back.quarterResAlways, 1);

    set.quarterResAlways = 0;
    ASSERT_EQ(api->setRenderOptions(plugin, &set), FX_ERROR_NONE);
    api->getRenderOptions(plugin, &back);
    EXPECT_EQ(back.quarterResAlways, 0);
    EXPECT_TRUE(host.errors.empty());
}

// tiled (2.3) reads back as set; a 2.1-2.2 host's size (ending before it) is taken and leaves it
// as it was, and a read with that size writes nothing past it.
TEST_F(OutputStructTest, TiledIsSetFromA23SizeAndKeptByA22One) {
    fxRenderOptions back = FX_DESC_INIT(fxRenderOptions);
    api->getRenderOptions(plugin, &back);
    EXPECT_EQ(back.tiled, 0) << "left to tiling by default";

    fxRenderOptions set = FX_DESC_INIT(fxRenderOptions);
    set.tiled = 1;
    ASSERT_EQ(api->setRenderOptions(plugin, &set), FX_ERROR_NONE);
    api->getRenderOptions(plugin, &back);
    EXPECT_EQ(back.tiled, 1);

    const size_t size22 = offsetof(fxRenderOptions, tiled);
    fxRenderOptions set22 = FX_DESC_INIT(fxRenderOptions);
    set22.size = uint32_t(size22);
    set22.quarterResAlways = 1;
    set22.tiled = 0;  // past its size: not read
    ASSERT_EQ(api->setRenderOptions(plugin, &set22), FX_ERROR_NONE);
    api->getRenderOptions(plugin, &back);
    EXPECT_EQ(back.tiled, 1);
    EXPECT_EQ(back.quarterResAlways, 1) << "the 2.1 field inside a 2.2 size is read";

    Guarded<fxRenderOptions> old{uint32_t(size22)};
    api->getRenderOptions(plugin, old.out());
    EXPECT_EQ(old.writtenFrom(size22), 0u);
    EXPECT_EQ(old.out()->quarterResAlways, 1);

    set.tiled = 0;
    ASSERT_EQ(api->setRenderOptions(plugin, &set), FX_ERROR_NONE);
    api->getRenderOptions(plugin, &back);
    EXPECT_EQ(back.tiled, 0);
    EXPECT_TRUE(host.errors.empty());
}

// tiling (2.4): FX_TILING_AUTO by default; set from a 2.4 size, refused outside its enum (nothing
// changes), left as it was by a 2.3 host's size (ending before it), and not written past that
// size by a read.
TEST_F(OutputStructTest, TilingIsAutoBySetFromA24SizeAndKeptByA23One) {
    fxRenderOptions back = FX_DESC_INIT(fxRenderOptions);
    api->getRenderOptions(plugin, &back);
    EXPECT_EQ(back.tiling, FX_TILING_AUTO);

    fxRenderOptions set = FX_DESC_INIT(fxRenderOptions);
    set.tiling = FX_TILING_OFF;
    ASSERT_EQ(api->setRenderOptions(plugin, &set), FX_ERROR_NONE);
    api->getRenderOptions(plugin, &back);
    EXPECT_EQ(back.tiling, FX_TILING_OFF);

    set.tiling = 3;
    set.quarterRes = 1;
    EXPECT_EQ(api->setRenderOptions(plugin, &set), FX_ERROR_INVALID_VALUE);
    api->getRenderOptions(plugin, &back);
    EXPECT_EQ(back.tiling, FX_TILING_OFF);
    EXPECT_EQ(back.quarterRes, 0) << "a refused call sets no field";
    ASSERT_EQ(host.errors.size(), 1u);
    EXPECT_NE(host.errors[0].find("tiling = 3"), std::string::npos) << host.errors[0];
    host.errors.clear();

    const size_t size23 = offsetof(fxRenderOptions, tiling);
    fxRenderOptions set23 = FX_DESC_INIT(fxRenderOptions);
    set23.size = uint32_t(size23);
    set23.tiled = 1;
    set23.tiling = FX_TILING_ON;  // past its size: not read
    ASSERT_EQ(api->setRenderOptions(plugin, &set23), FX_ERROR_NONE);
    api->getRenderOptions(plugin, &back);
    EXPECT_EQ(back.tiling, FX_TILING_OFF);
    EXPECT_EQ(back.tiled, 1) << "the 2.3 field inside a 2.3 size is read";

    Guarded<fxRenderOptions> old{uint32_t(size23)};
    api->getRenderOptions(plugin, old.out());
    EXPECT_EQ(old.writtenFrom(size23), 0u);
    EXPECT_EQ(old.out()->tiled, 1);
    EXPECT_TRUE(host.errors.empty());
}

// fxHostCallbacks grew in 2.2 (parallelFor): a 2.0/2.1 host's size is taken, parallelFor past it
// is not read (a poisoned pointer there would crash the first large view); a size between the two
// is refused with the sizes it could have been.
TEST(HostCallbacksSize, A21SizeIsTakenWithoutItsTailAndAnUnknownOneRefused) {
    const fxApi* api = fxGetApi(FX_API_VERSION);
    ASSERT_NE(api, nullptr);
    Host host;
    fxHostCallbacks callbacks;
    std::memset(&callbacks, kPoison, sizeof callbacks);  // parallelFor: not a function
    callbacks.size = uint32_t(offsetof(fxHostCallbacks, parallelFor));
    callbacks.user = &host;
    callbacks.getProcAddress = noGl;
    callbacks.log = hostLog;
    callbacks.wheelCount = nullptr;
    callbacks.wheel = nullptr;
    callbacks.wind = nullptr;
    callbacks.collisionPoint = nullptr;
    fxPluginDesc desc = FX_DESC_INIT(fxPluginDesc);
    desc.host = &callbacks;
    fxPlugin* plugin = api->create(&desc, nullptr);
    ASSERT_NE(plugin, nullptr);
    api->destroy(plugin);
    EXPECT_TRUE(host.errors.empty());

    // A table of unknown size cannot be trusted to hold its log: the line goes to stderr.
    callbacks.size = uint32_t(offsetof(fxHostCallbacks, parallelFor) + 4);
    int error = FX_ERROR_NONE;
    testing::internal::CaptureStderr();
    EXPECT_EQ(api->create(&desc, &error), nullptr);
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_EQ(error, FX_ERROR_BAD_DESCRIPTOR);
    EXPECT_TRUE(host.errors.empty());
    EXPECT_NE(said.find("fxHostCallbacks::size = " + std::to_string(callbacks.size) + "; expected " +
                        std::to_string(sizeof(fxHostCallbacks))),
              std::string::npos)
        << said;
}

}  // namespace
