// Pure (no GL) checks of descriptor rules: size resolution and validation codes.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "rtt/RenderTargetDesc.h"
#include "rtt/RttError.h"

namespace cube::rtt {
namespace {

RenderTargetLimits limits() { return {4096, 4096, 4}; }

TEST(RenderTargetDesc, DefaultsAreFullSizeRgba8NoDepthLinearClamp) {
    RenderTargetDesc d;
    EXPECT_TRUE(isRelative(d));
    EXPECT_EQ(d.scale, 1.0f);
    EXPECT_EQ(colorAttachmentCount(d), 1);
    EXPECT_EQ(d.color[0], ColorFormat::RGBA8);
    EXPECT_EQ(d.depth, DepthFormat::None);
    EXPECT_FALSE(d.sampledDepth);
    EXPECT_FALSE(d.sharedDepth.valid());
    EXPECT_EQ(d.filter, Filter::Linear);
    EXPECT_EQ(d.wrap, Wrap::Clamp);
    EXPECT_EQ(validateDesc(d, limits()), RttError::None);
}

TEST(RenderTargetDesc, RelativeSizesRoundUpAndNeverReachZero) {
    RenderTargetDesc half, quarter, third;
    half.scale = 0.5f;
    quarter.scale = 0.25f;
    third.scale = 1.0f / 3.0f;
    const int sizes[] = {0, 1, 2, 3, 5, 7, 640, 641, 1023, 1279, 1280, 1920, 16383};
    for (int w : sizes) {
        int x = 0, y = 0;
        resolveSize(half, w, w + 1, 0, &x, &y);
        EXPECT_EQ(x, std::max(1, (w + 1) / 2)) << w;
        EXPECT_EQ(y, std::max(1, (w + 2) / 2)) << w;
        resolveSize(quarter, w, w, 0, &x, &y);
        EXPECT_EQ(x, std::max(1, (w + 3) / 4)) << w;
        resolveSize(third, w, w, 0, &x, &y);
        EXPECT_EQ(x, std::max(1, (w + 2) / 3)) << w;
    }
}

TEST(RenderTargetDesc, RelativeSizesClampToTheLimitAbsoluteSizesPassThrough) {
    RenderTargetDesc big;
    big.scale = 4.0f;
    int x = 0, y = 0;
    resolveSize(big, 1000, 10, 2048, &x, &y);
    EXPECT_EQ(x, 2048);
    EXPECT_EQ(y, 40);
    RenderTargetDesc fixed;
    fixed.width = 33;
    fixed.height = 17;
    resolveSize(fixed, 1000, 1000, 16, &x, &y);
    EXPECT_EQ(x, 33);
    EXPECT_EQ(y, 17);
}

TEST(RenderTargetDesc, ValidationMessagesNameTheField) {
    RenderTargetDesc d;
    d.name = "mirror";
    d.width = 16;
    std::string message;
    EXPECT_EQ(validateDesc(d, limits(), &message), RttError::InvalidSize);
    EXPECT_NE(message.find("'mirror'"), std::string::npos) << message;
    EXPECT_NE(message.find("width/height"), std::string::npos) << message;
}

TEST(RttError, EveryCodeHasADistinctName) {
    std::set<std::string> names;
    for (int i = 0; i < int(RttError::Count); ++i) {
        const std::string name = rttErrorName(RttError(i));
        EXPECT_NE(name, "?") << i;
        names.insert(name);
    }
    EXPECT_EQ(names.size(), size_t(RttError::Count));
    EXPECT_STREQ(rttErrorName(RttError::Count), "?");
}

}  // namespace
}  // namespace cube::rtt
