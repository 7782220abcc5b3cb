#pragma once
// One headless OSMesa GL context per test process, shared by every GL test in it, and a
// fixture that checks each test leaves no GL error behind.
//
//   class MyTest : public cube::test::GlTest {};
//   TEST_F(MyTest, Draws) { ... platform().width() ... }
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "gl/Gl.h"
#include "platform/Platform.h"

namespace cube::test {

/// The process's OSMesa platform (64x64 default framebuffer, debug context), made on first
/// use and current from then on; null with `error` set when no context could be made.
inline Platform* glPlatform(std::string* error = nullptr) {
    static std::string s_error;
    static const std::unique_ptr<Platform> s_platform = [] {
        PlatformDesc desc;
        desc.width = 64;
        desc.height = 64;
        return Platform::create(desc, &s_error);
    }();
    if (error) *error = s_error;
    return s_platform.get();
}

/// Fixture: fails the test when no context can be made; resets cube::gl::errorCount() before
/// the test and expects it to be 0 after (KHR_debug messages and glGetError both count).
/// The context is made in the constructor, so a derived fixture's GL-owning members may be
/// constructed in place, as long as they tolerate (or the test skips) a failed context.
class GlTest : public ::testing::Test {
protected:
    GlTest() : platform_(glPlatform()) {}
    void SetUp() override {
        std::string error;
        platform_ = glPlatform(&error);
        ASSERT_NE(platform_, nullptr) << error;
        gl::checkErrors("GlTest::SetUp");
        gl::resetErrorCount();
    }
    void TearDown() override {
        if (!platform_) return;
        gl::checkErrors("GlTest::TearDown");
        EXPECT_EQ(gl::errorCount(), 0) << "last GL error: " << gl::lastError();
    }
    Platform& platform() { return *platform_; }

private:
    Platform* platform_ = nullptr;
};

}  // namespace cube::test
