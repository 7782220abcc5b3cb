#pragma once
// fx_host: a second, engine-free host for the plugin. Its own OSMesa context (OsMesaContext.cpp,
// the only file that sees GL/osmesa.h), its own frame graph (TestFrameGraph.cpp: FBO targets, a
// linear-depth R32F sceneDepth with a z-buffer filled by a "prepass" that runs only when a later
// pass reads it, pass culling), its own scene of flat quads (ground, walls) with its own shaders,
// and its own HostAdapter with scripted wheels (TestScene.cpp). Nothing here includes
// engine_stub: the build links this area with fx_plugin, glad, yaml-cpp and OSMesa only.
//
// GL errors: every test checks glGetError after each pass and counts KHR_debug messages of HIGH
// and MEDIUM severity through a callback (GlTestSupport.cpp).
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "fx/HostAdapter.h"
#include "fx/Plugin.h"
#include "../../fx_plugin/render/ParticleRenderer.h"
#include "../../fx_plugin/sim/ParticlePool.h"

namespace fxtest {

// ---- context (OsMesaContext.cpp) -------------------------------------------------------------

using ProcAddressFn = void (*(*)(const char*))();
/// Creates the process's OSMesa context once and makes it current; false + *error when it cannot.
/// A 3.3 core context, or a compatibility-profile one (3.3 or later) when the environment has
/// CUBE_FX_HOST_PROFILE=compat (the poisoned-host test's second run). The proc-address function
/// is what glad loads the entry points with.
bool createOsMesaContext(std::string* error);
/// True when the process's context is a compatibility-profile one.
bool osMesaCompatibilityProfile();
ProcAddressFn osMesaProcAddress();
/// Gives the context's default framebuffer (RGBA8, DEPTH24 + STENCIL8) this size (it starts 4 x 4;
/// the immediate-path tests draw into it as a host without FBOs would). False when it cannot.
bool resizeDefaultFramebuffer(int width, int height);

// ---- GL support (GlTestSupport.cpp) ----------------------------------------------------------

/// Context + glad + the debug callback, once per process. Tests call it in SetUp.
bool ensureGl(std::string* error);
/// glFlush calls the plugin made since the process started, or -1 where its GL table was not
/// filled by these tests' loaders (ensureGl, TestHostAdapter), which count them.
int pluginFlushes();
/// GL errors seen since the last reset: glGetError codes drained by drainGlErrors() plus
/// KHR_debug messages of HIGH or MEDIUM severity.
int glErrorCount();
std::string glErrorLog();
/// Also disallows shader-compiler messages again (see below).
void resetGlErrors();
/// For tests that break a shader on purpose: KHR_debug messages from the shader compiler are
/// counted apart (shaderCompilerMessages()) until the next resetGlErrors().
void allowShaderCompilerMessages();
int shaderCompilerMessages();
/// Drains glGetError into the count; returns how many were pending.
int drainGlErrors(const char* where);
bool hasKhrDebug();
/// A GL program from two inline GLSL sources (the tests' own scene, plane and state shaders);
/// asserts that it links.
uint32_t compileTestProgram(const char* vs, const char* fs);

/// The GL state a host cares about after a plugin pass (25 values, some of them arrays).
struct GlStateSnapshot {
    int program = 0, vertexArray = 0, arrayBuffer = 0, elementBuffer = 0, activeTexture = 0;
    int texture2D[8] = {};
    int sampler[8] = {};
    int blend = 0, blendSrcRgb = 0, blendDstRgb = 0, blendSrcAlpha = 0, blendDstAlpha = 0;
    int blendEqRgb = 0, blendEqAlpha = 0;
    int depthTest = 0, depthFunc = 0, depthMask = 0, cullFace = 0, scissorTest = 0, stencilTest = 0;
    int colorMask[4] = {};
    int viewport[4] = {};
    int scissorBox[4] = {};
    int drawFramebuffer = 0, readFramebuffer = 0;
    float clearColor[4] = {};
    int unpackBuffer = 0, unpackAlignment = 0;

    /// "name: before -> after" for each differing value; empty when equal.
    std::string diff(const GlStateSnapshot& after) const;
};
GlStateSnapshot captureGlState();

/// Puts the context into an unusual but valid host state (its own program, VAO with an element
/// buffer, textures on units 0-7, sampler objects, blending, depth GREATER, culling, scissor,
/// stencil, a colour mask, an odd viewport, other framebuffers, a bound pixel-unpack buffer...).
/// Creates its objects once.
void applyDirtyHostState();
/// GL's initial values for everything applyDirtyHostState() touches (each test starts here).
void applyDefaultHostState();

// ---- images (GlTestSupport.cpp) --------------------------------------------------------------

struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;  ///< bottom row first (GL order)
    const uint8_t* at(int x, int y) const { return &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
    /// Channel c of pixel (x, y) in [0, 1].
    float value(int x, int y, int c) const { return at(x, y)[c] / 255.0f; }
};
/// The RGBA8 pixels of `framebuffer`'s colour attachment 0 (0 = the default one), width x height
/// from the origin; leaves the read framebuffer at 0.
Image readFramebuffer(uint32_t framebuffer, int width, int height);
/// A host framebuffer of its own (GlTestSupport.cpp): an RGBA8 colour texture + a depth texture of
/// `depthFormat` (0 = none), deleted with it.
struct HostTarget {
    uint32_t colour = 0, depth = 0, fbo = 0;
    int width = 0, height = 0;
    HostTarget(int w, int h, uint32_t depthFormat);
    ~HostTarget();
    HostTarget(const HostTarget&) = delete;
    HostTarget& operator=(const HostTarget&) = delete;
};
/// Writes a PNG (top row first) for looking at; returns false when it cannot.
bool writePng(const std::string& path, const Image& image);
/// PSNR over RGB, in dB (infinity when equal); `mask` (optional, width*height) selects pixels.
double psnr(const Image& a, const Image& b, const std::vector<uint8_t>* mask = nullptr);
/// Largest |a - b| over RGB channels, in 1/255 units.
int maxAbsDiff(const Image& a, const Image& b);

// ---- depth-edge error (EdgeScene.cpp): the quarter-res tests -----------------------------------

/// |a - b| per channel times `gain`, opaque, for looking at.
Image amplifiedDiff(const Image& a, const Image& b, int gain);
/// Pixels within `radius` px (Chebyshev) of a depth discontinuity: neighbours whose linear depths
/// (width x height, bottom row first) differ by more than 10 % of the nearer one.
std::vector<uint8_t> depthEdgeMask(const std::vector<float>& depth, int width, int height, int radius);
struct MaskError {
    double mean = 0.0;  ///< mean |difference| per RGB channel, 1/255 units
    int max = 0;
    int pixels = 0;
};
/// |a - b| over the pixels `mask` selects.
MaskError maskedError(const Image& a, const Image& b, const std::vector<uint8_t>& mask);

// ---- frame graph (TestFrameGraph.cpp) --------------------------------------------------------

/// The host's render-to-texture layer, as the plugin sees it through fx::FrameBuilder.
/// Per frame: beginFrame(), the host's and the plugin's addPass calls, execute(). Culling: a
/// pass runs when it writes sceneColor (the presented target) or a target that a later running
/// pass reads; targets are allocated (from a pool kept across frames) only for running passes.
class TestFrameGraph final : public fx::FrameBuilder {
public:
    /// `floatDepth`: 32-bit float z-buffers (what a reversed-Z host uses), else 24-bit.
    /// `zBuffer`: sceneColor's z-buffer is a depth texture offered through sceneZBuffer() (API
    /// 2.1), drawn under clip control ZERO_TO_ONE when `floatDepth` (the reversed-Z hosts of
    /// these tests: useReversedZ); else a renderbuffer and nothing is offered.
    TestFrameGraph(int width, int height, bool floatDepth = false, bool zBuffer = false);
    ~TestFrameGraph() override;

    void beginFrame();
    /// Passes declared from now on count as the plugin's (for the state checks).
    void beginPluginPasses() { pluginPasses_ = true; }
    void endPluginPasses() { pluginPasses_ = false; }
    void execute();

    // fx::FrameBuilder
    fx::Target sceneColor() override { return fx::Target{kSceneColor}; }
    fx::Target sceneDepth() override { return fx::Target{kSceneDepth}; }
    fx::Target sceneZBuffer() override { return zBufferTex_ ? fx::Target{kSceneZBuffer} : fx::Target{}; }
    fx::HostDepth sceneZBufferMapping() override { return zMapping_; }
    fx::Target createTarget(const char* name, const fx::TargetDesc& desc) override;
    void addPass(const char* name, std::initializer_list<fx::Target> reads,
                 std::initializer_list<fx::Target> writes,
                 std::function<void(fx::PassContext&)> execute) override;

    // What the last frame did.
    const std::vector<std::string>& declared() const { return declared_; }
    const std::vector<std::string>& executed() const { return executed_; }
    bool ran(const std::string& pass) const;
    /// The plugin's passes that bound a target to draw into (PassContext::bindForDraw): a pass
    /// that ran and did nothing is not among them.
    const std::vector<std::string>& drew() const { return drew_; }
    bool drewIn(const std::string& pass) const;
    int targetsCreated() const { return targetsCreated_; }      ///< createTarget calls
    int targetsAllocated() const { return targetsAllocated_; }  ///< created targets backed by GL
    std::vector<std::string> allocatedTargetNames() const;
    bool sceneDepthUsed() const { return sceneDepthUsed_; }
    bool zBufferUsed() const { return zBufferUsed_; }

    /// When set, runs before every plugin pass; the state is snapshotted after it and compared
    /// after the pass. Mismatches are collected in stateMismatches().
    std::function<void()> beforePluginPass;
    /// When set, runs right after every plugin pass (before the GL error drain), with its name.
    std::function<void(const std::string&)> afterPluginPass;
    /// When set and true for a plugin pass's name, that pass is left out though it would run (a
    /// host graph that culled it, or ran it elsewhere): what the plugin's next passes must survive.
    std::function<bool(const std::string&)> skipPluginPass;
    bool checkPluginState = false;
    /// Relative sizes round up (the engine's RenderTargetPool) instead of down: a half-size
    /// target of an odd view then has a last column and row of one pixel's block.
    bool roundSizesUp = false;
    const std::vector<std::string>& stateMismatches() const { return stateMismatches_; }

    int width() const { return width_; }
    int height() const { return height_; }
    Image readColor() const;
    std::vector<float> readLinearDepth() const;
    /// RGBA as floats (bottom row first) of the target named `name` that this frame allocated;
    /// empty when there is none. Its size in *width, *height.
    std::vector<float> readTarget(const std::string& name, int* width, int* height) const;
    /// GL objects for the host's own passes.
    unsigned colorFramebuffer() const { return colorFbo_; }
    unsigned depthFramebuffer() const { return depthFbo_; }
    /// Sets the sampling state of the scene's linear depth (R32F, what sceneDepth() names), as a
    /// host might leave it: min / mag filter and GL_TEXTURE_MAX_LEVEL (built with NEAREST, 0).
    void setSceneDepthSampling(int minFilter, int magFilter, int maxLevel);

    static constexpr uint32_t kSceneColor = 1, kSceneDepth = 2;
    static constexpr uint32_t kSceneZBuffer = 0xFFFF0000u;  ///< outside createTarget's ids

private:
    struct Pass {
        std::string name;
        std::vector<uint32_t> reads, writes;
        std::function<void(fx::PassContext&)> execute;
        bool plugin = false;
    };
    struct TargetSlot {
        std::string name;
        fx::TargetDesc desc;
        int width = 0, height = 0;
        unsigned texture = 0, framebuffer = 0, depth = 0;
        bool inUse = false;
    };
    class Context;

    TargetSlot* slotFor(uint32_t id);
    void allocate(uint32_t id);

    int width_, height_;
    unsigned colorTex_ = 0, colorDepth_ = 0, colorFbo_ = 0;
    unsigned zBufferTex_ = 0;  ///< sceneColor's z-buffer as a texture (zBuffer), else 0
    fx::HostDepth zMapping_;
    bool zBufferUsed_ = false;
    unsigned depthTex_ = 0, depthDepth_ = 0, depthFbo_ = 0;
    std::vector<Pass> passes_;
    std::vector<TargetSlot> pool_;              ///< GL targets kept across frames
    std::map<uint32_t, size_t> frameTargets_;   ///< created id -> pool slot (this frame)
    std::vector<std::pair<std::string, fx::TargetDesc>> created_;  ///< id - 3 -> request
    std::vector<std::string> declared_, executed_, drew_, stateMismatches_;
    int targetsCreated_ = 0, targetsAllocated_ = 0;
    bool sceneDepthUsed_ = false;
    bool pluginPasses_ = false;
};

// ---- scene and host (TestScene.cpp) ----------------------------------------------------------

/// A flat-coloured parallelogram: origin + s * edgeU + t * edgeV, s, t in [0, 1].
struct SceneQuad {
    glm::vec3 origin{0.0f}, edgeU{1.0f, 0.0f, 0.0f}, edgeV{0.0f, 0.0f, 1.0f};
    glm::vec3 colour{0.5f};
};

/// The host's opaque world. declareHostPasses() adds "prepass" (linear depth + z into
/// sceneDepth; culled unless a particle pass reads it) and "opaque" (colour into sceneColor).
class TestScene {
public:
    std::vector<SceneQuad> quads;
    glm::vec3 sky{0.35f, 0.45f, 0.6f};
    /// Linear depth where nothing is drawn; negative = the view's far plane. fx/HostAdapter.h
    /// allows any value >= far, or 0.
    float depthBackground = -1.0f;
    /// Draw the opaque pass with reversed-Z (glClipControl ZERO_TO_ONE, clear 0, GEQUAL); the
    /// view's proj must then be a reversed-Z projection (reversedZProjection()).
    bool reversedZ = false;
    /// drawOpaque only: draw under glClipControl ZERO_TO_ONE in standard order (a host with [0, 1]
    /// projection matrices that does not reverse z). Left set afterwards, like reversed-Z.
    bool clipZeroToOne = false;

    void declareHostPasses(TestFrameGraph& graph, const fx::ViewInfo& view);
    /// The "opaque" pass's drawing (clear to the sky, colour and z of the quads) into the
    /// framebuffer bound now, viewport (0, 0, view size): a host without a frame graph.
    void drawOpaque(const fx::ViewInfo& view) const;

    static SceneQuad ground(float halfExtent, glm::vec3 colour, float y = 0.0f);
    /// A wall in the plane z = `z`, facing +z, spanning x in [x0, x1] and y in [y0, y1].
    static SceneQuad wallZ(float z, float x0, float x1, float y0, float y1, glm::vec3 colour);
};

/// A view for a camera at `eye` looking at `target`, 60 degree vertical field of view.
fx::ViewInfo makeView(glm::vec3 eye, glm::vec3 target, int width, int height,
                      float nearPlane = 0.1f, float farPlane = 1000.0f);
/// The view's projection with near mapped to depth 1 and far to 0 (for glClipControl's
/// ZERO_TO_ONE range); sets view->depth to ReversedZ.
void useReversedZ(fx::ViewInfo* view);
/// Pixel (x, y from the bottom) where a world point lands; z is the NDC depth.
glm::vec3 projectToPixel(const fx::ViewInfo& view, glm::vec3 world);

/// Scripted car: four wheels of a car at `position` (rear axle at +z), all grounded on asphalt.
class TestHostAdapter final : public fx::HostAdapter {
public:
    TestHostAdapter();
    /// The OSMesa context's entry points: the plugin fills its private GL table from these.
    void* getProcAddress(const char* name) override;
    int wheelCount() const override { return 4; }
    fx::WheelContact wheel(int index) const override { return wheels_[size_t(index & 3)]; }
    void log(fx::LogLevel level, const char* message) override;

    void setRearSlip(float slip);
    const std::vector<std::string>& errors() const { return errors_; }
    const std::vector<std::string>& messages() const { return messages_; }
    bool logged(const std::string& fragment) const;

private:
    fx::WheelContact wheels_[4];
    std::vector<std::string> errors_, messages_;
};

/// Renders one frame: the scene's host passes, then `declareParticles` (the plugin's hook, or
/// nothing), then execute. The graph is reset first.
void renderFrame(TestFrameGraph& graph, TestScene& scene, const fx::ViewInfo& view,
                 const std::function<void(fx::FrameBuilder&)>& declareParticles);

/// A writable directory under /tmp for this test run (created on first use).
std::string scratchDir();

/// One way of drawing that a test goes through in turn: a technique, quarter res (always) or full,
/// lit by the default scene light or unlit.
struct RenderMode {
    const char* label;
    fx::Technique technique;
    bool quarter = false, lit = false;
    bool tiled = false;  ///< the tiled compute path (RenderOptions::tiled)
};
/// The modes that more than one test file goes through.
namespace modes {
inline constexpr RenderMode kHard{"hard", fx::Technique::Hard};
inline constexpr RenderMode kSoft{"soft", fx::Technique::Soft};
inline constexpr RenderMode kSpherical{"spherical", fx::Technique::Spherical};
inline constexpr RenderMode kSoftQuarter{"soft quarter", fx::Technique::Soft, true};
inline constexpr RenderMode kSphericalQuarter{"spherical quarter", fx::Technique::Spherical, true};
inline constexpr RenderMode kMega{"mega", fx::Technique::Mega};
inline constexpr RenderMode kSoftLit{"soft lit", fx::Technique::Soft, false, true};
inline constexpr RenderMode kHardTiled{"hard tiled", fx::Technique::Hard, false, false, true};
inline constexpr RenderMode kSoftTiled{"soft tiled", fx::Technique::Soft, false, false, true};
inline constexpr RenderMode kSphericalTiled{"spherical tiled", fx::Technique::Spherical, false, false, true};
inline constexpr RenderMode kSoftLitTiled{"soft lit tiled", fx::Technique::Soft, false, true, true};
}  // namespace modes

// ---- hand-placed particles (TestParticles.cpp) ------------------------------------------------

/// One particle put straight into a pool (no simulation).
struct HandParticle {
    glm::vec3 position{0.0f};
    float size = 1.0f;
    float life = 0.5f;
    float rotation = 0.0f;
    float fade = 1.0f;
    int frame = 0;
};

/// The plugin's renderer drawing one hand-filled pool: the targeted technique tests use it to
/// place a particle exactly. `desc` starts as the wheel_smoke defaults with an opaque white ramp.
class DirectParticles {
public:
    explicit DirectParticles(fx::HostAdapter* host, std::string shaderDir = std::string(),
                             std::string dataDir = std::string(), int capacity = 4096);
    void set(const std::vector<HandParticle>& particles);
    /// The plugin's hook body for one view: declares the renderer's passes into `frame`.
    int declare(const fx::ViewInfo& view, fx::FrameBuilder& frame);
    /// The technique of `m`, its quarter res (always, when on) and its tiled path in `settings`;
    /// the light stays.
    void setMode(const RenderMode& m);

    fx::ReactionDesc desc;
    fx::FrameSettings settings;  ///< what the plugin's hook reads from its switches once a frame
    fx::ProgramCache programs;   ///< the renderer's programs (Renderers' cache in the plugin)
    fx::ParticleRenderer renderer;
    fx::ParticlePool pool;
};

/// A cache of the embedded shaders with the depth lineariser's program built (the program the
/// plugin's DepthLinearizer takes from Renderers' cache); the test fails where it does not build.
void buildLinearizeProgram(fx::ProgramCache* programs);

/// The depth-edge scene (EdgeScene.cpp) of the quarter-res tests: bright soft puffs (softness 0.3 m) behind a wall
/// whose top edge crosses them and a 6 cm pole in front, on a dark ground, seen from 8 m.
struct EdgeScene {
    TestScene scene;
    std::vector<HandParticle> puffs;
    fx::ViewInfo view;
    float softness = 0.3f;
};
EdgeScene wallAndPoleScene(int width, int height, bool reversedZ);

/// Base fixture: GL up, errors reset before and checked (0) after every test.
/// GL comes up in the constructor, so fixture members may create GL objects.
class FxHostTest : public ::testing::Test {
protected:
    FxHostTest() { glReady_ = ensureGl(&glError_); }
    void SetUp() override {
        ASSERT_TRUE(glReady_) << glError_;
        applyDefaultHostState();
        resetGlErrors();
    }
    void TearDown() override {
        drainGlErrors("end of test");
        EXPECT_EQ(glErrorCount(), 0) << glErrorLog();
    }

private:
    bool glReady_ = false;
    std::string glError_;
};


/// Base fixture for tests that drive the plugin through its public entry point (PluginHostTest.cpp):
/// SetUp creates `plugin` on `host`; createPlugin... loads the reactions; the end-to-end view
/// (from (5, 2.2, 7.5) toward the rear wheels) over a ground-only `scene`.
class PluginHostTest : public FxHostTest {
protected:
    static constexpr float kDt = 1.0f / 60.0f;
    PluginHostTest(int width, int height) : graph(width, height), width_(width), height_(height) {}
    /// Creates the plugin and loads `reactions` (a folder or file); asserts on failure.
    void createPlugin(const std::string& reactions);
    /// `steps` steps of kDt with the rear wheels slipping at `slip`.
    void simulate(float slip, int steps);
    /// One frame of `scene` from `view`, with the plugin's passes when `withPlugin`.
    Image render(bool withPlugin = true);
    /// The GL-state tests' setting: the ground, a wall behind the smoke, the view from (4, 2, 7).
    void useWallScene();
    /// Sets the render options and the scene light of `m`; asserts that the plugin takes them.
    void setMode(const RenderMode& m);
    /// One frame from `v`; with `dirty` the host state is scrambled before declarePasses and
    /// before every plugin pass, and each state the plugin left changed is appended to *mismatches.
    Image renderChecked(const fx::ViewInfo& v, bool dirty, std::string* mismatches);

    TestHostAdapter host;
    std::unique_ptr<fx::Plugin> plugin;
    TestScene scene;
    fx::ViewInfo view;
    TestFrameGraph graph;

private:
    int width_, height_;
};

/// What a LoadedPluginTest's SetUp does after PluginHostTest's: createPlugin(reactions), then
/// `slippingSteps` steps with the rear wheels fully slipping, then useWallScene() with `wallScene`.
struct PluginSetUp {
    const char* reactions;
    int slippingSteps = 0;
    bool wallScene = false;
};

/// The burnout smoke after one second of wheelspin, in front of the wall.
inline constexpr PluginSetUp kSmokeOnWall{CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml", 60, true};

/// Base fixture for the tests whose plugin is loaded and warmed up the same way before each test.
class LoadedPluginTest : public PluginHostTest {
protected:
    LoadedPluginTest(int width, int height, PluginSetUp setUp) : PluginHostTest(width, height), setUp_(setUp) {}
    void SetUp() override {
        PluginHostTest::SetUp();
        createPlugin(setUp_.reactions);
        if (setUp_.slippingSteps > 0) simulate(1.0f, setUp_.slippingSteps);
        if (setUp_.wallScene) useWallScene();
    }

private:
    PluginSetUp setUp_;
};

}  // namespace fxtest
