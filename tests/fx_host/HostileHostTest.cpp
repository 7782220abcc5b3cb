// The hostile C99 host (HostileHost.c, compiled as C): garbage descriptors, a sweep of every
// numeric parameter, dead handles, depth formats and texture names, no context, and a loader
// that returns NULL for each GL function in turn. It makes its own OSMesa context.
#include <cstdio>

#include <gtest/gtest.h>

extern "C" int fxHostileHostCheck(const char* reactionFile, const char* explosionFile, char* report, int capacity);

namespace {

TEST(HostileHostTest, EveryCallOfTheCTableSurvivesACarelessHost) {
    static char report[16384];
    const int failed = fxHostileHostCheck(CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml",
                                          CUBE_SOURCE_DIR "/reactions/explosion.yaml", report, int(sizeof report));
    std::printf("%s", report);
    EXPECT_EQ(failed, 0) << report;
}

}  // namespace
