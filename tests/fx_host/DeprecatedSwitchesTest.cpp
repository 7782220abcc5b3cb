// The switches deprecated in API 2.1 (Plugin::setQuarterResEdges, setFadeClassCounting) and in
// 2.4 (setFadeClassification, which 2.2 and 2.3 honoured per block of each particle): a host
// written against an earlier API still calls them. They validate and keep their value as before,
// and change nothing: no program is built for them, the same passes run, the pixels are the same.
#include <string>
#include <vector>

#include "FxTestHost.h"
#include "../../fx_plugin/render/ShaderLoader.h"

namespace fxtest {
namespace deprecated_switches_test {  // named: the fx_host tests build as unity batches

constexpr int kW = 160, kH = 120;

// The smoke across the wall's top edge: depth edges in the quarter-res footprints.
class DeprecatedSwitchesTest : public LoadedPluginTest {
protected:
    DeprecatedSwitchesTest() : LoadedPluginTest(kW, kH, kSmokeOnWall) {}

    // All three switches on (`on`) or at their defaults; returns the programs prepareGl built.
    uint64_t setDeprecated(bool on) {
        const uint64_t before = fx::programBuildCounts().built;
        EXPECT_EQ(plugin->setQuarterResEdges(on ? fx::QuarterResEdges::MixedResolution
                                                : fx::QuarterResEdges::DepthAware),
                  fx::ErrorCode::None);
        EXPECT_EQ(plugin->setFadeClassification(on ? fx::FadeClassification::On : fx::FadeClassification::Off),
                  fx::ErrorCode::None);
        EXPECT_EQ(plugin->setFadeClassCounting(on), fx::ErrorCode::None);
        EXPECT_TRUE(plugin->prepareGl(nullptr));  // as a 2.0 host does after switching
        return fx::programBuildCounts().built - before;
    }

    // One frame of `technique`, at quarter res (always) or full res, with the deprecated
    // switches at their defaults.
    Image renderTechnique(fx::Technique technique, bool quarter) {
        fx::RenderOptions o;
        o.techniqueOverride = technique;
        o.quarterRes = quarter;
        o.quarterResAlways = quarter;  // the quarter-res path itself, however light the smoke
        EXPECT_EQ(plugin->setRenderOptions(o), fx::ErrorCode::None);
        setDeprecated(false);
        return render();
    }

    // `set` takes `on` (`get` reads it back), refuses `invalid` as InvalidValue and keeps `on`,
    // then takes `off`.
    template <typename T>
    void expectSetterValidates(fx::ErrorCode (fx::Plugin::*set)(T), T (fx::Plugin::*get)() const, T on, T invalid,
                               T off) {
        fx::Plugin& p = *plugin;
        EXPECT_EQ((p.*set)(on), fx::ErrorCode::None);
        EXPECT_EQ((p.*get)(), on);
        EXPECT_EQ((p.*set)(invalid), fx::ErrorCode::InvalidValue);
        EXPECT_EQ((p.*get)(), on) << "a refused value changes nothing";
        EXPECT_EQ((p.*set)(off), fx::ErrorCode::None);
        EXPECT_EQ((p.*get)(), off);
    }
};

TEST_F(DeprecatedSwitchesTest, SettersValidateAndKeepTheirValue) {
    EXPECT_EQ(plugin->quarterResEdges(), fx::QuarterResEdges::DepthAware);
    EXPECT_EQ(plugin->fadeClassification(), fx::FadeClassification::Off);

    expectSetterValidates(&fx::Plugin::setQuarterResEdges, &fx::Plugin::quarterResEdges,
                          fx::QuarterResEdges::MixedResolution, static_cast<fx::QuarterResEdges>(2),
                          fx::QuarterResEdges::DepthAware);
    expectSetterValidates(&fx::Plugin::setFadeClassification, &fx::Plugin::fadeClassification,
                          fx::FadeClassification::On, static_cast<fx::FadeClassification>(255),
                          fx::FadeClassification::Off);

    EXPECT_EQ(plugin->setFadeClassCounting(true), fx::ErrorCode::None);
    EXPECT_EQ(plugin->setFadeClassCounting(false), fx::ErrorCode::None);
}

// Soft billboards and spheres, at full res and at quarter res (the depth-aware composite), drawn
// with every deprecated switch on and with them off: prepareGl builds nothing for the switches,
// the same passes run and the frames are bit-identical; nothing is counted. The smoke stands on
// the ground and crosses the wall's top edge: where fade classification (2.2, 2.3) had particles
// skip the scene-depth fetch in some blocks and not in others.
TEST_F(DeprecatedSwitchesTest, FramesWithTheSwitchesOnAreBitIdenticalToFramesWithThemOff) {
    // The smoke lies within its softness of the geometry: the fade shapes it, so the soft frame is
    // not the hard one (a billboard with a fade of 1 everywhere draws as a hard one).
    const Image hard = renderTechnique(fx::Technique::Hard, false);
    ASSERT_GT(maxAbsDiff(hard, renderTechnique(fx::Technique::Soft, false)), 0)
        << "no soft fade in the frame: the smoke is nowhere near the geometry";

    for (const fx::Technique technique : {fx::Technique::Soft, fx::Technique::Spherical}) {
        for (const bool quarter : {false, true}) {
            const std::string label = std::string(technique == fx::Technique::Soft ? "soft" : "spherical") +
                                      (quarter ? " quarter res" : " full res");
            SCOPED_TRACE(label);
            const Image off = renderTechnique(technique, quarter);
            const std::vector<std::string> offPasses = graph.executed();
            ASSERT_GT(plugin->stats().particlesDrawn, 0) << "no smoke: the comparison would prove nothing";
            ASSERT_GT(maxAbsDiff(off, render(false)), 0) << "no smoke in the picture";

            EXPECT_EQ(setDeprecated(true), 0u) << "programs built for a switch with no effect";
            const Image on = render();
            EXPECT_EQ(graph.executed(), offPasses);
            EXPECT_EQ(maxAbsDiff(on, off), 0);
            EXPECT_EQ(on.rgba, off.rgba);  // alpha too
            EXPECT_FALSE(plugin->fadeClassCounts().counted);
            EXPECT_EQ(plugin->fadeClassCounts().fadeNeeded + plugin->fadeClassCounts().inFront +
                          plugin->fadeClassCounts().hidden,
                      0);
        }
    }
    EXPECT_TRUE(host.errors().empty()) << host.errors().front();
}

}  // namespace deprecated_switches_test
}  // namespace fxtest
