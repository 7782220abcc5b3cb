// The plugin glue (PluginImpl) driven by a fake host: entry-point version check, loading,
// Reaction::Continue with the host's wheels and collision amount, the frame settings, stats, and
// hot reload that keeps the particles of reactions whose name and capacity did not change.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "../../fx_plugin/src/PluginImpl.h"

namespace fs = std::filesystem;

namespace {

class FakeHost : public fx::HostAdapter {
public:
    void* getProcAddress(const char*) override { return nullptr; }
    int wheelCount() const override { return static_cast<int>(wheels.size()); }
    fx::WheelContact wheel(int i) const override { return wheels.at(static_cast<size_t>(i)); }
    glm::vec3 wind() const override { return glm::vec3(1.0f, 0.0f, 0.0f); }
    glm::vec3 collisionPoint() const override { return glm::vec3(2.0f, 0.5f, 0.0f); }
    void log(fx::LogLevel level, const char* message) override {
        if (level == fx::LogLevel::Error) errors.push_back(message);
    }
    std::vector<fx::WheelContact> wheels;
    std::vector<std::string> errors;
};

class FakeFrame : public fx::FrameBuilder {
public:
    fx::Target sceneColor() override { return fx::Target{1}; }
    fx::Target sceneDepth() override { return fx::Target{2}; }
    fx::Target createTarget(const char*, const fx::TargetDesc&) override { return fx::Target{3}; }
    void addPass(const char*, std::initializer_list<fx::Target>, std::initializer_list<fx::Target>,
                 std::function<void(fx::PassContext&)>) override {
        ++passes;
    }
    int passes = 0;
};

const std::string kReactions = std::string(CUBE_SOURCE_DIR) + "/reactions";

std::unique_ptr<fx::Plugin> create(FakeHost* host) {
    fx::PluginImports imports;
    imports.host = host;
    return fxCreatePlugin(imports);
}

void burnout(FakeHost* host) {
    host->wheels.assign(4, fx::WheelContact{});
    for (int i = 0; i < 4; ++i) {
        fx::WheelContact& w = host->wheels[static_cast<size_t>(i)];
        w.grounded = true;
        w.rear = i >= 2;
        w.slip = w.rear ? 1.0f : 0.0f;
        w.position = glm::vec3(i % 2 ? 0.8f : -0.8f, 0.0f, w.rear ? -1.4f : 1.4f);
    }
}

int indexOf(const fx::Plugin& p, const std::string& name) {
    for (int i = 0; i < p.reactionCount(); ++i) {
        if (p.reactionName(i) == name) return i;
    }
    return -1;
}

TEST(Plugin, EntryPointChecksVersionAndHost) {
    FakeHost host;
    fx::PluginImports imports;
    imports.host = &host;
    imports.apiVersion = fx::kApiVersion + 1;
    EXPECT_EQ(fxCreatePlugin(imports), nullptr);
    imports.apiVersion = fx::kApiVersion;
    imports.host = nullptr;
    EXPECT_EQ(fxCreatePlugin(imports), nullptr);
    imports.host = &host;
    EXPECT_NE(fxCreatePlugin(imports), nullptr);
}

TEST(Plugin, ContinueEmitsFromTheHostsWheelsAndCollisions) {
    FakeHost host;
    auto plugin = create(&host);
    fx::Diagnostics diags;
    ASSERT_TRUE(plugin->loadReactions(kReactions, &diags));
    ASSERT_EQ(plugin->reactionCount(), 12);
    EXPECT_EQ(plugin->reactionName(12), "");  // one past the last
    burnout(&host);
    const int smoke = indexOf(*plugin, "burnout_smoke");
    const int dust = indexOf(*plugin, "offtrack_dust");
    const int burst = indexOf(*plugin, "barrier_burst");
    float amount = 0.0f;
    for (int i = 0; i < 60; ++i) {
        amount = i == 30 ? 1.0f : 0.0f;
        for (int r = 0; r < plugin->reactionCount(); ++r) plugin->continueReaction(r, 1.0f / 60.0f, &amount);
    }
    const auto& impl = fx::implOf(*plugin);
    EXPECT_NEAR(impl.runtimes()[static_cast<size_t>(smoke)].pool().alive(), 180, 1);  // 2 x 90/s x 1 s
    EXPECT_EQ(impl.runtimes()[static_cast<size_t>(dust)].pool().alive(), 0);          // on asphalt
    EXPECT_EQ(impl.runtimes()[static_cast<size_t>(burst)].counters().bursts, 1u);
    EXPECT_EQ(impl.runtimes()[static_cast<size_t>(burst)].counters().emitted, 40u);
    plugin->continueReaction(burst, 1.0f / 60.0f, nullptr);  // null amount = no collision
    EXPECT_EQ(plugin->stats().reactions, 12);
    int alive = 0;
    for (const auto& rt : impl.runtimes()) alive += rt.stateless() ? rt.ring().alive(rt.time()) : rt.pool().alive();
    EXPECT_EQ(plugin->stats().particlesAlive, alive);  // stateless sparks counted from their ring
}

TEST(Plugin, ReactionStatsNameTechniqueAliveAndEmitted) {
    FakeHost host;
    auto plugin = create(&host);
    ASSERT_TRUE(plugin->loadReactions(kReactions, nullptr));
    burnout(&host);
    const int smoke = indexOf(*plugin, "burnout_smoke");
    const int burst = indexOf(*plugin, "barrier_burst");
    // 3 s of burnout: the first puffs (3-5 s lives) are still alive; one barrier hit.
    for (int i = 0; i < 180; ++i) {
        float amount = i == 30 ? 1.0f : 0.0f;
        for (int r = 0; r < plugin->reactionCount(); ++r) plugin->continueReaction(r, 1.0f / 60.0f, &amount);
    }
    // Then 2 s of rolling without slip: smoke stops emitting, its oldest puffs die.
    for (int w = 0; w < host.wheelCount(); ++w) host.wheels[static_cast<size_t>(w)].slip = 0.0f;
    for (int i = 0; i < 120; ++i) {
        for (int r = 0; r < plugin->reactionCount(); ++r) plugin->continueReaction(r, 1.0f / 60.0f, nullptr);
    }
    const auto& impl = fx::implOf(*plugin);
    const fx::ReactionStats s = plugin->reactionStats(smoke);
    EXPECT_EQ(s.name, "burnout_smoke");
    EXPECT_EQ(s.technique, "soft");
    EXPECT_EQ(s.alive, impl.runtimes()[static_cast<size_t>(smoke)].pool().alive());
    EXPECT_NEAR(static_cast<double>(s.emitted), 2 * 90 * 3, 2);  // 2 wheels x 90/s x 3 s, within 1 each
    EXPECT_LT(s.alive, static_cast<int>(s.emitted));              // some died: alive is not emitted
    const fx::ReactionStats b = plugin->reactionStats(burst);
    EXPECT_EQ(b.name, "barrier_burst");
    EXPECT_EQ(b.emitted, 40u);
    EXPECT_EQ(b.alive, 0);  // 0.8-1.8 s lives, hit 4 s before the end
    const int errorsBefore = plugin->stats().apiErrors;
    EXPECT_EQ(plugin->reactionStats(99).name, "");
    EXPECT_EQ(plugin->stats().apiErrors, errorsBefore + 1);  // refused and counted
}

TEST(Plugin, FireReactionSetsOffEveryLayerOfTheRecipeOnce) {
    FakeHost host;
    auto plugin = create(&host);
    ASSERT_TRUE(plugin->loadReactions(kReactions, nullptr));
    const int errors = plugin->stats().apiErrors;
    EXPECT_EQ(plugin->fireReaction("explosion", glm::vec3(1.0f, 0.5f, 2.0f)), fx::ErrorCode::None);
    for (int i = 0; i < 3; ++i) {
        for (int r = 0; r < plugin->reactionCount(); ++r) plugin->continueReaction(r, 1.0f / 60.0f, nullptr);
    }
    int layers = 0;
    for (int r = 0; r < plugin->reactionCount(); ++r) {
        const fx::ReactionStats s = plugin->reactionStats(r);
        if (s.name.rfind("explosion.", 0) == 0) {
            ++layers;
            EXPECT_GT(s.emitted, 0u) << s.name;  // every layer fired, once
        } else {
            EXPECT_EQ(s.emitted, 0u) << s.name;  // nothing else did
        }
    }
    EXPECT_EQ(layers, 5);
    EXPECT_EQ(plugin->reactionStats(indexOf(*plugin, "explosion.sparks")).emitted, 320u);  // one burst
    EXPECT_EQ(plugin->stats().apiErrors, errors);
    // Refused and counted: a name that is not an on_demand reaction, a prefix that is not a whole
    // name part, a non-finite point.
    EXPECT_EQ(plugin->fireReaction("burnout_smoke", glm::vec3(0.0f)), fx::ErrorCode::InvalidValue);
    EXPECT_EQ(plugin->fireReaction("explo", glm::vec3(0.0f)), fx::ErrorCode::InvalidValue);
    EXPECT_EQ(plugin->fireReaction("explosion", glm::vec3(NAN, 0.0f, 0.0f)), fx::ErrorCode::InvalidValue);
    EXPECT_EQ(plugin->stats().apiErrors, errors + 3);
}

TEST(Plugin, SettersWriteTheOneFrameSettingsTheRenderersAreHanded) {
    // PluginImpl directly, without installRenderers (fxCreatePlugin makes the GL renderers, and
    // this test has no GL context; the engine-free GL host tests cover that path).
    FakeHost host;
    fx::PluginImports imports;
    imports.host = &host;
    auto plugin = std::make_unique<fx::PluginImpl>(imports);
    ASSERT_TRUE(plugin->loadReactions(kReactions + "/burnout_smoke.yaml", nullptr));
    FakeFrame frame;
    fx::ViewInfo view;
    view.width = 64;   // a valid view (the default size 0 is refused as InvalidView)
    view.height = 48;
    EXPECT_EQ(plugin->declarePasses(view, frame), fx::ErrorCode::None);  // no renderers: nothing declared
    EXPECT_EQ(frame.passes, 0);
    EXPECT_EQ(plugin->stats().particlesDrawn, 0);
    EXPECT_EQ(plugin->renderers(), nullptr);

    fx::RenderOptions opts;
    opts.quarterRes = true;
    opts.techniqueOverride = fx::Technique::Mega;
    ASSERT_EQ(plugin->setRenderOptions(opts), fx::ErrorCode::None);
    ASSERT_EQ(plugin->setParticleShape(fx::ParticleShape::Quad), fx::ErrorCode::None);
    ASSERT_EQ(plugin->setSceneLight(fx::SceneLight{}), fx::ErrorCode::None);
    const fx::FrameSettings& s = plugin->frameSettings();
    EXPECT_TRUE(s.options.quarterRes);
    EXPECT_EQ(s.options.techniqueOverride, fx::Technique::Mega);
    EXPECT_EQ(s.shape, fx::ParticleShape::Quad);
    EXPECT_TRUE(s.light.on);
    // A refused value leaves the settings as they were.
    fx::RenderOptions bad = opts;
    bad.techniqueOverride = static_cast<fx::Technique>(99);
    EXPECT_EQ(plugin->setRenderOptions(bad), fx::ErrorCode::InvalidValue);
    EXPECT_EQ(plugin->frameSettings().options.techniqueOverride, fx::Technique::Mega);
    plugin->clearSceneLight();
    EXPECT_FALSE(plugin->frameSettings().light.on);
}

TEST(Plugin, ImportedSeedPicksTheParticles) {
    auto run = [](uint64_t seed) {
        FakeHost host;
        burnout(&host);
        fx::PluginImports imports;
        imports.host = &host;
        imports.seed = seed;
        auto plugin = fxCreatePlugin(imports);
        EXPECT_TRUE(plugin->loadReactions(kReactions + "/burnout_smoke.yaml", nullptr));
        for (int i = 0; i < 20; ++i) plugin->continueReaction(0, 1.0f / 60.0f, nullptr);
        const auto& impl = fx::implOf(*plugin);
        return impl.runtimes()[0].pool().posX()[0];
    };
    EXPECT_EQ(run(0), run(fx::ReactionRuntime::kDefaultSeed));  // 0 = the default seed
    EXPECT_EQ(run(5), run(5));
    EXPECT_NE(run(5), run(6));
}

TEST(Plugin, FailedLoadKeepsTheRunningSet) {
    FakeHost host;
    auto plugin = create(&host);
    ASSERT_TRUE(plugin->loadReactions(kReactions + "/burnout_smoke.yaml", nullptr));
    fx::Diagnostics diags;
    EXPECT_FALSE(plugin->loadReactions("/nonexistent/reactions", &diags));
    ASSERT_EQ(diags.size(), 1u);
    EXPECT_EQ(diags[0].code, fx::ErrorCode::FileNotFound);
    EXPECT_FALSE(host.errors.empty());  // and the host's log heard about it
    EXPECT_EQ(plugin->reactionCount(), 1);
}

class PluginReload : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("fx_plugin_reload_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    void write(const std::string& drag, int capacity, const char* extraName = nullptr) {
        std::string text = "reactions:\n  - name: smoke\n    type: wheel_smoke\n"
                           "    emission: {rate: 100, capacity: " + std::to_string(capacity) +
                           "}\n    particle: {drag: " + drag + ", lifetime: [8, 8]}\n";
        if (extraName) text += "  - {name: " + std::string(extraName) + ", type: dust}\n";
        std::ofstream(dir_ / "smoke.yaml", std::ios::binary | std::ios::trunc) << text;
    }
    bool pollFor(fx::Plugin& plugin, fx::Diagnostics* diags) {
        // The library polls the disk at most every 0.1 s; 1.5 s is the deadline.
        for (int i = 0; i < 100; ++i) {
            if (plugin.pollHotReload(diags)) return true;
            if (diags && !diags->empty()) return false;
            usleep(15000);
        }
        return false;
    }
    fs::path dir_;
};

TEST_F(PluginReload, KeepsParticlesWhenNameAndCapacityAreUnchanged) {
    FakeHost host;
    burnout(&host);
    auto plugin = create(&host);
    write("1.0", 500);
    ASSERT_TRUE(plugin->loadReactions(dir_.string(), nullptr));
    for (int i = 0; i < 30; ++i) plugin->continueReaction(0, 1.0f / 60.0f, nullptr);
    const int alive = plugin->stats().particlesAlive;
    ASSERT_EQ(alive, 100);  // 2 rear wheels x 100/s x 0.5 s

    write("3.0", 500, "dust");  // new drag, one more reaction
    ASSERT_TRUE(pollFor(*plugin, nullptr));
    ASSERT_EQ(plugin->reactionCount(), 2);
    const auto& impl = fx::implOf(*plugin);
    const int smoke = indexOf(*plugin, "smoke");
    EXPECT_EQ(impl.runtimes()[static_cast<size_t>(smoke)].pool().alive(), alive);  // the smoke stays
    EXPECT_EQ(impl.runtimes()[static_cast<size_t>(smoke)].desc().particle.drag, 3.0f);
    EXPECT_EQ(plugin->stats().reloads, 1);

    write("fast", 500);  // bad edit: reported, running set kept
    fx::Diagnostics diags;
    EXPECT_FALSE(pollFor(*plugin, &diags));
    ASSERT_EQ(diags.size(), 1u);
    EXPECT_EQ(diags[0].code, fx::ErrorCode::WrongType);
    EXPECT_EQ(plugin->stats().reloadErrors, 1);
    EXPECT_EQ(plugin->reactionCount(), 2);

    write("3.0", 800);  // capacity changed: a fresh pool
    ASSERT_TRUE(pollFor(*plugin, nullptr));
    ASSERT_EQ(plugin->reactionCount(), 1);
    EXPECT_EQ(impl.runtimes()[0].pool().alive(), 0);
    EXPECT_EQ(impl.runtimes()[0].pool().capacity(), 800);
}

}  // namespace
