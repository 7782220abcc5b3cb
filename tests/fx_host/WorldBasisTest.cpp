// The host world's up axis (fxPluginDesc::upAxis, API 2.1): a Z-up host that hands in the same
// scene in its own basis (wheels, their velocities, wind, the collision point, fireReaction's
// point, the sun, the view matrix and the eye) gets the Y-up host's picture bit for bit, and the
// smoke shadow's worldToShadow back in its own basis.
#include <glad/gl.h>

#include <cstring>
#include <string>

#include "FxTestHost.h"

namespace fxtest {
namespace worldbasis {  // named: the fx_host tests build as unity batches

constexpr int kW = 160, kH = 120;
constexpr float kDt = 1.0f / 60.0f;

// Y-up (the plugin's own world) to a right-handed Z-up world: (x, y, z) -> (x, -z, y).
glm::vec3 toZUp(glm::vec3 v) { return glm::vec3(v.x, -v.z, v.y); }
// A Y-up view matrix as a Z-up host has it (the same camera over the same scene): view C, where
// C takes Z-up points to Y-up ones, (x, y, z) -> (x, z, -y).
glm::mat4 viewToZUp(const glm::mat4& v) {
    glm::mat4 out = v;
    out[1] = -v[2];
    out[2] = v[1];
    return out;
}

// The test car with moving wheels, wind and a wall contact, in the Y-up world or turned to Z-up.
class BasisHost final : public fx::HostAdapter {
public:
    BasisHost(TestHostAdapter& gl, bool zUp) : gl_(gl), zUp_(zUp) {}
    void* getProcAddress(const char* name) override { return gl_.getProcAddress(name); }
    int wheelCount() const override { return gl_.wheelCount(); }
    fx::WheelContact wheel(int index) const override {
        fx::WheelContact w = gl_.wheel(index);
        w.velocity = glm::vec3(2.5f, 0.25f, -7.0f);
        w.position = out(w.position);
        w.velocity = out(w.velocity);
        return w;
    }
    glm::vec3 wind() const override { return out(glm::vec3(1.5f, 0.2f, -0.75f)); }
    glm::vec3 collisionPoint() const override { return out(glm::vec3(0.9f, 0.4f, -1.8f)); }
    void log(fx::LogLevel level, const char* message) override { gl_.log(level, message); }
    glm::vec3 out(glm::vec3 v) const { return zUp_ ? toZUp(v) : v; }

private:
    TestHostAdapter& gl_;
    bool zUp_;
};

class WorldBasisTest : public PluginHostTest {
protected:
    WorldBasisTest() : PluginHostTest(kW, kH) {}

    std::unique_ptr<fx::Plugin> make(BasisHost& h, fx::UpAxis up) {
        fx::PluginImports imports;
        imports.host = &h;
        imports.upAxis = up;
        std::unique_ptr<fx::Plugin> p = fxCreatePlugin(imports);
        EXPECT_TRUE(p);
        if (!p) return p;
        fx::Diagnostics diags;
        EXPECT_TRUE(p->loadReactions(CUBE_SOURCE_DIR "/reactions", &diags));
        return p;
    }
    // The same steps for both: slipping rear wheels, a wall contact from step 20, an explosion.
    void simulate(fx::Plugin& p, const BasisHost& h) {
        host.setRearSlip(1.0f);
        for (int s = 0; s < 60; ++s) {
            if (s == 10) {
                EXPECT_EQ(p.fireReaction("explosion", h.out(glm::vec3(-1.0f, 0.5f, -2.0f))), fx::ErrorCode::None);
            }
            for (int r = 0; r < p.reactionCount(); ++r) {
                float collision = s >= 20 ? 0.8f : 0.0f;
                p.continueReaction(r, kDt, &collision);
            }
        }
    }
};

TEST_F(WorldBasisTest, AZUpHostGetsTheYUpHostsPictureBitForBit) {
    BasisHost yHost(host, false), zHost(host, true);
    std::unique_ptr<fx::Plugin> yUp = make(yHost, fx::UpAxis::Y);
    std::unique_ptr<fx::Plugin> zUp = make(zHost, fx::UpAxis::Z);
    ASSERT_TRUE(yUp && zUp);
    useWallScene();
    simulate(*yUp, yHost);
    simulate(*zUp, zHost);
    fx::ViewInfo zView = view;
    zView.view = viewToZUp(view.view);
    zView.eye = toZUp(view.eye);
    fx::SceneLight light;
    fx::SceneLight zLight = light;
    zLight.toSun = toZUp(light.toSun);
    for (bool lit : {false, true}) {
        SCOPED_TRACE(lit ? "lit (shadow passes)" : "unlit");
        if (lit) {
            ASSERT_EQ(yUp->setSceneLight(light), fx::ErrorCode::None);
            ASSERT_EQ(zUp->setSceneLight(zLight), fx::ErrorCode::None);
        }
        fx::SmokeShadow yShadow, zShadow;
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
            yShadow = yUp->declareShadowPasses(view, f);
            EXPECT_EQ(yUp->declarePasses(view, f), fx::ErrorCode::None);
        });
        const Image yImage = graph.readColor();
        const int yDrawn = yUp->stats().particlesDrawn;
        renderFrame(graph, scene, view, [&](fx::FrameBuilder& f) {
            zShadow = zUp->declareShadowPasses(zView, f);
            EXPECT_EQ(zUp->declarePasses(zView, f), fx::ErrorCode::None);
        });
        const Image zImage = graph.readColor();
        ASSERT_GT(yDrawn, 100) << "the comparison needs smoke";
        EXPECT_EQ(zUp->stats().particlesDrawn, yDrawn);
        EXPECT_EQ(maxAbsDiff(zImage, yImage), 0) << "the same picture, bit for bit";
        EXPECT_GT(maxAbsDiff(yImage, render(false)), 0) << "smoke on screen";
        EXPECT_EQ(zShadow.valid(), yShadow.valid());
        if (lit) {
            ASSERT_TRUE(yShadow.valid());
            // worldToShadow takes the host's own points: a Z-up point lands where its Y-up twin does.
            const glm::vec3 p(0.7f, 1.2f, -0.4f);
            const glm::vec4 a = yShadow.worldToShadow * glm::vec4(p, 1.0f);
            const glm::vec4 b = zShadow.worldToShadow * glm::vec4(toZUp(p), 1.0f);
            for (int k = 0; k < 4; ++k) EXPECT_EQ(a[k], b[k]) << "component " << k;
        }
    }
    fx::ParticleCheck yc = yUp->checkParticles(), zc = zUp->checkParticles();
    EXPECT_EQ(zc.alive, yc.alive);
    EXPECT_EQ(zc.nonFinite, 0);
    EXPECT_TRUE(host.errors().empty()) << host.errors().front();
}

TEST_F(WorldBasisTest, AnUpAxisOutsideTheEnumIsRefused) {
    fxHostCallbacks callbacks = fx::detail::HostTrampolines::make(&host);
    fxPluginDesc desc;
    std::memset(&desc, 0, sizeof desc);
    desc.size = sizeof desc;
    desc.host = &callbacks;
    desc.upAxis = 2;
    int error = 0;
    EXPECT_EQ(fxGetApi(FX_API_VERSION)->create(&desc, &error), nullptr);
    EXPECT_EQ(error, FX_ERROR_INVALID_VALUE);
    EXPECT_TRUE(host.logged("upAxis")) << "the refusal names the field";
    // A 2.0 host's descriptor (no upAxis) is Y-up.
    desc.upAxis = 0;
    desc.size = uint32_t(offsetof(fxPluginDesc, upAxis));
    fxPlugin* p = fxGetApi(FX_API_VERSION)->create(&desc, &error);
    EXPECT_NE(p, nullptr);
    EXPECT_EQ(error, FX_ERROR_NONE);
    fxGetApi(FX_API_VERSION)->destroy(p);
}

}  // namespace worldbasis
}  // namespace fxtest
