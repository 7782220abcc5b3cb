#pragma once
// One viewport of the scene (CUBE's cubeView): a camera, a colour target, and the passes that
// fill it. cubeView::Render -> RenderObjects: set camera parameters, sort the scene's objects into
// buckets, and declare the view's frame in pipeline order (RenderObjects reads top to bottom:
// smoke shadow, depth prepass (prepass-EQUAL only), opaque, alpha-tested, sky, legacy sprites,
// the plugin's passes, depth read-back, HUD). Nothing is decided ahead: the frame graph's
// compile() picks where the linear scene depth comes from (the prepass, whose z-buffer the colour
// target then shares, or the opaque pass's second render target, or nobody when nothing reads
// it), and the passes ask their PassContext at execution (sharesDepth, isNeeded). The passes
// describe what to draw; the GL work is the back end's (render/SceneRenderer).
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "fx/Plugin.h"
#include "render/SceneRenderer.h"
#include "rtt/FrameGraph.h"
#include "view/Buckets.h"

namespace cube {

class cubeScene;
struct FrameSettings;

/// Camera parameters of a view. Defaults: 60 degree vertical field of view, near 0.1, far 2000.
struct ViewCamera {
    glm::vec3 eye{0.0f, 2.0f, 8.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovY = glm::radians(60.0f);
    float nearPlane = 0.1f;
    float farPlane = 2000.0f;
    glm::mat4 view() const;
    /// Standard: GL's [-1, 1] clip depth, near -> -1. `reversedZ`: clip depth in [0, 1] with
    /// near -> 1 and far -> 0 (for glClipControl ZERO_TO_ONE and a float z-buffer cleared to 0).
    glm::mat4 proj(float aspect, bool reversedZ = false) const;
};

class cubeView {
public:
    cubeView(std::string name, int index) : name_(std::move(name)), index_(index) {}

    const std::string& name() const { return name_; }
    ViewCamera& camera() { return camera_; }
    const ViewCamera& camera() const { return camera_; }
    void setSize(int width, int height) { width_ = width; height_ = height; }
    int width() const { return width_; }
    int height() const { return height_; }
    /// Draws this view into the rectangle (x, y, width(), height()) of `target` (targetWidth x
    /// targetHeight), a colour target with a z-buffer that other views share (a split screen),
    /// instead of a target of its own. The view then clears nothing of it (whoever created it
    /// clears it once) and its linear scene depth, when read, is the target's size.
    /// An invalid target: the view's own again.
    void placeIn(rtt::FrameGraphResource target, int x, int y, int targetWidth, int targetHeight) {
        placedIn_ = target;
        x_ = x;
        y_ = y;
        targetWidth_ = targetWidth;
        targetHeight_ = targetHeight;
    }
    bool placed() const { return placedIn_.valid(); }

    /// Declares this view's passes into `graph`; returns the view's colour target.
    rtt::FrameGraphResource Render(cubeScene& scene, rtt::FrameGraph& graph, const FrameSettings& settings);

    /// Draws recorded in the last RenderObjects, per bucket (for tests and stats).
    size_t opaqueDraws() const { return opaque_.size(); }
    /// The view as the plugin gets it (matrices, size, depth convention and the scene's fog),
    /// as of the last RenderObjects.
    fx::ViewInfo pluginView() const;

private:
    struct Targets {
        rtt::FrameGraphResource sceneDepth;  ///< R32F linear depth (+ the z-buffer, if shared)
        rtt::FrameGraphResource color;       ///< RGBA8 + its own z-buffer, or the prepass's (compile decides)
    };
    rtt::FrameGraphResource RenderObjects(cubeScene& scene, rtt::FrameGraph& graph, const FrameSettings& settings);
    Targets declareTargets(rtt::FrameGraph& graph);
    rtt::DepthFormat zBufferFormat() const;
    void declareDepthPrepass(cubeScene& scene, rtt::FrameGraph& graph, const Targets& t, const FrameSettings& s);
    void declareOpaque(cubeScene& scene, rtt::FrameGraph& graph, const Targets& t, const FrameSettings& s);
    void declareAlphaTested(cubeScene& scene, rtt::FrameGraph& graph, const Targets& t);
    void declareSky(cubeScene& scene, rtt::FrameGraph& graph, const Targets& t);
    void declareLegacySprites(cubeScene& scene, rtt::FrameGraph& graph, const Targets& t, const FrameSettings& s);
    void declarePluginPasses(rtt::FrameGraph& graph, const Targets& t, const FrameSettings& s);
    /// The smoke's opacity map (the plugin's declareShadowPasses), in the shadow bucket before
    /// the opaque pass that darkens the ground with it.
    void declareSmokeShadow(rtt::FrameGraph& graph, const Targets& t, const FrameSettings& s);
    void declareDepthReadback(rtt::FrameGraph& graph, const Targets& t, const FrameSettings& s);
    void declareHud(cubeScene& scene, rtt::FrameGraph& graph, const Targets& t, const FrameSettings& s);
    CameraMatrices cameraMatrices() const;
    void recordBuckets(cubeScene& scene);
    std::string passName(const char* bucket) const { return name_ + "." + bucket; }
    int order(int bucketOrder) const { return index_ * kViewOrderStride + bucketOrder; }
    /// bindForDraw(color) and, for a placed view, its rectangle as the viewport.
    bool bindColor(rtt::PassContext& ctx, rtt::FrameGraphResource color) const;
    bool bindColor(rtt::PassContext& ctx, rtt::FrameGraphResource color, rtt::FrameGraphResource second) const;

    std::string name_;
    int index_;
    ViewCamera camera_;
    int width_ = 0, height_ = 0;
    rtt::FrameGraphResource placedIn_;  ///< a shared colour target (placeIn), or none: the view's own
    int x_ = 0, y_ = 0, targetWidth_ = 0, targetHeight_ = 0;
    glm::mat4 view_{1.0f}, proj_{1.0f};
    bool reversedZ_ = false;  ///< the scene renderer's depth convention, read each frame
    SceneFog fog_;            ///< the scene renderer's fog, read each frame (the plugin gets it too)
    // Buckets, recorded by the game side; the pass callbacks only draw them.
    std::vector<MeshDraw> all_, opaque_, alphaTested_;
    std::vector<std::string> names_;
    fx::SmokeShadow smokeShadow_;  ///< this frame's smoke opacity map (invalid: no lit smoke)
};

}  // namespace cube
