// The immediate path (fx_plugin/render/ImmediateRenderer.h) for engines without a
// frame graph. Its image equals the frame-graph path's (TestFrameGraph) bit for bit when it gets the
// same linear depth; with the host's z-buffer (a depth texture, the bound FBO's depth, the default
// framebuffer's depth) it equals it within kDepthSourceTolerance; it allocates nothing in a frame
// without particles, reuses its targets, leaves the host's bindings alone.
#include <glad/gl.h>

#include <algorithm>
#include <cstdio>
#include <initializer_list>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "FxTestHost.h"
#include "../../fx_plugin/src/PluginImpl.h"
#include "../../fx_plugin/render/ImmediateFrame.h"
#include "../../fx_plugin/render/ImmediateRenderer.h"
#include "../../fx_plugin/render/SceneDepthSource.h"
#include "../../fx_plugin/render/TiledPath.h"

namespace fxtest {
namespace immediate {  // named: the fx_host tests build as unity batches

constexpr int kW = 160, kH = 120;
/// Largest |difference| (1/255 per channel) against the frame-graph image when the plugin makes
/// the linear depth from the host's 24-bit z-buffer itself, and the least PSNR. Derived: at the
/// wall and ground (3-15 m, near 0.1 m) 24-bit depth is exact to ~0.07 mm (DepthMapping.h), the
/// linearised value differs from the host's float prepass by ~1e-5 relative; a soft fade (softness
/// >= 0.3 m) or a sphere's chord moves by < 1e-3, less than one 8-bit step, so each particle layer
/// blended into the pixel may flip one rounding step; where two overlapping layers flip the same
/// way the pixel moves by 2. Measured (llvmpipe, 160 x 120, six techniques): 1/255 into RGBA8
/// targets, 2/255 once (spherical) in the default framebuffer; PSNR 76-87 dB.
constexpr int kDepthSourceTolerance = 2;
constexpr double kDepthSourceMinPsnr = 70.0;
/// The default framebuffer against an RGBA8 texture, same depth: blend rounding (see below).
constexpr int kColourBufferTolerance = 1;

using Source = fx::ImmediateView::DepthSource;

const RenderMode kModes[] = {modes::kHard,        modes::kSoft,      modes::kSpherical,
                             modes::kSoftQuarter, modes::kMega,      modes::kSoftLit,
                             modes::kSoftTiled,   modes::kSphericalTiled, modes::kSoftLitTiled};


class ImmediateRendererTest : public LoadedPluginTest {
protected:
    ImmediateRendererTest() : LoadedPluginTest(kW, kH, kSmokeOnWall) {}
    void SetUp() override {
        LoadedPluginTest::SetUp();
        immediate = std::make_unique<fx::ImmediateRenderer>(&host, programs);
    }
    void TearDown() override {
        immediate.reset();
        LoadedPluginTest::TearDown();
    }

    // The frame graph's linear depth texture (what its prepass wrote last).
    GLuint graphLinearDepth() const {
        GLint name = 0;
        glBindFramebuffer(GL_READ_FRAMEBUFFER, graph.depthFramebuffer());
        glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                              GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        return GLuint(name);
    }

    fx::ImmediateView immediateView(Source source, GLuint texture = 0) const {
        fx::ImmediateView iv;
        iv.view = view;
        iv.depthSource = source;
        iv.depthTexture = texture;
        return iv;
    }

    // The opaque scene into `fbo` (its size = the view's), then the immediate path on it.
    fx::ErrorCode drawImmediate(GLuint fbo, const fx::ImmediateView& iv) {
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        scene.drawOpaque(iv.view);
        const fx::ErrorCode e = fx::implOf(*plugin).renderImmediate(iv, immediate.get());
        drainGlErrors("immediate render");
        return e;
    }

    fx::ProgramCache programs{fx::snapshotShaderReader(fx::shaderReader(""))};  ///< the immediate path's
    std::unique_ptr<fx::ImmediateRenderer> immediate;
};

// One depth source's image and the image it must match.
struct SourceImage {
    const char* what;
    const Image* image;
    const Image* reference;
};

// Each source's image within the depth-source tolerances of its reference; prints the measured
// difference under `label` (the mode).
void expectSameImagePerSource(const std::string& label, std::initializer_list<SourceImage> sources) {
    for (const SourceImage& s : sources) {
        const int diff = maxAbsDiff(*s.image, *s.reference);
        EXPECT_LE(diff, kDepthSourceTolerance) << s.what;
        EXPECT_GE(psnr(*s.image, *s.reference), kDepthSourceMinPsnr) << s.what;
        std::printf("  %-19s %-24s max |diff| %d/255, PSNR %.1f dB\n", label.c_str(), s.what, diff,
                    psnr(*s.image, *s.reference));
    }
}

TEST_F(ImmediateRendererTest, SameImageAsTheFrameGraphPerTechniqueAndDepthSource) {
    ASSERT_TRUE(resizeDefaultFramebuffer(kW, kH));
    HostTarget withDepthTexture(kW, kH, GL_DEPTH_COMPONENT24);
    for (const RenderMode& m : kModes) {
        SCOPED_TRACE(m.label);
        setMode(m);
        const Image reference = render(true);
        ASSERT_GT(plugin->stats().particlesDrawn, 0);
        const GLuint linear = graphLinearDepth();

        // (a) The host's linear R32F depth, into the graph's own scene colour framebuffer.
        ASSERT_EQ(drawImmediate(graph.colorFramebuffer(), immediateView(Source::LinearR32F, linear)),
                  fx::ErrorCode::None);
        EXPECT_FALSE(immediate->lastPasses().empty());
        EXPECT_EQ(maxAbsDiff(graph.readColor(), reference), 0) << "bit for bit with the same linear depth";

        // (c) Only the bound framebuffer's depth (the graph's DEPTH24 renderbuffer).
        ASSERT_EQ(drawImmediate(graph.colorFramebuffer(), immediateView(Source::BoundFramebuffer)),
                  fx::ErrorCode::None);
        const Image fromFbo = graph.readColor();
        // (b) A depth texture of the host's.
        ASSERT_EQ(drawImmediate(withDepthTexture.fbo, immediateView(Source::DepthTexture, withDepthTexture.depth)),
                  fx::ErrorCode::None);
        const Image fromTexture = readFramebuffer(withDepthTexture.fbo, kW, kH);
        // (c) on the default framebuffer (OSMesa's DEPTH24 + STENCIL8). Its colour buffer is
        // OSMesa's client memory, where llvmpipe's blending rounds differently from an RGBA8
        // texture (up to 1/255 even for hard particles, which read no depth): its reference is the
        // same framebuffer with the graph's linear depth.
        ASSERT_EQ(drawImmediate(0, immediateView(Source::LinearR32F, linear)), fx::ErrorCode::None);
        const Image defaultReference = readFramebuffer(0, kW, kH);
        EXPECT_LE(maxAbsDiff(defaultReference, reference), kColourBufferTolerance);
        ASSERT_EQ(drawImmediate(0, immediateView(Source::BoundFramebuffer)), fx::ErrorCode::None);
        const Image fromDefault = readFramebuffer(0, kW, kH);
        expectSameImagePerSource(m.label, {{"bound FBO", &fromFbo, &reference},
                                          {"depth texture", &fromTexture, &reference},
                                          {"default framebuffer", &fromDefault, &defaultReference}});
    }
    ASSERT_TRUE(resizeDefaultFramebuffer(4, 4));
}

void clipControlZeroToOne(bool on) {
    using ClipControlFn = void (*)(GLenum, GLenum);
    static const auto fn = reinterpret_cast<ClipControlFn>(osMesaProcAddress()("glClipControl"));
    ASSERT_TRUE(fn != nullptr);
    fn(0x8CA1 /* LOWER_LEFT */, on ? 0x935F /* ZERO_TO_ONE */ : 0x935E /* NEGATIVE_ONE_TO_ONE */);
}

// A reversed-Z host (ZERO_TO_ONE, float z-buffers, GEQUAL): the plugin learns the convention from
// the matrix and the mapping alone (ViewInfo::depth is left Standard here on purpose).
TEST_F(ImmediateRendererTest, ReversedZHostSameImagePerDepthSource) {
    ASSERT_TRUE(resizeDefaultFramebuffer(kW, kH));
    TestFrameGraph reversedGraph(kW, kH, /*floatDepth=*/true);
    scene.reversedZ = true;
    fx::ViewInfo rv = view;
    useReversedZ(&rv);
    HostTarget withDepthTexture(kW, kH, GL_DEPTH_COMPONENT32F);
    for (const RenderMode& m : {kModes[1], kModes[2], kModes[3], kModes[4]}) {
        SCOPED_TRACE(m.label);
        setMode(m);
        renderFrame(reversedGraph, scene, rv, [&](fx::FrameBuilder& f) { plugin->declarePasses(rv, f); });
        const Image reference = reversedGraph.readColor();
        GLint linear = 0;
        glBindFramebuffer(GL_READ_FRAMEBUFFER, reversedGraph.depthFramebuffer());
        glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                              GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &linear);
        auto run = [&](GLuint fbo, Source source, GLuint texture) {
            fx::ImmediateView iv = immediateView(source, texture);
            iv.view = rv;
            iv.view.depth = fx::DepthConvention::Standard;  // conventionOf decides
            iv.mapping.clipZeroToOne = true;
            const fx::ErrorCode e = drawImmediate(fbo, iv);  // drawOpaque leaves ZERO_TO_ONE set
            clipControlZeroToOne(false);
            glDepthFunc(GL_LESS);
            return e;
        };
        ASSERT_EQ(run(reversedGraph.colorFramebuffer(), Source::LinearR32F, GLuint(linear)), fx::ErrorCode::None);
        EXPECT_EQ(maxAbsDiff(reversedGraph.readColor(), reference), 0) << "bit for bit with the same linear depth";
        ASSERT_EQ(run(reversedGraph.colorFramebuffer(), Source::BoundFramebuffer, 0), fx::ErrorCode::None);
        const Image fromFbo = reversedGraph.readColor();
        ASSERT_EQ(run(withDepthTexture.fbo, Source::DepthTexture, withDepthTexture.depth), fx::ErrorCode::None);
        const Image fromTexture = readFramebuffer(withDepthTexture.fbo, kW, kH);
        ASSERT_EQ(run(0, Source::LinearR32F, GLuint(linear)), fx::ErrorCode::None);
        const Image defaultReference = readFramebuffer(0, kW, kH);
        ASSERT_EQ(run(0, Source::BoundFramebuffer, 0), fx::ErrorCode::None);
        const Image fromDefault = readFramebuffer(0, kW, kH);
        expectSameImagePerSource(std::string("reversed ") + m.label,
                                 {{"bound FBO (32F)", &fromFbo, &reference},
                                  {"depth texture (32F)", &fromTexture, &reference},
                                  {"default framebuffer (24)", &fromDefault, &defaultReference}});
    }
    ASSERT_TRUE(resizeDefaultFramebuffer(4, 4));
}

// The host's z-buffer is copied and linearised only where the plugin's passes read it (the
// particles' screen bound, for the tiled path its tiles that hold particles, grown to whole 64 px
// blocks), and the picture is the one a
// whole-view depth gives: with the smoke in one corner of the view, the region is a part of it.
TEST_F(ImmediateRendererTest, DepthIsMadeOnlyWhereThePassesReadIt) {
    constexpr int W = 480, H = 360;  // large enough for 64 px tiles to leave some of it out
    TestFrameGraph bigGraph(W, H);
    HostTarget host24(W, H, GL_DEPTH_COMPONENT24);
    const fx::ViewInfo v = makeView(glm::vec3(-7.0f, 2.5f, 8.0f), glm::vec3(-3.0f, 0.8f, -1.0f), W, H);
    for (const RenderMode& m : {kModes[1], kModes[2], kModes[3], kModes[6], kModes[7]}) {  // + the tiled path's tiles
        SCOPED_TRACE(m.label);
        setMode(m);
        renderFrame(bigGraph, scene, v, [&](fx::FrameBuilder& f) { plugin->declarePasses(v, f); });
        const Image reference = bigGraph.readColor();
        ASSERT_GT(plugin->stats().particlesDrawn, 0);
        fx::ImmediateView iv = immediateView(Source::BoundFramebuffer);
        iv.view = v;
        ASSERT_EQ(drawImmediate(host24.fbo, iv), fx::ErrorCode::None);
        const fx::DepthRegion r = immediate->lastDepthRegion();
        EXPECT_FALSE(r.whole);
        const int area = (r.x1 - r.x0) * (r.y1 - r.y0);
        EXPECT_GT(area, 0);
        EXPECT_LT(area, W * H);
        EXPECT_EQ(r.x0 % 64, 0);
        EXPECT_EQ(r.y0 % 64, 0);
        const Image image = readFramebuffer(host24.fbo, W, H);
        EXPECT_LE(maxAbsDiff(image, reference), kDepthSourceTolerance);
        EXPECT_GE(psnr(image, reference), kDepthSourceMinPsnr);
        std::printf("  %-10s region [%d, %d) x [%d, %d) of %dx%d (%.0f %%), max |diff| %d/255\n", m.label, r.x0, r.x1,
                    r.y0, r.y1, W, H, 100.0 * area / (W * H), maxAbsDiff(image, reference));
    }
}

// renderView's tiled views whose particles the GPU orders (forced here: llvmpipe orders on the
// CPU) are binned by the GPU in their passes (TiledPath::gpuBins), and the depth they read is then
// the whole view's (the bins are known only once the passes run); on the host's threads they are
// binned while declared, the copy narrowed to them. The same picture either way, and the frame
// graph's bit for bit where the host hands in its linear depth.
TEST_F(ImmediateRendererTest, TiledViewsTheGpuOrdersAreBinnedByTheGpu) {
    struct Back {
        ~Back() {
            fx::TiledPath::resetCpuListLimit();
            fx::TileSort::resetOrderLimit();
            fx::TiledPath::resetGpuBins();
        }
    } back;
    fx::TiledPath::setCpuListLimit(0);
    fx::TileSort::setOrderLimit(0);
    HostTarget host24(kW, kH, GL_DEPTH_COMPONENT24);
    for (const RenderMode& m : {kModes[6], kModes[7], kModes[8]}) {
        SCOPED_TRACE(m.label);
        setMode(m);
        const Image reference = render(true);
        ASSERT_GT(plugin->stats().particlesDrawn, 0);
        const GLuint linear = graphLinearDepth();
        Image images[2], copied[2];
        bool whole[2] = {};
        for (int gpu = 1; gpu >= 0; --gpu) {
            fx::TiledPath::setGpuBins(gpu == 1);
            const uint64_t binned = fx::TiledPath::gpuBinnedViews(), deferred = fx::TiledPath::deferredBinViews();
            const uint64_t gathered = fx::TiledPath::gatheredViews();
            ASSERT_EQ(drawImmediate(graph.colorFramebuffer(), immediateView(Source::LinearR32F, linear)),
                      fx::ErrorCode::None);
            images[gpu] = graph.readColor();
            EXPECT_EQ(fx::TiledPath::gpuBinnedViews(), binned + uint64_t(gpu)) << "gpu " << gpu;
            EXPECT_EQ(fx::TiledPath::deferredBinViews(), deferred + uint64_t(gpu)) << "binned in its pass only by the GPU";
            EXPECT_EQ(fx::TiledPath::gatheredViews(), gathered + uint64_t(gpu)) << "its particles written by its pass";
            ASSERT_EQ(drawImmediate(host24.fbo, immediateView(Source::BoundFramebuffer)), fx::ErrorCode::None);
            copied[gpu] = readFramebuffer(host24.fbo, kW, kH);
            whole[gpu] = immediate->lastDepthRegion().whole;
        }
        EXPECT_EQ(maxAbsDiff(images[1], reference), 0) << "bit for bit with the same linear depth";
        EXPECT_EQ(maxAbsDiff(images[0], reference), 0);
        EXPECT_EQ(maxAbsDiff(copied[1], copied[0]), 0) << "the whole view's depth or the bins' part of it";
        EXPECT_LE(maxAbsDiff(copied[1], reference), kDepthSourceTolerance);
        EXPECT_TRUE(whole[1]) << "binned by the GPU: the whole view's depth";
    }
}

// Hosts whose z-buffer follows neither mapping a DepthConvention names: a D3D-style [0, 1]
// projection under GL's default clip control (Irrlicht: window z in [0.5, 1]), the same matrix
// under ZERO_TO_ONE without reversal, and a GL projection drawn with glDepthRange(0.2, 0.9). The
// host states the mapping; before the call it leaves clip control and depth range at GL's
// defaults (as a host that resets them would), so only the plugin's guard can put its z-tested
// passes back on the host's mapping. Each must match the standard host's picture.
TEST_F(ImmediateRendererTest, HostsWithOtherDepthMappingsGetTheSamePicture) {
    HostTarget withDepthTexture(kW, kH, GL_DEPTH_COMPONENT24);
    enum class Matrix { Gl, ZeroToOne, InfiniteGl };
    struct Case {
        const char* name;
        Matrix matrix;
        bool clipZeroToOne;
        float rangeNear, rangeFar;
    };
    const Case cases[] = {{"D3D-style [0,1] matrix, GL clip control", Matrix::ZeroToOne, false, 0.0f, 1.0f},
                          {"[0,1] matrix, ZERO_TO_ONE, not reversed", Matrix::ZeroToOne, true, 0.0f, 1.0f},
                          {"GL matrix, depth range [0.2, 0.9]", Matrix::Gl, false, 0.2f, 0.9f},
                          {"infinite far plane (GL)", Matrix::InfiniteGl, false, 0.0f, 1.0f}};
    for (const RenderMode& m : {kModes[0], kModes[1], kModes[2], kModes[3]}) {
        setMode(m);
        const Image reference = render(true);
        ASSERT_GT(plugin->stats().particlesDrawn, 0);
        for (const Case& c : cases) {
            SCOPED_TRACE(std::string(m.label) + ", " + c.name);
            fx::ImmediateView iv = immediateView(Source::BoundFramebuffer);
            const float aspect = float(kW) / float(kH), fov = glm::radians(60.0f);
            iv.view.proj = c.matrix == Matrix::ZeroToOne    ? glm::perspectiveRH_ZO(fov, aspect, view.nearPlane, view.farPlane)
                           : c.matrix == Matrix::InfiniteGl ? glm::infinitePerspectiveRH(fov, aspect, view.nearPlane)
                                                            : view.proj;
            iv.mapping.clipZeroToOne = c.clipZeroToOne;
            iv.mapping.rangeNear = c.rangeNear;
            iv.mapping.rangeFar = c.rangeFar;
            glBindFramebuffer(GL_FRAMEBUFFER, withDepthTexture.fbo);
            scene.clipZeroToOne = c.clipZeroToOne;
            glDepthRange(c.rangeNear, c.rangeFar);
            scene.drawOpaque(iv.view);
            scene.clipZeroToOne = false;
            clipControlZeroToOne(false);
            glDepthRange(0.0, 1.0);
            ASSERT_EQ(fx::implOf(*plugin).renderImmediate(iv, immediate.get()), fx::ErrorCode::None);
            drainGlErrors("immediate render");
            const Image image = readFramebuffer(withDepthTexture.fbo, kW, kH);
            const int diff = maxAbsDiff(image, reference);
            EXPECT_LE(diff, kDepthSourceTolerance);
            EXPECT_GE(psnr(image, reference), kDepthSourceMinPsnr);
            std::printf("  %-10s %-42s max |diff| %d/255, PSNR %.1f dB\n", m.label, c.name, diff, psnr(image, reference));
        }
    }
}

// An MSAA host framebuffer: the depth copy is a resolve (HostDepthTest checks its values); the
// particles draw into the multisampled target, z-tested against its own samples.
TEST_F(ImmediateRendererTest, MultisampledHostFramebufferDraws) {
    setMode(kModes[1]);
    GLuint rb[2] = {}, fbo = 0;
    glGenRenderbuffers(2, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, kW, kH);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH24_STENCIL8, kW, kH);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
    ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    const Image reference = render(true);
    // The resolved colour of the immediate frame, against the single-sampled frame graph's.
    HostTarget resolved(kW, kH, 0);
    auto resolve = [&] {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved.fbo);
        glBlitFramebuffer(0, 0, kW, kH, 0, 0, kW, kH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        return readFramebuffer(resolved.fbo, kW, kH);
    };
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    scene.drawOpaque(view);
    const Image opaque = resolve();
    ASSERT_EQ(drawImmediate(fbo, immediateView(Source::BoundFramebuffer)), fx::ErrorCode::None);
    EXPECT_EQ(immediate->depthCopies(), 1);
    const Image smoke = resolve();
    EXPECT_GT(maxAbsDiff(smoke, opaque), 20) << "smoke was drawn";
    // Edges are antialiased here, not in the reference: compare in PSNR only.
    EXPECT_GT(psnr(smoke, reference), 30.0);
    std::printf("  MSAA4 host vs single-sampled frame graph: PSNR %.1f dB\n", psnr(smoke, reference));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(2, rb);
}

TEST_F(ImmediateRendererTest, FrameWithoutVisibleParticlesAllocatesAndCopiesNothing) {
    setMode(kModes[1]);
    view = makeView(glm::vec3(0.0f, 2.0f, 20.0f), glm::vec3(0.0f, 2.0f, 40.0f), kW, kH);  // looking away
    for (Source s : {Source::BoundFramebuffer, Source::None}) {
        EXPECT_EQ(drawImmediate(graph.colorFramebuffer(), immediateView(s)), fx::ErrorCode::None);
    }
    EXPECT_TRUE(immediate->lastPasses().empty());
    EXPECT_EQ(immediate->targetAllocations(), 0);
    EXPECT_EQ(immediate->depthCopies(), 0);
    EXPECT_EQ(immediate->depthLinearizations(), 0);
}

// With particles alive, renderView sends what the host drew to the GPU (glFlush) before it culls,
// sorts and bounds them, so the GPU draws the host's scene meanwhile: one flush a call. Without a
// live particle it does not flush.
TEST_F(ImmediateRendererTest, LiveSmokeSendsTheHostsSceneToTheGpuFirst) {
    setMode(kModes[1]);
    ASSERT_EQ(drawImmediate(graph.colorFramebuffer(), immediateView(Source::BoundFramebuffer)), fx::ErrorCode::None);
    const int before = pluginFlushes();
    if (before < 0) GTEST_SKIP() << "the plugin's GL table was loaded through another host in this process";
    ASSERT_EQ(drawImmediate(graph.colorFramebuffer(), immediateView(Source::BoundFramebuffer)), fx::ErrorCode::None);
    ASSERT_FALSE(immediate->lastPasses().empty());
    EXPECT_EQ(pluginFlushes() - before, 1);
    createPlugin(CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml");  // nothing emitted yet
    const int idle = pluginFlushes();
    ASSERT_EQ(drawImmediate(graph.colorFramebuffer(), immediateView(Source::BoundFramebuffer)), fx::ErrorCode::None);
    EXPECT_TRUE(immediate->lastPasses().empty());
    EXPECT_EQ(pluginFlushes(), idle);
}

TEST_F(ImmediateRendererTest, DepthIsCopiedOnlyWhenAPassReadsIt) {
    setMode(kModes[0]);  // hard: the z-buffer test alone, no pass reads the scene depth
    ASSERT_EQ(drawImmediate(graph.colorFramebuffer(), immediateView(Source::BoundFramebuffer)), fx::ErrorCode::None);
    EXPECT_FALSE(immediate->lastPasses().empty());
    EXPECT_EQ(immediate->depthCopies(), 0);
    setMode(kModes[1]);  // soft reads it
    ASSERT_EQ(drawImmediate(graph.colorFramebuffer(), immediateView(Source::BoundFramebuffer)), fx::ErrorCode::None);
    ASSERT_TRUE(fx::canSampleZBufferInPlace()) << "llvmpipe has glTextureBarrier (GL 4.5)";
    // The framebuffer's depth cannot be sampled: one copy, decoded by the particle shaders (no
    // linearise pass, no linear target).
    EXPECT_EQ(immediate->depthCopies(), 1);
    EXPECT_EQ(immediate->depthLinearizations(), 0);
    EXPECT_EQ(std::count(immediate->lastPasses().begin(), immediate->lastPasses().end(), "particles"), 1);
    // A depth texture of the host's is sampled where it is, attached to the framebuffer the
    // particles draw into: no copy either.
    HostTarget withDepthTexture(kW, kH, GL_DEPTH_COMPONENT24);
    glBindFramebuffer(GL_FRAMEBUFFER, withDepthTexture.fbo);
    glClear(GL_DEPTH_BUFFER_BIT);
    ASSERT_EQ(drawImmediate(withDepthTexture.fbo, immediateView(Source::DepthTexture, withDepthTexture.depth)),
              fx::ErrorCode::None);
    EXPECT_EQ(immediate->depthCopies(), 1);
    EXPECT_EQ(immediate->depthLinearizations(), 0);
}

TEST_F(ImmediateRendererTest, TargetsAreReusedReallocatedOnResizeAndFreedOnRelease) {
    setMode(kModes[3]);  // quarter res: the half-res depth and colour (the z-buffer copy is no pooled target)
    for (int f = 0; f < 3; ++f) {
        ASSERT_EQ(drawImmediate(graph.colorFramebuffer(), immediateView(Source::BoundFramebuffer)),
                  fx::ErrorCode::None);
    }
    const int perFrame = immediate->targetsAllocated();
    EXPECT_GE(perFrame, 2);  // half depth, half colour
    EXPECT_EQ(immediate->targetAllocations(), perFrame) << "frames 2 and 3 reuse frame 1's targets";

    // The view changes size: new targets; the old ones go after ImmediateTargetPool::kKeepFrames.
    const fx::ViewInfo small = makeView(glm::vec3(4.0f, 2.0f, 7.0f), glm::vec3(0.0f, 0.8f, 1.0f), 120, 90);
    HostTarget smallHost(120, 90, GL_DEPTH_COMPONENT24);
    view = small;
    ASSERT_EQ(drawImmediate(smallHost.fbo, immediateView(Source::BoundFramebuffer)), fx::ErrorCode::None);
    EXPECT_EQ(immediate->targetAllocations(), 2 * perFrame);
    for (uint64_t f = 0; f < fx::ImmediateTargetPool::kKeepFrames; ++f) {
        ASSERT_EQ(drawImmediate(smallHost.fbo, immediateView(Source::BoundFramebuffer)), fx::ErrorCode::None);
    }
    EXPECT_EQ(immediate->targetAllocations(), 2 * perFrame);
    EXPECT_EQ(immediate->targetsAllocated(), perFrame) << "the old size's targets were freed";
    immediate->releaseGl();
    EXPECT_EQ(immediate->targetsAllocated(), 0);
}

TEST_F(ImmediateRendererTest, HostBindingsAndStateAreUnchanged) {
    setMode(kModes[3]);
    for (Source s : {Source::BoundFramebuffer, Source::None}) {
        glBindFramebuffer(GL_FRAMEBUFFER, graph.colorFramebuffer());
        scene.drawOpaque(view);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, graph.depthFramebuffer());  // read != draw, as a host may
        const GlStateSnapshot before = captureGlState();
        ASSERT_EQ(fx::implOf(*plugin).renderImmediate(immediateView(s), immediate.get()), fx::ErrorCode::None);
        EXPECT_EQ(before.diff(captureGlState()), "");
        EXPECT_FALSE(immediate->lastPasses().empty());
    }
}

// API 2.1's view fields through the public renderView (the C table): the host's fog gives the
// frame-graph path's fogged picture, and two complementary distance slices drawn one after the
// other give the one-call picture (the same particles, in the same back-to-front order).
TEST_F(ImmediateRendererTest, FogAndDistanceSlicesReachRenderView) {
    HostTarget target(kW, kH, GL_DEPTH_COMPONENT24);
    fx::ViewInfo fogged = view;
    fogged.fog.mode = fx::Fog::Mode::Exp2;
    fogged.fog.density = 0.12f;
    fogged.fog.color = glm::vec3(0.6f, 0.65f, 0.7f);
    auto drawn = [&](const fx::ViewInfo& v) {
        const fx::ErrorCode e = plugin->renderView(v);
        drainGlErrors("renderView");
        EXPECT_EQ(e, fx::ErrorCode::None);
        return plugin->stats().particlesDrawn;
    };
    for (const RenderMode& m : {kModes[0], kModes[1], kModes[2]}) {
        SCOPED_TRACE(m.label);
        setMode(m);
        const fx::ViewInfo plain = view;
        view = fogged;
        const Image graphFogged = render(true);
        view = plain;
        const Image graphPlain = render(true);
        EXPECT_GT(maxAbsDiff(graphFogged, graphPlain), 10) << "fog changed nothing";

        glBindFramebuffer(GL_FRAMEBUFFER, target.fbo);
        scene.drawOpaque(plain);
        drawn(fogged);
        const Image immediateFogged = readFramebuffer(target.fbo, kW, kH);
        EXPECT_LE(maxAbsDiff(immediateFogged, graphFogged), kDepthSourceTolerance);
        std::printf("[ measured ] %s: exp2 fog, renderView vs frame graph max |diff| %d/255 (fog vs none %d/255)\n",
                    m.label, maxAbsDiff(immediateFogged, graphFogged), maxAbsDiff(graphFogged, graphPlain));

        glBindFramebuffer(GL_FRAMEBUFFER, target.fbo);
        scene.drawOpaque(plain);
        const int all = drawn(plain);
        const Image oneCall = readFramebuffer(target.fbo, kW, kH);
        fx::ViewInfo farSlice = plain, nearSlice = plain;
        farSlice.slice = fx::DistanceSlice{7.5f, 0.0f};
        nearSlice.slice = fx::DistanceSlice{0.0f, 7.5f};
        glBindFramebuffer(GL_FRAMEBUFFER, target.fbo);
        scene.drawOpaque(plain);
        const int far = drawn(farSlice);
        const int near = drawn(nearSlice);
        const Image twoCalls = readFramebuffer(target.fbo, kW, kH);
        std::printf("[ measured ] %s: %d particles, %d beyond 7.5 m, %d nearer; two slices vs one call max |diff| %d/255\n",
                    m.label, all, far, near, maxAbsDiff(twoCalls, oneCall));
        EXPECT_GT(far, 0);
        EXPECT_GT(near, 0);
        EXPECT_EQ(far + near, all);
        EXPECT_LE(maxAbsDiff(twoCalls, oneCall), 1);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_F(ImmediateRendererTest, RefusesWhatItCannotDraw) {
    setMode(kModes[1]);
    glBindFramebuffer(GL_FRAMEBUFFER, graph.colorFramebuffer());
    glViewport(0, 0, kW, kH);
    EXPECT_EQ(fx::implOf(*plugin).renderImmediate(immediateView(Source::LinearR32F, 0), immediate.get()), fx::ErrorCode::NullArgument);
    EXPECT_EQ(fx::implOf(*plugin).renderImmediate(immediateView(Source::DepthTexture, 0), immediate.get()), fx::ErrorCode::NullArgument);
    HostTarget colourOnly(kW, kH, 0);
    EXPECT_EQ(fx::implOf(*plugin).renderImmediate(immediateView(Source::DepthTexture, colourOnly.colour), immediate.get()),
              fx::ErrorCode::UnsupportedDepth)
        << "an RGBA8 texture is not a depth texture";
    glBindFramebuffer(GL_FRAMEBUFFER, colourOnly.fbo);
    EXPECT_EQ(fx::implOf(*plugin).renderImmediate(immediateView(Source::BoundFramebuffer), immediate.get()), fx::ErrorCode::UnsupportedDepth)
        << "no depth attachment";
    glBindFramebuffer(GL_FRAMEBUFFER, graph.colorFramebuffer());
    fx::ImmediateView bad = immediateView(Source::BoundFramebuffer);
    bad.mapping.rangeNear = bad.mapping.rangeFar = 0.5f;
    EXPECT_EQ(fx::implOf(*plugin).renderImmediate(bad, immediate.get()), fx::ErrorCode::InvalidValue);
    bad = immediateView(static_cast<Source>(7));
    EXPECT_EQ(fx::implOf(*plugin).renderImmediate(bad, immediate.get()), fx::ErrorCode::InvalidValue);
    HostTarget wrongSize(kW / 2, kH / 2, GL_DEPTH_COMPONENT24);
    EXPECT_EQ(fx::implOf(*plugin).renderImmediate(immediateView(Source::DepthTexture, wrongSize.depth), immediate.get()),
              fx::ErrorCode::SizeMismatch);
    EXPECT_TRUE(host.logged("error[SizeMismatch] immediate render")) << "refusals are logged";
    // A view away from (0, 0) is drawn since API 2.1 (ViewportTest); a host depth texture must then
    // be the view's size or a framebuffer's that holds the view at the viewport's origin.
    HostTarget tooNarrow(kW + 4, kH, GL_DEPTH_COMPONENT24);
    glViewport(8, 0, kW, kH);
    EXPECT_EQ(fx::implOf(*plugin).renderImmediate(immediateView(Source::DepthTexture, tooNarrow.depth), immediate.get()),
              fx::ErrorCode::SizeMismatch);
    glViewport(0, 0, kW, kH);
    fx::ImmediateView zero = immediateView(Source::None);
    zero.view.width = 0;
    EXPECT_EQ(fx::implOf(*plugin).renderImmediate(zero, immediate.get()), fx::ErrorCode::InvalidView);
    EXPECT_EQ(immediate->targetAllocations(), 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace immediate
}  // namespace fxtest
