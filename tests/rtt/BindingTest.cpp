// Binding helpers: the scoped binder, clears against hostile state, blits, presenting and the
// pixel-pack hygiene of read-backs.
#include <gtest/gtest.h>

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

class BindingTest : public test::GlTest {};

GLint getInt(GLenum e) {
    GLint v = 0;
    glGetIntegerv(e, &v);
    return v;
}

TEST_F(BindingTest, ScopedBindingRestoresFramebuffersAndViewport) {
    RenderTargetPool pool;
    RenderTargetHandle a = pool.acquire(fixed(16, 8));
    RenderTargetHandle b = pool.acquire(fixed(4, 2));
    // A distinct draw and read framebuffer before, and an odd viewport.
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, pool.framebuffer(a));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glViewport(3, 5, 7, 11);
    {
        ScopedTargetBinding bind(pool, b);
        EXPECT_EQ(GLuint(getInt(GL_DRAW_FRAMEBUFFER_BINDING)), pool.framebuffer(b));
        EXPECT_EQ(GLuint(getInt(GL_READ_FRAMEBUFFER_BINDING)), pool.framebuffer(b));
        GLint vp[4];
        glGetIntegerv(GL_VIEWPORT, vp);
        EXPECT_EQ(vp[2], 4);
        EXPECT_EQ(vp[3], 2);
        EXPECT_FALSE(bind.bind(pool, RenderTargetHandle{}));  // stale: binds nothing
        EXPECT_EQ(GLuint(getInt(GL_DRAW_FRAMEBUFFER_BINDING)), pool.framebuffer(b));
    }
    EXPECT_EQ(GLuint(getInt(GL_DRAW_FRAMEBUFFER_BINDING)), pool.framebuffer(a));
    EXPECT_EQ(getInt(GL_READ_FRAMEBUFFER_BINDING), 0);
    GLint vp[4];
    glGetIntegerv(GL_VIEWPORT, vp);
    EXPECT_EQ(vp[0], 3);
    EXPECT_EQ(vp[1], 5);
    EXPECT_EQ(vp[2], 7);
    EXPECT_EQ(vp[3], 11);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, platform().width(), platform().height());
}

TEST_F(BindingTest, ReadbackRestoresPackStateAndIgnoresIt) {
    RenderTargetPool pool;
    RenderTargetHandle t = pool.acquire(fixed(3, 3));  // 3 px * 4 B rows: alignment would matter for RGB
    ClearValues cv;
    cv.color[0] = {1.0f, 0.0f, 0.0f, 1.0f};
    clear(pool, t, cv);
    GLuint pbo = 0;
    glGenBuffers(1, &pbo);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, pbo);
    glBufferData(GL_PIXEL_PACK_BUFFER, 1024, nullptr, GL_STREAM_READ);
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    glPixelStorei(GL_PACK_ROW_LENGTH, 17);
    glPixelStorei(GL_PACK_SKIP_ROWS, 2);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
    glClampColor(GL_CLAMP_READ_COLOR, GL_TRUE);
    std::vector<uint8_t> px;
    ASSERT_EQ(readRGBA8(pool, t, 0, &px), RttError::None);
    ASSERT_EQ(px.size(), 36u);
    for (size_t i = 0; i < px.size(); i += 4) {
        EXPECT_EQ(px[i], 255);
        EXPECT_EQ(px[i + 1], 0);
        EXPECT_EQ(px[i + 3], 255);
    }
    // Float read-back is not clamped even though the caller asked for read clamping.
    RenderTargetHandle f = pool.acquire(fixed(3, 3, ColorFormat::R32F));
    cv.color[0] = {5.5f, 0, 0, 0};
    clear(pool, f, cv);
    std::vector<float> fpx;
    readFloat(pool, f, 0, FloatLayout::Native, &fpx);
    EXPECT_EQ(fpx[4], 5.5f);
    EXPECT_EQ(getInt(GL_PACK_ALIGNMENT), 8);
    EXPECT_EQ(getInt(GL_PACK_ROW_LENGTH), 17);
    EXPECT_EQ(getInt(GL_PACK_SKIP_ROWS), 2);
    EXPECT_EQ(getInt(GL_PACK_SKIP_PIXELS), 1);
    EXPECT_EQ(getInt(GL_PACK_SWAP_BYTES), GL_TRUE);
    EXPECT_EQ(GLuint(getInt(GL_PIXEL_PACK_BUFFER_BINDING)), pbo);
    EXPECT_EQ(getInt(GL_CLAMP_READ_COLOR), GL_TRUE);
    glClampColor(GL_CLAMP_READ_COLOR, GL_FIXED_ONLY);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glDeleteBuffers(1, &pbo);
}

TEST_F(BindingTest, ReadbackRowsAreTopDown) {
    RenderTargetPool pool;
    RenderTargetHandle t = pool.acquire(fixed(4, 4));
    clear(pool, t);
    testutil::TestProgram prog(testutil::kVsQuad, testutil::kFsConstant);
    prog.set("uColor0", 0, 1, 0, 1);
    {
        ScopedTargetBinding bind(pool, t);
        prog.drawQuad(-1, 0, 1, 1);  // GL's upper half
    }
    std::vector<uint8_t> px;
    readRGBA8(pool, t, 0, &px);
    EXPECT_EQ(px[1], 255);               // row 0 = top
    EXPECT_EQ(px[3 * 16 + 1], 0);        // row 3 = bottom
}

TEST_F(BindingTest, ClearIgnoresMasksScissorAndDiscardAndRestoresThem) {
    RenderTargetPool pool;
    RenderTargetHandle t = pool.acquire(fixed(4, 4, ColorFormat::RGBA8, DepthFormat::Depth24Stencil8));
    glColorMask(GL_FALSE, GL_FALSE, GL_TRUE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glStencilMask(0x0F);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 1, 1);
    glEnable(GL_RASTERIZER_DISCARD);
    ClearValues cv;
    cv.color[0] = {1, 1, 1, 1};
    cv.depth = 0.25f;
    ASSERT_EQ(clear(pool, t, cv), RttError::None);
    glDisable(GL_RASTERIZER_DISCARD);
    std::vector<uint8_t> px;
    readRGBA8(pool, t, 0, &px);
    EXPECT_EQ(px[15 * 4 + 0], 255);  // last pixel, outside the scissor, red channel masked off
    std::vector<float> depth;
    readDepth(pool, t, &depth);
    EXPECT_NEAR(depth[15], 0.25f, 1e-6f);
    GLboolean mask[4];
    glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    EXPECT_FALSE(mask[0]);
    EXPECT_TRUE(mask[2]);
    GLboolean depthMask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
    EXPECT_FALSE(depthMask);
    EXPECT_EQ(getInt(GL_STENCIL_WRITEMASK), 0x0F);
    EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST));
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFFFFFFFFu);
    glDisable(GL_SCISSOR_TEST);
}

TEST_F(BindingTest, BlitScalesBetweenTargetsAndPresentsToTheDefaultFramebuffer) {
    RenderTargetPool pool;
    RenderTargetHandle small = pool.acquire(fixed(2, 2));
    RenderTargetDesc twoDesc = fixed(8, 8, ColorFormat::RGBA16F);
    twoDesc.color[1] = ColorFormat::RGBA8;
    RenderTargetHandle big = pool.acquire(twoDesc);
    ClearValues cv;
    cv.color[0] = {0, 0, 1, 1};
    clear(pool, small, cv);
    clear(pool, big);
    ASSERT_EQ(blitColor(pool, small, 0, big, 1, Filter::Nearest), RttError::None);
    std::vector<uint8_t> px;
    readRGBA8(pool, big, 1, &px);
    for (size_t i = 0; i < px.size(); i += 4) EXPECT_EQ(px[i + 2], 255);
    readRGBA8(pool, big, 0, &px);  // attachment 0 untouched
    EXPECT_EQ(px[2], 0);
    // Draw buffers are back to both attachments: one draw reaches both.
    testutil::TestProgram prog(testutil::kVsQuad, testutil::kFsConstant);
    prog.set("uColor0", 1, 0, 0, 1);
    prog.set("uColor1", 0, 1, 0, 1);
    {
        ScopedTargetBinding bind(pool, big);
        prog.drawQuad();
    }
    readRGBA8(pool, big, 0, &px);
    EXPECT_EQ(px[0], 255);
    readRGBA8(pool, big, 1, &px);
    EXPECT_EQ(px[1], 255);

    ASSERT_EQ(present(pool, small, 0, 0, 0, platform().width(), platform().height(), Filter::Nearest),
              RttError::None);
    readDefaultFramebufferRGBA8(platform().width(), platform().height(), &px);
    ASSERT_EQ(px.size(), size_t(platform().width() * platform().height() * 4));
    EXPECT_EQ(px[2], 255);
    EXPECT_EQ(px[px.size() - 2], 255);
    EXPECT_EQ(present(pool, small, 0, 0, 0, 0, 0), RttError::None);  // minimised: no-op

    // Depth blit between equal formats.
    RenderTargetHandle d1 = pool.acquire(fixed(4, 4, ColorFormat::None, DepthFormat::Depth32F));
    RenderTargetHandle d2 = pool.acquire(fixed(4, 4, ColorFormat::RGBA8, DepthFormat::Depth32F));
    ClearValues dv;
    dv.depth = 0.125f;
    clear(pool, d1, dv);
    clear(pool, d2);
    ASSERT_EQ(blitDepth(pool, d1, d2), RttError::None);
    std::vector<float> depth;
    readDepth(pool, d2, &depth);
    EXPECT_EQ(depth[0], 0.125f);
}

}  // namespace
}  // namespace cube::rtt
