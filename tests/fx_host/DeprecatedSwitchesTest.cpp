// The switches deprecated in API 2.1 (Plugin::setQuarterResEdges, setFadeClassCounting) and fade
// classification (no effect in 2.1, per billboard block since 2.2): a host written against 2.0
// still calls them. They validate and keep their value as before, and change nothing in the
// frame: the same passes, the same pixels (FadeClassificationTest checks classification's
// pixels on billboards large enough to be classified).
#include <string>
#include <vector>

#include "FxTestHost.h"

namespace fxtest {
namespace deprecated_switches_test {  // named: the fx_host tests build as unity batches

constexpr int kW = 160, kH = 120;

// The smoke across the wall's top edge: depth edges in the quarter-res footprints.
class DeprecatedSwitchesTest : public LoadedPluginTest {
protected:
    DeprecatedSwitchesTest() : LoadedPluginTest(kW, kH, kSmokeOnWall) {}

    // All three switches on (`on`) or at their defaults.
    void setDeprecated(bool on) {
        ASSERT_EQ(plugin->setQuarterResEdges(on ? fx::QuarterResEdges::MixedResolution
                                                : fx::QuarterResEdges::DepthAware),
                  fx::ErrorCode::None);
        ASSERT_EQ(plugin->setFadeClassification(on ? fx::FadeClassification::On : fx::FadeClassification::Off),
                  fx::ErrorCode::None);
        ASSERT_EQ(plugin->setFadeClassCounting(on), fx::ErrorCode::None);
        ASSERT_TRUE(plugin->prepareGl(nullptr));  // as a 2.0 host does after switching
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

// Soft smoke at full res and at quarter res (the depth-aware composite), drawn with every
// deprecated switch on and with them off: the same passes run and the frames are bit-identical;
// nothing is counted.
TEST_F(DeprecatedSwitchesTest, FramesWithTheSwitchesOnAreBitIdenticalToFramesWithThemOff) {
    for (const bool quarter : {false, true}) {
        const std::string label = quarter ? "soft quarter res" : "soft full res";
        SCOPED_TRACE(label);
        fx::RenderOptions o;
        o.techniqueOverride = fx::Technique::Soft;
        o.quarterRes = quarter;
        o.quarterResAlways = quarter;  // the quarter-res path itself, however light the smoke
        ASSERT_EQ(plugin->setRenderOptions(o), fx::ErrorCode::None);

        setDeprecated(false);
        const Image off = render();
        const std::vector<std::string> offPasses = graph.executed();
        ASSERT_GT(plugin->stats().particlesDrawn, 0) << "no smoke: the comparison would prove nothing";
        ASSERT_GT(maxAbsDiff(off, render(false)), 0) << "no smoke in the picture";

        setDeprecated(true);
        const Image on = render();
        EXPECT_EQ(graph.executed(), offPasses);
        EXPECT_EQ(maxAbsDiff(on, off), 0);
        EXPECT_EQ(on.rgba, off.rgba);  // alpha too
        EXPECT_FALSE(plugin->fadeClassCounts().counted);
        EXPECT_EQ(plugin->fadeClassCounts().fadeNeeded + plugin->fadeClassCounts().inFront +
                      plugin->fadeClassCounts().hidden,
                  0);
    }
    EXPECT_TRUE(host.errors().empty()) << host.errors().front();
}

}  // namespace deprecated_switches_test
}  // namespace fxtest
