// A view anywhere in the framebuffer (API 2.1): two views side by side in one framebuffer (a
// two-player split screen, the second view away from (0, 0) in both axes), each drawn through
// renderView with the host's viewport on it. Each rectangle equals the same view drawn alone at
// (0, 0) of a framebuffer of its own size, for the plugin's copy of the bound framebuffer's depth
// (the view's rectangle) and for the host's whole-framebuffer depth texture sampled in place (the
// view at the viewport's origin). A host scissor clips the smoke when the view asks for it
// (clipToHostScissor) and is ignored otherwise (the 2.0 behaviour).
#include <glad/gl.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "FxTestHost.h"

namespace fxtest {
namespace viewport {  // named: the fx_host tests build as unity batches

constexpr int kW = 160, kH = 120;
// The second view's origin: off both axes, not a multiple of the 16 px tiles or of 2 (quarter res).
constexpr int kBx = kW + 13, kBy = 7;
constexpr int kSplitW = kBx + kW + 5, kSplitH = kBy + kH + 3;
/// Largest |difference| (1/255 per channel) between a view drawn in its rectangle and alone.
/// Measured (llvmpipe, 160 x 120): 0 at (0, 0); at (173, 7) 0 for quarter res and mega, 1 for
/// hard and soft, 3 for spherical. The same differences come with no scene depth
/// at all (FX_DEPTH_FROM_NOTHING): llvmpipe interpolates a varying at another window position
/// with other float rounding, and the spherical chord amplifies it, as does its atlas read from
/// the nearest mip level where a pixel's level of detail sits between two (ParticleDraw::draw). So the test holds each depth
/// source to what the same placement gives without depth (depth addressing adds nothing), and
/// that to kTolerance, or kSphericalTolerance for spherical particles.
constexpr int kTolerance = 1;
constexpr int kSphericalTolerance = 3;

const RenderMode kModes[] = {modes::kHard,        modes::kSoft,             modes::kSpherical,
                             modes::kSoftQuarter, modes::kSphericalQuarter, modes::kMega,
                             modes::kHardTiled,   modes::kSoftTiled,        modes::kSphericalTiled,
                             modes::kSoftLitTiled};

// An RGBA8 colour texture + a GL_DEPTH_COMPONENT24 depth texture in one framebuffer.
struct Framebuffer : HostTarget {
    Framebuffer(int w, int h) : HostTarget(w, h, GL_DEPTH_COMPONENT24) {}
};

// The w x h rectangle of `img` at (x, y).
Image crop(const Image& img, int x, int y, int w, int h) {
    Image out;
    out.width = w;
    out.height = h;
    out.rgba.resize(size_t(w) * size_t(h) * 4);
    for (int r = 0; r < h; ++r) {
        for (int c = 0; c < w; ++c) {
            for (int k = 0; k < 4; ++k) out.rgba[(size_t(r) * size_t(w) + size_t(c)) * 4 + size_t(k)] = img.at(x + c, y + r)[k];
        }
    }
    return out;
}

class ViewportTest : public LoadedPluginTest {
protected:
    ViewportTest() : LoadedPluginTest(kW, kH, kSmokeOnWall) {}
    void SetUp() override {
        LoadedPluginTest::SetUp();
        views[0] = view;
        // Player two: the same smoke from the other side of the car, lower and nearer.
        views[1] = makeView(glm::vec3(-4.5f, 1.4f, 5.0f), glm::vec3(0.3f, 0.7f, 0.5f), kW, kH);
    }

    void setModeAndPrepare(const RenderMode& m) {
        ASSERT_NO_FATAL_FAILURE(setMode(m));
        ASSERT_TRUE(plugin->prepareGl(nullptr));
    }

    // View `v`'s opaque scene into `alone` (its own size), as the host draws it.
    void drawScene(const Framebuffer& alone, const fx::ViewInfo& v) {
        glBindFramebuffer(GL_FRAMEBUFFER, alone.fbo);
        scene.drawOpaque(v);
    }
    // The opaque scene of both views into their rectangles of `split`: each drawn alone, then its
    // colour and depth copied (exactly: same formats, nearest) to its origin.
    void drawSplitScene(const Framebuffer& split, const Framebuffer& scratch) {
        const int origin[2][2] = {{0, 0}, {kBx, kBy}};
        glBindFramebuffer(GL_FRAMEBUFFER, split.fbo);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClearDepth(1.0);
        glViewport(0, 0, kSplitW, kSplitH);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        for (int i = 0; i < 2; ++i) {
            drawScene(scratch, views[i]);
            glBindFramebuffer(GL_READ_FRAMEBUFFER, scratch.fbo);
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, split.fbo);
            glBlitFramebuffer(0, 0, kW, kH, origin[i][0], origin[i][1], origin[i][0] + kW, origin[i][1] + kH,
                              GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, split.fbo);
    }
    fx::HostDepth depthOf(bool texture, const Framebuffer& fb, bool none = false) const {
        fx::HostDepth d;
        if (none) d.source = fx::HostDepth::Source::None;
        if (texture) {
            d.source = fx::HostDepth::Source::DepthTexture;
            d.texture = fb.depth;
        }
        return d;
    }

    fx::ViewInfo views[2];
};

TEST_F(ViewportTest, EachHalfOfASplitScreenEqualsTheViewDrawnAlone) {
    Framebuffer alone(kW, kH), split(kSplitW, kSplitH), scratch(kW, kH);
    const int origin[2][2] = {{0, 0}, {kBx, kBy}};
    for (const RenderMode& m : kModes) {
        SCOPED_TRACE(m.label);
        setModeAndPrepare(m);
        int noDepthDiff[2] = {0, 0};
        for (int pass = 0; pass < 3; ++pass) {
            const bool texture = pass == 2, none = pass == 0;
            const char* source = none ? "no depth (rasterisation alone)"
                                 : texture ? "whole-framebuffer depth texture" : "bound framebuffer's depth (copied)";
            Image reference[2];
            for (int i = 0; i < 2; ++i) {
                drawScene(alone, views[i]);
                glViewport(0, 0, kW, kH);
                ASSERT_EQ(plugin->renderView(views[i], depthOf(texture, alone, none)), fx::ErrorCode::None);
                reference[i] = readFramebuffer(alone.fbo, kW, kH);
                drawScene(alone, views[i]);
                EXPECT_GT(maxAbsDiff(reference[i], readFramebuffer(alone.fbo, kW, kH)), 0)
                    << "view " << i << " shows no smoke: the comparison would prove nothing";
            }
            drawSplitScene(split, scratch);
            for (int i = 0; i < 2; ++i) {
                glBindFramebuffer(GL_FRAMEBUFFER, split.fbo);
                glViewport(origin[i][0], origin[i][1], kW, kH);
                ASSERT_EQ(plugin->renderView(views[i], depthOf(texture, split, none)), fx::ErrorCode::None);
            }
            drainGlErrors("split screen");
            const Image frame = readFramebuffer(split.fbo, kSplitW, kSplitH);
            for (int i = 0; i < 2; ++i) {
                const int diff = maxAbsDiff(crop(frame, origin[i][0], origin[i][1], kW, kH), reference[i]);
                const int allowed = m.technique == fx::Technique::Spherical ? kSphericalTolerance : kTolerance;
                EXPECT_LE(diff, allowed) << source << ", view " << i;
                if (none) {
                    noDepthDiff[i] = diff;
                } else {
                    EXPECT_LE(diff, std::max(noDepthDiff[i], i == 0 ? 0 : kTolerance))
                        << source << ", view " << i << ": reading depth in place of none must add no difference";
                }
                if (i == 0) {
                    EXPECT_EQ(diff, 0) << source << ": the view at (0, 0) of a larger framebuffer, bit for bit";
                }
                std::printf("[ measured ] %-28s %-36s view %d at (%3d, %d): max |diff| %d/255\n", m.label, source,
                            i, origin[i][0], origin[i][1], diff);
            }
            // Nothing outside the two rectangles: the gap between them kept its clear colour.
            for (int y = 0; y < kSplitH; ++y) {
                EXPECT_EQ(frame.at(kW + 6, y)[0], 0) << "the gap at row " << y;
            }
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_F(ViewportTest, AHostScissorClipsTheSmokeWhenTheViewAsksForIt) {
    Framebuffer split(kSplitW, kSplitH), scratch(kW, kH), alone(kW, kH);
    // Full res (the particles drawn straight into the host's framebuffer), quarter res and mega
    // (their composites scissor to the smoke's rect themselves).
    for (const RenderMode& m : {kModes[1], kModes[2], kModes[3], kModes[5]}) {
        SCOPED_TRACE(m.label);
        setModeAndPrepare(m);
        const int allowed = m.technique == fx::Technique::Spherical ? kSphericalTolerance : kTolerance;
        fx::ViewInfo v = views[1];
        drawScene(alone, v);
        glViewport(0, 0, kW, kH);
        ASSERT_EQ(plugin->renderView(v, fx::HostDepth{}), fx::ErrorCode::None);
        const Image reference = readFramebuffer(alone.fbo, kW, kH);
        drawSplitScene(split, scratch);
        const Image bare = crop(readFramebuffer(split.fbo, kSplitW, kSplitH), kBx, kBy, kW, kH);
        ASSERT_GT(maxAbsDiff(reference, bare), 0) << "no smoke in view 1";

        // The scissor: the left 70 and the bottom 50 pixels of the second view.
        const int sw = 70, sh = 50;
        for (bool clip : {true, false}) {
            drawSplitScene(split, scratch);
            glViewport(kBx, kBy, kW, kH);
            glEnable(GL_SCISSOR_TEST);
            glScissor(kBx, kBy, sw, sh);
            v.clipToHostScissor = clip;
            ASSERT_EQ(plugin->renderView(v, fx::HostDepth{}), fx::ErrorCode::None);
            EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST)) << "the host's scissor state is left as it was";
            glDisable(GL_SCISSOR_TEST);
            const Image got = crop(readFramebuffer(split.fbo, kSplitW, kSplitH), kBx, kBy, kW, kH);
            int inside = 0, outsideChanged = 0, outsideSmoke = 0, insideSmoke = 0;
            for (int y = 0; y < kH; ++y) {
                for (int x = 0; x < kW; ++x) {
                    const bool in = x < sw && y < sh;
                    bool same = true, smoke = false;
                    for (int k = 0; k < 3; ++k) {
                        same = same && std::abs(int(got.at(x, y)[k]) - int(reference.at(x, y)[k])) <= allowed;
                        smoke = smoke || reference.at(x, y)[k] != bare.at(x, y)[k];
                    }
                    if (in) {
                        inside += same ? 0 : 1;
                        insideSmoke += smoke;
                    } else {
                        outsideSmoke += smoke;
                        bool untouched = true;
                        for (int k = 0; k < 3; ++k) untouched = untouched && got.at(x, y)[k] == bare.at(x, y)[k];
                        outsideChanged += untouched ? 0 : 1;
                    }
                }
            }
            ASSERT_GT(insideSmoke, 50) << "the scissor box must hold smoke";
            ASSERT_GT(outsideSmoke, 50) << "smoke must reach past the scissor box";
            EXPECT_EQ(inside, 0) << "inside the box the view draws as alone (clip " << clip << ")";
            if (clip) {
                EXPECT_EQ(outsideChanged, 0) << "clipToHostScissor: no smoke outside the host's scissor";
            } else {
                EXPECT_LE(maxAbsDiff(got, reference), allowed) << "without clipToHostScissor the scissor is ignored (2.0)";
            }
            std::printf("[ measured ] %-12s clipToHostScissor %d: %d of %d smoke pixels outside the box drawn\n",
                        m.label, int(clip), outsideChanged, outsideSmoke);
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace viewport
}  // namespace fxtest
