// RenderTargetPool on OSMesa: formats round-trip, depth formats, sizes, reuse, garbage
// collection and one test per validation error code.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "GlTestContext.h"
#include "RttTestUtil.h"
#include "rtt/Blit.h"
#include "rtt/Clear.h"
#include "rtt/Readback.h"
#include "rtt/RenderTargetPool.h"
#include "rtt/ScopedTargetBinding.h"

namespace cube::rtt {
namespace {

using testutil::fixed;

using testutil::TestProgram;

class RenderTargetPoolTest : public test::GlTest {};

RenderTargetDesc relative(float scale) {
    RenderTargetDesc desc;
    desc.scale = scale;
    return desc;
}

// --- formats -------------------------------------------------------------------------------------

TEST_F(RenderTargetPoolTest, Rgba8ClearAndShaderRoundTripExactly) {
    RenderTargetPool pool;
    RenderTargetHandle t = pool.acquire(fixed(8, 4));
    ASSERT_TRUE(pool.isValid(t)) << pool.lastErrorMessage();
    ClearValues cv;
    cv.color[0] = {51 / 255.0f, 102 / 255.0f, 153 / 255.0f, 1.0f};
    ASSERT_EQ(clear(pool, t, cv), RttError::None);
    std::vector<uint8_t> px;
    ASSERT_EQ(readRGBA8(pool, t, 0, &px), RttError::None);
    ASSERT_EQ(px.size(), 8u * 4u * 4u);
    for (size_t i = 0; i < px.size(); i += 4) {
        EXPECT_EQ(px[i + 0], 51);
        EXPECT_EQ(px[i + 1], 102);
        EXPECT_EQ(px[i + 2], 153);
        EXPECT_EQ(px[i + 3], 255);
    }
    // A shader writing constants into the top half only: rows come back top-down.
    TestProgram prog(testutil::kVsQuad, testutil::kFsConstant);
    prog.set("uColor0", 1.0f, 0.0f, 128 / 255.0f, 0.0f);
    {
        ScopedTargetBinding bind(pool, t);
        prog.drawQuad(-1.0f, 0.0f, 1.0f, 1.0f);
    }
    ASSERT_EQ(readRGBA8(pool, t, 0, &px), RttError::None);
    for (int y = 0; y < 4; ++y) {
        const uint8_t* p = &px[size_t(y) * 8u * 4u];
        if (y < 2) {
            EXPECT_EQ(p[0], 255) << y;
            EXPECT_EQ(p[1], 0) << y;
            EXPECT_EQ(p[2], 128) << y;
            EXPECT_EQ(p[3], 0) << y;
        } else {
            EXPECT_EQ(p[0], 51) << y;
        }
    }
}

TEST_F(RenderTargetPoolTest, Rgba16fRoundTripsToHalfPrecision) {
    RenderTargetPool pool;
    RenderTargetHandle t = pool.acquire(fixed(4, 4, ColorFormat::RGBA16F));
    ASSERT_TRUE(pool.isValid(t));
    const float values[4] = {0.1f, -3.75f, 1234.5678f, 65504.0f};
    ClearValues cv;
    cv.color[0] = {values[0], values[1], values[2], values[3]};
    clear(pool, t, cv);
    std::vector<float> px;
    int channels = 0;
    ASSERT_EQ(readFloat(pool, t, 0, FloatLayout::Native, &px, &channels), RttError::None);
    EXPECT_EQ(channels, 4);
    ASSERT_EQ(px.size(), 4u * 4u * 4u);
    for (size_t i = 0; i < px.size(); ++i)
        EXPECT_NEAR(px[i], values[i % 4], std::fabs(values[i % 4]) * 1e-3f) << i;
    // Through a shader too, into the lower half.
    TestProgram prog(testutil::kVsQuad, testutil::kFsConstant);
    prog.set("uColor0", 0.333f, 2.5f, -0.001f, 1.0f);
    {
        ScopedTargetBinding bind(pool, t);
        prog.drawQuad(-1.0f, -1.0f, 1.0f, 0.0f);
    }
    readFloat(pool, t, 0, FloatLayout::RGBA, &px);
    const size_t bottom = size_t(3 * 4) * 4u;  // row 3 (top-down) = bottom row
    EXPECT_NEAR(px[bottom + 0], 0.333f, 0.333f * 1e-3f);
    EXPECT_NEAR(px[bottom + 1], 2.5f, 2.5f * 1e-3f);
    EXPECT_NEAR(px[bottom + 2], -0.001f, 0.001f * 1e-3f);
    EXPECT_NEAR(px[0], values[0], values[0] * 1e-3f);  // top row kept the clear
}

TEST_F(RenderTargetPoolTest, R32fAndRg32fRoundTripExactly) {
    RenderTargetPool pool;
    RenderTargetDesc desc = fixed(4, 2, ColorFormat::R32F);
    desc.color[1] = ColorFormat::RG32F;
    RenderTargetHandle t = pool.acquire(desc);
    ASSERT_TRUE(pool.isValid(t)) << pool.lastErrorMessage();
    ClearValues cv;
    cv.color[0] = {1234.5678f, 0, 0, 0};
    cv.color[1] = {-3.25e-3f, 1e30f, 0, 0};
    clear(pool, t, cv);
    std::vector<float> px;
    int channels = 0;
    ASSERT_EQ(readFloat(pool, t, 0, FloatLayout::Native, &px, &channels), RttError::None);
    EXPECT_EQ(channels, 1);
    ASSERT_EQ(px.size(), 8u);
    for (float v : px) EXPECT_EQ(v, 1234.5678f);
    ASSERT_EQ(readFloat(pool, t, 1, FloatLayout::Native, &px, &channels), RttError::None);
    EXPECT_EQ(channels, 2);
    ASSERT_EQ(px.size(), 16u);
    EXPECT_EQ(px[0], -3.25e-3f);
    EXPECT_EQ(px[1], 1e30f);
    // RGBA layout fills the missing channels the GL way: G = B = 0, A = 1.
    ASSERT_EQ(readFloat(pool, t, 0, FloatLayout::RGBA, &px, &channels), RttError::None);
    EXPECT_EQ(channels, 4);
    EXPECT_EQ(px[0], 1234.5678f);
    EXPECT_EQ(px[1], 0.0f);
    EXPECT_EQ(px[2], 0.0f);
    EXPECT_EQ(px[3], 1.0f);

    // A shader writing the constants to both attachments (one draw, two outputs).
    TestProgram prog(testutil::kVsQuad, testutil::kFsConstant);
    prog.set("uColor0", -3.25e-3f, 0, 0, 0);
    prog.set("uColor1", 1234.5678f, -3.25e-3f, 0, 0);
    {
        ScopedTargetBinding bind(pool, t);
        prog.drawQuad();
    }
    readFloat(pool, t, 0, FloatLayout::Native, &px);
    for (float v : px) EXPECT_EQ(v, -3.25e-3f);
    readFloat(pool, t, 1, FloatLayout::Native, &px);
    for (size_t i = 0; i < px.size(); i += 2) {
        EXPECT_EQ(px[i], 1234.5678f);
        EXPECT_EQ(px[i + 1], -3.25e-3f);
    }
    // RGBA8 read-back of a float target clamps and rounds.
    std::vector<uint8_t> bytes;
    ASSERT_EQ(readRGBA8(pool, t, 1, &bytes), RttError::None);
    EXPECT_EQ(bytes[0], 255);
    EXPECT_EQ(bytes[1], 0);
}

TEST_F(RenderTargetPoolTest, FourColorAttachmentsEachKeepTheirOwnValue) {
    RenderTargetPool pool;
    RenderTargetDesc desc = fixed(2, 2);
    desc.color = {ColorFormat::RGBA8, ColorFormat::RGBA16F, ColorFormat::R32F, ColorFormat::RG32F};
    RenderTargetHandle t = pool.acquire(desc);
    ASSERT_TRUE(pool.isValid(t)) << pool.lastErrorMessage();
    EXPECT_EQ(pool.stats().liveTextures, 4);
    TestProgram prog(testutil::kVsQuad, testutil::kFsConstant);
    prog.set("uColor0", 1, 0, 0, 1);
    prog.set("uColor1", 0.5f, 0.25f, 0.125f, 1);
    prog.set("uColor2", 42.0f, 0, 0, 0);
    prog.set("uColor3", 7.0f, -7.0f, 0, 0);
    {
        ScopedTargetBinding bind(pool, t);
        prog.drawQuad();
    }
    std::vector<float> px;
    readFloat(pool, t, 0, FloatLayout::RGBA, &px);
    EXPECT_EQ(px[0], 1.0f);
    readFloat(pool, t, 1, FloatLayout::RGBA, &px);
    EXPECT_EQ(px[2], 0.125f);
    readFloat(pool, t, 2, FloatLayout::Native, &px);
    EXPECT_EQ(px[0], 42.0f);
    readFloat(pool, t, 3, FloatLayout::Native, &px);
    EXPECT_EQ(px[1], -7.0f);
}

// --- depth ---------------------------------------------------------------------------------------

struct DepthCase {
    DepthFormat format;
    bool sampled;
    float tolerance;  // window-space depth
};

class DepthFormatTest : public test::GlTest, public ::testing::WithParamInterface<DepthCase> {};

TEST_P(DepthFormatTest, AttachesIsCompleteAndReadsBackToItsPrecision) {
    const DepthCase c = GetParam();
    RenderTargetPool pool;
    RenderTargetDesc desc = fixed(8, 8, ColorFormat::RGBA8, c.format);
    desc.sampledDepth = c.sampled;
    RenderTargetHandle t = pool.acquire(desc);
    ASSERT_TRUE(pool.isValid(t)) << pool.lastErrorMessage();
    EXPECT_EQ(pool.depthFormat(t), c.format);
    EXPECT_EQ(pool.depthTexture(t) != 0, c.sampled);
    EXPECT_EQ(pool.stats().liveRenderbuffers, c.sampled ? 0 : 1);
    {
        GLint prev = 0;
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &prev);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, pool.framebuffer(t));
        EXPECT_EQ(glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(prev));
    }
    ClearValues cv;
    cv.depth = 0.5f;
    clear(pool, t, cv);
    std::vector<float> depth;
    ASSERT_EQ(readDepth(pool, t, &depth), RttError::None);
    ASSERT_EQ(depth.size(), 64u);
    EXPECT_NEAR(depth[0], 0.5f, c.tolerance);

    // Draw the left half at NDC z = -0.3 -> window depth 0.35.
    TestProgram prog(testutil::kVsQuad, testutil::kFsConstant);
    {
        ScopedTargetBinding bind(pool, t);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_ALWAYS);
        prog.drawQuad(-1.0f, -1.0f, 0.0f, 1.0f, -0.3f);
        glDepthFunc(GL_LESS);
        glDisable(GL_DEPTH_TEST);
    }
    readDepth(pool, t, &depth);
    EXPECT_NEAR(depth[0], 0.35f, c.tolerance);  // left
    EXPECT_NEAR(depth[7], 0.5f, c.tolerance);   // right kept the clear

    if (!c.sampled) return;
    // Sampled depth: a shader copies it texel by texel into an R32F target.
    RenderTargetHandle copy = pool.acquire(fixed(8, 8, ColorFormat::R32F));
    ASSERT_TRUE(pool.isValid(copy));
    TestProgram copier(testutil::kVsQuad, testutil::kFsCopyDepth);
    copier.setInt("uDepth", 0);
    {
        ScopedTargetBinding bind(pool, copy);
        glBindTexture(GL_TEXTURE_2D, pool.depthTexture(t));
        copier.drawQuad();
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    std::vector<float> copied;
    readFloat(pool, copy, 0, FloatLayout::Native, &copied);
    EXPECT_NEAR(copied[0], 0.35f, c.tolerance);
    EXPECT_NEAR(copied[7], 0.5f, c.tolerance);
}

INSTANTIATE_TEST_SUITE_P(
    Formats, DepthFormatTest,
    ::testing::Values(DepthCase{DepthFormat::Depth24, false, 4.0f / 16777215.0f},
                      DepthCase{DepthFormat::Depth24, true, 4.0f / 16777215.0f},
                      DepthCase{DepthFormat::Depth32F, false, 1e-6f},
                      DepthCase{DepthFormat::Depth32F, true, 1e-6f},
                      DepthCase{DepthFormat::Depth24Stencil8, false, 4.0f / 16777215.0f},
                      DepthCase{DepthFormat::Depth24Stencil8, true, 4.0f / 16777215.0f}),
    [](const ::testing::TestParamInfo<DepthCase>& info) {
        return std::string(depthFormatName(info.param.format)) + (info.param.sampled ? "_Texture" : "_Renderbuffer");
    });

TEST_F(RenderTargetPoolTest, DepthOnlyTargetIsComplete) {
    RenderTargetPool pool;
    RenderTargetDesc desc = fixed(4, 4, ColorFormat::None, DepthFormat::Depth32F);
    RenderTargetHandle t = pool.acquire(desc);
    ASSERT_TRUE(pool.isValid(t)) << pool.lastErrorMessage();
    ClearValues cv;
    cv.depth = 0.25f;
    clear(pool, t, cv);
    std::vector<float> depth;
    ASSERT_EQ(readDepth(pool, t, &depth), RttError::None);
    EXPECT_EQ(depth[5], 0.25f);
}

// --- reuse, sizes, collection ---------------------------------------------------------------------

TEST_F(RenderTargetPoolTest, ReleaseMakesTheHandleStaleAndAcquireReusesTheTarget) {
    RenderTargetPool pool;
    RenderTargetHandle a = pool.acquire(fixed(16, 16));
    const uint32_t fbo = pool.framebuffer(a);
    EXPECT_EQ(pool.release(a), RttError::None);
    EXPECT_FALSE(pool.isValid(a));
    EXPECT_EQ(pool.framebuffer(a), 0u);
    EXPECT_EQ(pool.width(a), 0);
    RenderTargetHandle b = pool.acquire(fixed(16, 16));
    EXPECT_TRUE(pool.isValid(b));
    EXPECT_NE(a, b);                      // same slot, new generation
    EXPECT_EQ(pool.framebuffer(b), fbo);  // same GL objects
    EXPECT_FALSE(pool.isValid(a));
    EXPECT_EQ(pool.stats().totalAllocations, 1u);
    // A different shape is a different target.
    RenderTargetHandle c = pool.acquire(fixed(16, 16, ColorFormat::R32F));
    EXPECT_NE(pool.framebuffer(c), fbo);
    EXPECT_EQ(pool.stats().totalAllocations, 2u);
}

TEST_F(RenderTargetPoolTest, RelativeTargetsFollowTheViewThroughOddSizesKeepingHandlesAndNames) {
    RenderTargetPool pool;
    pool.setViewSize(640, 480);
    RenderTargetHandle full = pool.acquire(relative(1.0f));
    RenderTargetHandle half = pool.acquire(relative(0.5f));
    RenderTargetHandle quarter = pool.acquire(relative(0.25f));
    RenderTargetHandle fixedOne = pool.acquire(fixed(32, 8));
    ASSERT_TRUE(pool.isValid(quarter));
    const uint32_t halfTexture = pool.colorTexture(half);
    const struct { int w, h; } views[] = {{641, 479}, {1, 1}, {3, 5}, {1023, 769}, {17, 2}, {640, 480}};
    uint64_t reallocations = pool.stats().reallocations;
    for (const auto& v : views) {
        pool.setViewSize(v.w, v.h);
        EXPECT_TRUE(pool.isValid(half));
        EXPECT_EQ(pool.colorTexture(half), halfTexture);
        EXPECT_EQ(pool.width(full), v.w);
        EXPECT_EQ(pool.height(full), v.h);
        EXPECT_EQ(pool.width(half), std::max(1, (v.w + 1) / 2)) << v.w;
        EXPECT_EQ(pool.height(half), std::max(1, (v.h + 1) / 2)) << v.h;
        EXPECT_EQ(pool.width(quarter), std::max(1, (v.w + 3) / 4)) << v.w;
        EXPECT_EQ(pool.height(quarter), std::max(1, (v.h + 3) / 4)) << v.h;
        EXPECT_EQ(pool.width(fixedOne), 32);
        // The storage really has the new size: a read-back returns that many pixels.
        clear(pool, quarter);
        std::vector<uint8_t> px;
        readRGBA8(pool, quarter, 0, &px);
        EXPECT_EQ(px.size(), size_t(pool.width(quarter)) * size_t(pool.height(quarter)) * 4u);
        EXPECT_GT(pool.stats().reallocations, reallocations);
        reallocations = pool.stats().reallocations;
    }
    EXPECT_EQ(pool.stats().totalAllocations, 4u);
    // Free relative targets follow too: re-acquired after a resize, they have the new size.
    pool.release(half);
    pool.setViewSize(101, 99);
    RenderTargetHandle again = pool.acquire(relative(0.5f));
    EXPECT_EQ(pool.colorTexture(again), halfTexture);
    EXPECT_EQ(pool.width(again), 51);
    EXPECT_EQ(pool.height(again), 50);
}

TEST_F(RenderTargetPoolTest, ZeroViewClampsRelativeTargetsToOnePixelWithoutAllocating) {
    RenderTargetPool pool;
    pool.setViewSize(64, 48);
    RenderTargetHandle half = pool.acquire(relative(0.5f));
    const RenderTargetPoolStats before = pool.stats();
    pool.setViewSize(0, 0);
    EXPECT_EQ(pool.width(half), 1);
    EXPECT_EQ(pool.height(half), 1);
    RenderTargetHandle quarter = pool.acquire(relative(0.25f));  // acquiring still works
    EXPECT_TRUE(pool.isValid(quarter));
    EXPECT_EQ(pool.width(quarter), 1);
    EXPECT_EQ(clear(pool, quarter), RttError::None);
    const RenderTargetPoolStats after = pool.stats();
    EXPECT_EQ(after.liveFramebuffers, before.liveFramebuffers + 1);  // only the new acquire
    pool.setViewSize(64, 48);
    EXPECT_EQ(pool.width(half), 32);
    EXPECT_EQ(pool.stats().totalAllocations, 2u);
}

TEST_F(RenderTargetPoolTest, RelativeSizesClampToThePoolLimit) {
    RenderTargetPoolDesc pd;
    pd.maxTextureSize = 64;
    RenderTargetPool pool(pd);
    pool.setViewSize(16, 8);
    RenderTargetHandle big = pool.acquire(relative(100.0f));
    ASSERT_TRUE(pool.isValid(big)) << pool.lastErrorMessage();
    EXPECT_EQ(pool.width(big), 64);
    EXPECT_EQ(pool.height(big), 64);
}

TEST_F(RenderTargetPoolTest, FreeTargetsAreDestroyedAfterNFramesUnused) {
    RenderTargetPoolDesc pd;
    pd.framesUntilFree = 3;
    RenderTargetPool pool(pd);
    pool.beginFrame();  // frame 1
    RenderTargetHandle t = pool.acquire(fixed(8, 8, ColorFormat::RGBA8, DepthFormat::Depth24));
    RenderTargetHandle held = pool.acquire(fixed(8, 8, ColorFormat::R32F));
    pool.release(t);
    pool.endFrame();
    for (int frame = 2; frame <= 3; ++frame) {
        pool.beginFrame();
        pool.endFrame();
        EXPECT_EQ(pool.stats().targetsFree, 1) << frame;
    }
    pool.beginFrame();  // frame 4: 3 frames since last use
    pool.endFrame();
    const RenderTargetPoolStats st = pool.stats();
    EXPECT_EQ(st.targetsFree, 0);
    EXPECT_EQ(st.targetsInUse, 1);
    EXPECT_EQ(st.liveTextures, 1);
    EXPECT_EQ(st.liveRenderbuffers, 0);
    EXPECT_EQ(st.liveFramebuffers, 1);
    EXPECT_TRUE(pool.isValid(held));  // in use: never collected
}

TEST_F(RenderTargetPoolTest, SharedDepthSeesTheOwnersDepthAndPinsIt) {
    RenderTargetPool pool;
    RenderTargetDesc ownerDesc = fixed(8, 8, ColorFormat::R32F, DepthFormat::Depth24);
    ownerDesc.sampledDepth = true;
    RenderTargetHandle owner = pool.acquire(ownerDesc);
    RenderTargetDesc sharerDesc = fixed(8, 8);
    sharerDesc.sharedDepth = owner;
    RenderTargetHandle sharer = pool.acquire(sharerDesc);
    ASSERT_TRUE(pool.isValid(sharer)) << pool.lastErrorMessage();
    EXPECT_EQ(pool.depthTexture(sharer), pool.depthTexture(owner));
    EXPECT_EQ(pool.depthFormat(sharer), DepthFormat::Depth24);
    ClearValues cv;
    cv.depth = 0.75f;
    clear(pool, owner, cv);
    std::vector<float> depth;
    ASSERT_EQ(readDepth(pool, sharer, &depth), RttError::None);
    EXPECT_NEAR(depth[0], 0.75f, 1e-6f);
    // The owner, released, stays alive while the sharer uses its depth.
    pool.release(owner);
    for (int i = 0; i < 10; ++i) {
        pool.beginFrame();
        pool.endFrame();
    }
    EXPECT_EQ(pool.stats().targetsFree, 1);
    readDepth(pool, sharer, &depth);
    EXPECT_NEAR(depth[0], 0.75f, 1e-6f);
    pool.release(sharer);
    pool.trim();
    EXPECT_EQ(pool.stats().liveTextures, 0);
    EXPECT_EQ(pool.stats().liveFramebuffers, 0);
}

TEST_F(RenderTargetPoolTest, DebugNameBecomesTheObjectLabel) {
    if (!gl::hasDebug()) GTEST_SKIP() << "no KHR_debug";
    RenderTargetPool pool;
    RenderTargetDesc desc = fixed(4, 4);
    desc.name = "scene_color";
    RenderTargetHandle t = pool.acquire(desc);
    char label[64] = {};
    glGetObjectLabel(GL_FRAMEBUFFER, pool.framebuffer(t), sizeof label, nullptr, label);
    EXPECT_STREQ(label, "scene_color");
    glGetObjectLabel(GL_TEXTURE, pool.colorTexture(t), sizeof label, nullptr, label);
    EXPECT_STREQ(label, "scene_color.color0");
    EXPECT_STREQ(pool.desc(t)->name, "scene_color");
    for (int i = 0; i < 40; ++i) pool.acquire(fixed(4 + i, 4));  // grows the pool's storage
    EXPECT_STREQ(pool.desc(t)->name, "scene_color");
}

// --- one test per error code ------------------------------------------------------------------------

// Each failing acquire: the named code, an invalid handle, no GL object left, no GL error.
class RttErrorTest : public test::GlTest {
protected:
    void expectFailure(RenderTargetPool& pool, const RenderTargetDesc& desc, RttError expected) {
        const RenderTargetPoolStats before = pool.stats();
        RttError e = RttError::None;
        RenderTargetHandle h = pool.acquire(desc, &e);
        EXPECT_EQ(e, expected) << rttErrorName(e) << ": " << pool.lastErrorMessage();
        EXPECT_FALSE(h.valid());
        EXPECT_FALSE(pool.lastErrorMessage().empty());
        const RenderTargetPoolStats after = pool.stats();
        EXPECT_EQ(after.liveTextures, before.liveTextures);
        EXPECT_EQ(after.liveRenderbuffers, before.liveRenderbuffers);
        EXPECT_EQ(after.liveFramebuffers, before.liveFramebuffers);
        EXPECT_EQ(after.totalAllocations, before.totalAllocations);
    }
};

TEST_F(RttErrorTest, InvalidSize) {
    RenderTargetPool pool;
    expectFailure(pool, fixed(16, 0), RttError::InvalidSize);
    expectFailure(pool, fixed(0, 16), RttError::InvalidSize);
    expectFailure(pool, fixed(-4, 16), RttError::InvalidSize);
}

TEST_F(RttErrorTest, InvalidScale) {
    RenderTargetPool pool;
    expectFailure(pool, relative(0.0f), RttError::InvalidScale);
    expectFailure(pool, relative(-0.5f), RttError::InvalidScale);
    expectFailure(pool, relative(std::numeric_limits<float>::quiet_NaN()), RttError::InvalidScale);
    expectFailure(pool, relative(std::numeric_limits<float>::infinity()), RttError::InvalidScale);
}

TEST_F(RttErrorTest, TooLarge) {
    RenderTargetPool pool;
    const int maxTex = pool.limits().maxTextureSize;
    GLint driverMax = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &driverMax);
    EXPECT_EQ(maxTex, driverMax);
    expectFailure(pool, fixed(maxTex + 1, 4), RttError::TooLarge);
    expectFailure(pool, fixed(4, maxTex + 1), RttError::TooLarge);
    expectFailure(pool, fixed(pool.limits().maxRenderbufferSize + 1, 4, ColorFormat::None, DepthFormat::Depth24),
                  RttError::TooLarge);
    // A lowered pool limit applies the same way.
    RenderTargetPoolDesc pd;
    pd.maxTextureSize = 32;
    RenderTargetPool small(pd);
    expectFailure(small, fixed(33, 8), RttError::TooLarge);
}

TEST_F(RttErrorTest, NoAttachments) {
    RenderTargetPool pool;
    expectFailure(pool, fixed(8, 8, ColorFormat::None, DepthFormat::None), RttError::NoAttachments);
}

TEST_F(RttErrorTest, TooManyColorAttachments) {
    RenderTargetPoolDesc pd;
    pd.maxColorAttachments = 2;
    RenderTargetPool pool(pd);
    RenderTargetDesc desc = fixed(8, 8);
    desc.color = {ColorFormat::RGBA8, ColorFormat::RGBA8, ColorFormat::R32F, ColorFormat::None};
    expectFailure(pool, desc, RttError::TooManyColorAttachments);
    // The driver's own limit is at least the 4 a descriptor can hold.
    RenderTargetPool driver;
    EXPECT_EQ(driver.limits().maxColorAttachments, kMaxColorAttachments);
}

TEST_F(RttErrorTest, ColorAttachmentGap) {
    RenderTargetPool pool;
    RenderTargetDesc desc = fixed(8, 8);
    desc.color = {ColorFormat::RGBA8, ColorFormat::None, ColorFormat::R32F, ColorFormat::None};
    expectFailure(pool, desc, RttError::ColorAttachmentGap);
}

TEST_F(RttErrorTest, InvalidFormat) {
    RenderTargetPool pool;
    RenderTargetDesc desc = fixed(8, 8);
    desc.color[0] = static_cast<ColorFormat>(42);
    expectFailure(pool, desc, RttError::InvalidFormat);
    desc = fixed(8, 8);
    desc.depth = static_cast<DepthFormat>(9);
    expectFailure(pool, desc, RttError::InvalidFormat);
}

TEST_F(RttErrorTest, SharedDepthInvalid) {
    RenderTargetPool pool;
    RenderTargetHandle owner = pool.acquire(fixed(8, 8, ColorFormat::RGBA8, DepthFormat::Depth24));
    pool.release(owner);  // stale now
    RenderTargetDesc desc = fixed(8, 8);
    desc.sharedDepth = owner;
    expectFailure(pool, desc, RttError::SharedDepthInvalid);
    RenderTargetHandle noDepth = pool.acquire(fixed(8, 8));
    desc.sharedDepth = noDepth;
    expectFailure(pool, desc, RttError::SharedDepthInvalid);
}

TEST_F(RttErrorTest, SharedDepthSizeMismatch) {
    RenderTargetPool pool;
    pool.setViewSize(8, 8);
    RenderTargetHandle owner = pool.acquire(fixed(8, 8, ColorFormat::RGBA8, DepthFormat::Depth24));
    RenderTargetDesc desc = fixed(16, 16);
    desc.sharedDepth = owner;
    expectFailure(pool, desc, RttError::SharedDepthSizeMismatch);
    // Same pixels today, but a relative target would drift from an absolute owner on resize.
    RenderTargetDesc rel = relative(1.0f);
    rel.sharedDepth = owner;
    expectFailure(pool, rel, RttError::SharedDepthSizeMismatch);
}

TEST_F(RttErrorTest, SharedDepthConflict) {
    RenderTargetPool pool;
    RenderTargetHandle owner = pool.acquire(fixed(8, 8, ColorFormat::RGBA8, DepthFormat::Depth24));
    RenderTargetDesc desc = fixed(8, 8, ColorFormat::RGBA8, DepthFormat::Depth32F);
    desc.sharedDepth = owner;
    expectFailure(pool, desc, RttError::SharedDepthConflict);
}

// Every status GL defines for an incomplete framebuffer is named as GL spells it; others are not.
TEST(RttErrorNames, FramebufferStatusesAreNamedAsGlSpellsThem) {
    const std::pair<uint32_t, const char*> named[] = {
        {GL_FRAMEBUFFER_COMPLETE, "GL_FRAMEBUFFER_COMPLETE"},
        {GL_FRAMEBUFFER_UNDEFINED, "GL_FRAMEBUFFER_UNDEFINED"},
        {GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT, "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT"},
        {GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT, "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT"},
        {GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER, "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER"},
        {GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER, "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER"},
        {GL_FRAMEBUFFER_UNSUPPORTED, "GL_FRAMEBUFFER_UNSUPPORTED"},
        {GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE, "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE"},
        {GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS, "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS"},
        {0x1234u, "unknown framebuffer status"},
    };
    for (const auto& [status, name] : named) {
        const char* got = nullptr;
        const RttError e = rttErrorFromFramebufferStatus(status, &got);
        EXPECT_STREQ(got, name);
        EXPECT_EQ(e, status == GL_FRAMEBUFFER_COMPLETE ? RttError::None : RttError::FramebufferIncomplete) << name;
    }
}

TEST_F(RttErrorTest, FramebufferIncomplete) {
    // The status mapping on a really incomplete framebuffer (a texture without an image)...
    GLuint fbo = 0, tex = 0;
    GLint prevFbo = 0, prevTex = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &prevFbo);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &prevTex);
    glGenFramebuffers(1, &fbo);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    const char* statusName = "";
    EXPECT_EQ(rttErrorFromFramebufferStatus(glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER), &statusName),
              RttError::FramebufferIncomplete);
    EXPECT_STREQ(statusName, "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT");
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(prevFbo));
    glBindTexture(GL_TEXTURE_2D, GLuint(prevTex));
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &tex);
    EXPECT_EQ(rttErrorFromFramebufferStatus(GL_FRAMEBUFFER_COMPLETE), RttError::None);
    // ...and the pool's cleanup when the driver refuses a combination (llvmpipe refuses none of
    // ours, so the refusal is injected after the real GL objects were made).
    RenderTargetPool pool;
    pool.failNextCreateForTesting(RttError::FramebufferIncomplete);
    expectFailure(pool, fixed(8, 8, ColorFormat::RGBA16F, DepthFormat::Depth24Stencil8), RttError::FramebufferIncomplete);
    EXPECT_TRUE(pool.isValid(pool.acquire(fixed(8, 8))));  // only the next creation fails
}

TEST_F(RttErrorTest, AllocationFailed) {
    RenderTargetPool pool;
    pool.failNextCreateForTesting(RttError::AllocationFailed);
    RenderTargetDesc desc = fixed(8, 8, ColorFormat::R32F, DepthFormat::Depth32F);
    desc.sampledDepth = true;
    expectFailure(pool, desc, RttError::AllocationFailed);
}

TEST_F(RttErrorTest, InvalidHandle) {
    RenderTargetPool pool;
    RenderTargetHandle t = pool.acquire(fixed(8, 8));
    EXPECT_EQ(pool.release(t), RttError::None);
    EXPECT_EQ(pool.release(t), RttError::InvalidHandle);  // double release
    EXPECT_EQ(pool.release(RenderTargetHandle{}), RttError::InvalidHandle);
    EXPECT_EQ(pool.release(RenderTargetHandle{99, 1}), RttError::InvalidHandle);
    std::vector<uint8_t> px;
    std::vector<float> fpx;
    EXPECT_EQ(readRGBA8(pool, t, 0, &px), RttError::InvalidHandle);
    EXPECT_EQ(readFloat(pool, t, 0, FloatLayout::RGBA, &fpx), RttError::InvalidHandle);
    EXPECT_EQ(readDepth(pool, t, &fpx), RttError::InvalidHandle);
    EXPECT_EQ(clear(pool, t), RttError::InvalidHandle);
    EXPECT_EQ(present(pool, t, 0, 0, 0, 8, 8), RttError::InvalidHandle);
    EXPECT_EQ(pool.colorTexture(t), 0u);
    EXPECT_EQ(pool.desc(t), nullptr);
}

TEST_F(RttErrorTest, InvalidAttachment) {
    RenderTargetPool pool;
    RenderTargetHandle t = pool.acquire(fixed(8, 8));
    std::vector<uint8_t> px;
    std::vector<float> fpx;
    EXPECT_EQ(readRGBA8(pool, t, 1, &px), RttError::InvalidAttachment);
    EXPECT_EQ(readRGBA8(pool, t, -1, &px), RttError::InvalidAttachment);
    EXPECT_EQ(readDepth(pool, t, &fpx), RttError::InvalidAttachment);
    RenderTargetHandle u = pool.acquire(fixed(8, 8, ColorFormat::R32F));
    EXPECT_EQ(blitColor(pool, t, 0, u, 2), RttError::InvalidAttachment);
    EXPECT_EQ(blitDepth(pool, t, u), RttError::InvalidAttachment);
}

TEST_F(RttErrorTest, FormatMismatch) {
    RenderTargetPool pool;
    RenderTargetHandle a = pool.acquire(fixed(8, 8, ColorFormat::RGBA8, DepthFormat::Depth24));
    RenderTargetHandle b = pool.acquire(fixed(8, 8, ColorFormat::RGBA8, DepthFormat::Depth32F));
    EXPECT_EQ(blitDepth(pool, a, b), RttError::FormatMismatch);
}

}  // namespace
}  // namespace cube::rtt
