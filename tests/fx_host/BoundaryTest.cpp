// API 2's C boundary with GL: every frame of the other fx_host tests already crosses it (the C++
// layer turns the test graph into an fxFrameBuilder, the library turns it back); these check what
// only the boundary does: a left-handed host's matrices give the right-handed picture bit for bit,
// and a bad frame builder or view descriptor is refused before anything is declared.
#include <cstddef>
#include <cstring>

#include "FxTestHost.h"

namespace fxtest {
namespace {

class BoundaryTest : public PluginHostTest {
protected:
    BoundaryTest() : PluginHostTest(160, 120) {}

    // The burnout smoke after one second of wheelspin, reached through the C table (`api` on
    // `bridge`'s handle) as a C host reaches it.
    void createBehindTheCTable() {
        createPlugin(CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml");
        simulate(1.0f, 60);
        bridge = dynamic_cast<fx::detail::CApiPlugin*>(plugin.get());
        ASSERT_NE(bridge, nullptr);
        api = bridge->api();
    }

    fx::detail::CApiPlugin* bridge = nullptr;
    const fxApi* api = nullptr;
};

// The left-handed pair that draws the same clip coordinates: view_lh = F view, proj_lh = proj F.
fx::ViewInfo leftHanded(fx::ViewInfo v) {
    glm::mat4 flip(1.0f);
    flip[2][2] = -1.0f;
    v.view = flip * v.view;
    v.proj = v.proj * flip;
    v.handedness = fx::Handedness::LeftHanded;
    return v;
}

TEST_F(BoundaryTest, ALeftHandedHostGetsTheRightHandedPictureBitForBit) {
    createPlugin(CUBE_SOURCE_DIR "/reactions/burnout_smoke.yaml");
    simulate(1.0f, 90);
    for (fx::Technique t : {fx::Technique::Hard, fx::Technique::Soft, fx::Technique::Spherical}) {
        fx::RenderOptions o;
        o.techniqueOverride = t;
        ASSERT_EQ(plugin->setRenderOptions(o), fx::ErrorCode::None);
        const Image right = render();
        // The test host draws its scene (and its linear depth) with the right-handed view; only
        // the plugin gets the left-handed pair.
        const fx::ViewInfo lh = leftHanded(view);
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& frame) { plugin->declarePasses(lh, frame); });
        const Image left = graph.readColor();
        const Image none = render(false);
        EXPECT_EQ(maxAbsDiff(left, right), 0) << "technique " << int(t);
        EXPECT_GT(maxAbsDiff(right, none), 40) << "no smoke drawn, technique " << int(t);
    }
    // Left-handed view space reads +Z as forward: the same matrices marked right-handed put the
    // camera's forward behind it and draw nothing.
    fx::ViewInfo wrong = leftHanded(view);
    wrong.handedness = fx::Handedness::RightHanded;
    renderFrame(graph, scene, view, [&](fx::FrameBuilder& frame) { plugin->declarePasses(wrong, frame); });
    EXPECT_EQ(plugin->stats().particlesDrawn, 0);
    EXPECT_TRUE(host.errors().empty());
}

// A frame graph that records what the plugin declared through the C table.
struct RecordingFrame {
    int targets = 0, passes = 0, released = 0;
    static uint32_t color(void*) { return 1; }
    static uint32_t depth(void*) { return 2; }
    static uint32_t create(void* u, const char*, const fxTargetDesc*) { return 100 + uint32_t(++self(u).targets); }
    static void add(void* u, const char*, const uint32_t*, int, const uint32_t*, int, fxPassCallback cb) {
        ++self(u).passes;
        cb.release(cb.user);
        ++self(u).released;
    }
    static RecordingFrame& self(void* u) { return *static_cast<RecordingFrame*>(u); }
    fxFrameBuilder c() {
        fxFrameBuilder f;
        std::memset(&f, 0, sizeof f);
        f.size = sizeof f;
        f.user = this;
        f.sceneColor = &color;
        f.sceneDepth = &depth;
        f.createTarget = &create;
        f.addPass = &add;
        return f;
    }
};

TEST_F(BoundaryTest, BadFrameBuildersAndViewsAreRefusedBeforeAnythingIsDeclared) {
    ASSERT_NO_FATAL_FAILURE(createBehindTheCTable());
    fxViewDesc v = fx::detail::viewToC(view);
    RecordingFrame rec;
    fxFrameBuilder f = rec.c();

    ASSERT_EQ(api->declarePasses(bridge->handle(), &v, &f), FX_ERROR_NONE);
    EXPECT_GT(rec.passes, 0);
    EXPECT_EQ(rec.released, rec.passes);  // every pass handed back once
    const int declared = rec.passes;

    rec = RecordingFrame{};
    f = rec.c();
    f.size = 16;
    EXPECT_EQ(api->declarePasses(bridge->handle(), &v, &f), FX_ERROR_BAD_DESCRIPTOR);
    f = rec.c();
    f.addPass = nullptr;
    EXPECT_EQ(api->declarePasses(bridge->handle(), &v, &f), FX_ERROR_NULL_ARGUMENT);
    f = rec.c();
    fxViewDesc bad = v;
    bad.size = sizeof bad + 8;
    EXPECT_EQ(api->declarePasses(bridge->handle(), &bad, &f), FX_ERROR_BAD_DESCRIPTOR);
    bad = v;
    bad.depthOrder = 7;
    EXPECT_EQ(api->declarePasses(bridge->handle(), &bad, &f), FX_ERROR_INVALID_VIEW);
    bad = v;
    bad.width = 0;
    EXPECT_EQ(api->declarePasses(bridge->handle(), &bad, &f), FX_ERROR_INVALID_VIEW);
    EXPECT_EQ(rec.targets + rec.passes, 0);  // nothing declared by any refused call
    EXPECT_TRUE(host.logged("error[BadDescriptor] declarePasses: fxFrameBuilder::size = 16"));
    EXPECT_TRUE(host.logged("error[InvalidView] declarePasses: depthOrder 7"));

    // The refusals changed nothing: the same call declares the same passes again.
    f = rec.c();
    ASSERT_EQ(api->declarePasses(bridge->handle(), &v, &f), FX_ERROR_NONE);
    EXPECT_EQ(rec.passes, declared);
}

// API 2.1 appended fog and the distance slice to fxViewDesc: a 2.0 host's smaller descriptor is
// still served (as no fog and every particle, whatever lies past its end), and bad fog or slice
// values are refused as InvalidView.
TEST_F(BoundaryTest, AnApi20ViewDescriptorIsServedAndBadFogOrSlicesAreRefused) {
    ASSERT_NO_FATAL_FAILURE(createBehindTheCTable());
    RecordingFrame rec;
    fxFrameBuilder f = rec.c();
    fxViewDesc v = fx::detail::viewToC(view);
    ASSERT_EQ(api->declarePasses(bridge->handle(), &v, &f), FX_ERROR_NONE);
    const int passes = rec.passes;
    ASSERT_GT(passes, 0);

    // A 2.0 host: size = the offset of viewportX, the first field 2.1 appended; the bytes after
    // it (here an empty slice far away and a fog mode no host may pass) are not read.
    fxViewDesc old = v;
    old.size = uint32_t(offsetof(fxViewDesc, viewportX));
    old.fogMode = 99;
    old.sliceMinDistance = 1e6f;
    old.sliceMaxDistance = 2e6f;
    rec = RecordingFrame{};
    f = rec.c();
    EXPECT_EQ(api->declarePasses(bridge->handle(), &old, &f), FX_ERROR_NONE);
    EXPECT_EQ(rec.passes, passes);

    // The same slice from a 2.1 host: nothing in it, nothing declared.
    fxViewDesc sliced = v;
    sliced.sliceMinDistance = 1e6f;
    sliced.sliceMaxDistance = 2e6f;
    rec = RecordingFrame{};
    f = rec.c();
    EXPECT_EQ(api->declarePasses(bridge->handle(), &sliced, &f), FX_ERROR_NONE);
    EXPECT_EQ(rec.passes, 0);

    auto refused = [&](fxViewDesc bad) {
        rec = RecordingFrame{};
        f = rec.c();
        const int r = api->declarePasses(bridge->handle(), &bad, &f);
        return r == FX_ERROR_INVALID_VIEW && rec.passes == 0;
    };
    fxViewDesc bad = v;
    bad.fogMode = 4;
    EXPECT_TRUE(refused(bad));
    bad = v;
    bad.fogMode = FX_FOG_LINEAR;
    bad.fogStart = bad.fogEnd = 5.0f;
    EXPECT_TRUE(refused(bad));
    bad = v;
    bad.fogMode = FX_FOG_EXP;
    bad.fogDensity = -0.1f;
    EXPECT_TRUE(refused(bad));
    bad = v;
    bad.sliceMinDistance = 5.0f;
    bad.sliceMaxDistance = 3.0f;
    EXPECT_TRUE(refused(bad));
    bad = v;
    bad.sliceMinDistance = -1.0f;
    EXPECT_TRUE(refused(bad));
    EXPECT_TRUE(host.logged("error[InvalidView] declarePasses: fog mode 4"));
    EXPECT_TRUE(host.logged("error[InvalidView] declarePasses: linear fog with start = end"));

    // Valid fog passes: exp fog with a density, and linear fog.
    fxViewDesc good = v;
    good.fogMode = FX_FOG_EXP2;
    good.fogDensity = 0.05f;
    rec = RecordingFrame{};
    f = rec.c();
    EXPECT_EQ(api->declarePasses(bridge->handle(), &good, &f), FX_ERROR_NONE);
    EXPECT_EQ(rec.passes, passes);
}

}  // namespace
}  // namespace fxtest
