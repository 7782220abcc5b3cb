// The hostile C99 host (HostileHost.c, compiled as C): garbage descriptors, a sweep of every
// numeric parameter, dead handles, depth formats and texture names, no context, and a loader
// that returns NULL for each GL function in turn. It makes its own OSMesa context.
#include <GL/osmesa.h>

#include <cstdio>

#include <gtest/gtest.h>

extern "C" int fxHostileHostCheck(const char* reactionFile, const char* explosionFile, char* report, int capacity);

namespace {

TEST(HostileHostTest, EveryCallOfTheCTableSurvivesACarelessHost) {
    // The check starts with no context current (its first calls must be refused for that) and
    // ends on its own, destroyed: the context an earlier test of this process left current is
    // put aside first and made current again after, so the test binary runs whole too (ctest
    // runs each test alone).
    OSMesaContext earlier = OSMesaGetCurrentContext();
    GLint width = 0, height = 0, format = 0;
    void* buffer = nullptr;
    if (earlier && !OSMesaGetColorBuffer(earlier, &width, &height, &format, &buffer)) earlier = nullptr;
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    static char report[16384];
    const int failed = fxHostileHostCheck(CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml",
                                          CUBE_SOURCE_DIR "/reactions/explosion.yaml", report, int(sizeof report));
    if (earlier) {
        EXPECT_TRUE(OSMesaMakeCurrent(earlier, buffer, GL_UNSIGNED_BYTE, width, height));
    }
    std::printf("%s", report);
    EXPECT_EQ(failed, 0) << report;
}

}  // namespace
