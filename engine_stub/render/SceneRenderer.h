#pragma once
// The engine's GL back end for the scene: the only engine code (with gl/, rtt/ and platform/)
// that calls GL. The game side (scene/, game/, apps/) describes what to draw (MeshDraw lists, a
// camera, sprite vertices, text) and calls these functions from inside its frame-graph passes,
// with the pass's target bound. Each function sets the GL state it needs through RenderState
// and leaves the context in the engine's default state (RenderState::defaults()) afterwards.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Program.h"
#include "render/GpuScene.h"
#include "render/Hud.h"
#include "render/LegacySpriteRenderer.h"
#include "render/SceneFog.h"
#include "render/SunLight.h"
#include "scene/SceneData.h"

namespace cube {

/// What a scene pass draws with: the camera's matrices and the view's shape.
/// Defaults: identity matrices, 60 degree field of view, square.
struct CameraMatrices {
    glm::mat4 view{1.0f};
    glm::mat4 proj{1.0f};
    float fovY = glm::radians(60.0f);
    float aspect = 1.0f;
};

/// An opaque quad facing the camera `distance` metres in front of it, placed in units of the
/// view's half extents at that distance: centre (0, centerY * halfHeight), half size
/// (halfWidth * halfWidthOfView, halfHeight * halfHeightOfView). Defaults: a full-view quad 10 m
/// ahead, grey.
struct CameraQuad {
    float distance = 10.0f;
    float centerY = 0.0f;
    float halfWidth = 1.0f;
    float halfHeight = 1.0f;
    glm::vec4 color{0.5f, 0.5f, 0.5f, 1.0f};
};

/// Geometry an application attaches to the main view's camera, drawn in the order given in the
/// depth prepass and the opaque pass with the costly test material (`cost` noise octaves per
/// pixel). The benchmark stacks overdraw with it (bench/fxbench, scenario "overdraw").
/// Default: none.
struct CameraQuads {
    std::vector<CameraQuad> quads;
    int cost = 16;
    bool empty() const { return quads.empty(); }
};

class SceneRenderer : gl::NonCopyable {
public:
    ~SceneRenderer();

    /// Uploads the scene's meshes and builds every program. False + error (shader file:line ...).
    /// `reversedZ` asks for reversed-Z (clip z in [0, 1], near = 1, cleared to 0, GREATER); it
    /// is granted where the context has clip control, else the scene uses GL's default depth.
    bool init(const SceneData& data, std::string* error, bool reversedZ = false);
    /// The depth convention every pass of this renderer uses (see init): views build their
    /// projection, clear value and z-buffer format (32-bit float when reversed) to match.
    bool reversedZ() const { return reversedZ_; }

    /// The light every later opaque, alpha-tested and sky pass shades with (no GL until then).
    /// Default: SunLight{} (today's sun).
    void setSun(const SunLight& sun) { sun_ = sun; }
    /// The smoke's opacity map for this frame's opaque pass (fx::SmokeShadow: `texture` its GL
    /// name, `worldToSmoke` its matrix), darkening the sun's light on the ground under the cloud
    /// by exp(-absorption x alpha). `texture` 0 = no smoke shadow.
    void setSmokeShadow(uint32_t texture, const glm::mat4& worldToSmoke, float absorption = 1.0f) {
        smokeTexture_ = texture;
        worldToSmoke_ = worldToSmoke;
        smokeAbsorption_ = texture ? absorption : 0.0f;
    }
    const SunLight& sun() const { return sun_; }
    /// The fog the opaque, alpha-tested, sky and legacy-sprite passes apply; the views hand the
    /// same fog to the plugin. Default: off. Before init(): the programs are built with fog in
    /// them only when it is on (off costs nothing); its parameters may change afterwards, not
    /// whether it is on.
    void setFog(const SceneFog& fog) { fog_ = fog; }
    const SceneFog& fog() const { return fog_; }

    /// The mesh table (records MeshDraws for the game side; no GL).
    const GpuScene& meshes() const { return gpu_; }

    /// [depth prepass] linear view depth (R32F, cleared by the caller) + z-buffer, LESS (GREATER
    /// reversed).
    void depthPrepass(const std::vector<MeshDraw>& opaque, const std::vector<MeshDraw>& alphaTested,
                      const CameraMatrices& cam, const CameraQuads& quads) const;
    /// [opaque] LEQUAL (GEQUAL reversed) with depth writes, or EQUAL on the prepass z-buffer
    /// without them.
    void opaque(const std::vector<MeshDraw>& draws, const CameraMatrices& cam, bool equal,
                const CameraQuads& quads) const;
    /// [alpha-tested] as opaque, culling as in the prepass.
    void alphaTested(const std::vector<MeshDraw>& draws, const CameraMatrices& cam, bool equal) const;
    /// [sky] a full-screen triangle at the far plane where nothing was drawn.
    void sky(const CameraMatrices& cam) const;
    /// [legacy smoke] CPU-aligned sprites, depth-tested without writes.
    void sprites(const std::vector<cubeParticleSystem::SpriteVertex>& vertices, const glm::mat4& viewProj,
                 const glm::vec3& tint);
    /// [HUD] `texture` (another view's colour) inset at the top centre of a w x h target, with a
    /// dark 3-pixel frame, mirrored horizontally when `flipX`.
    void inset(uint32_t texture, int insetWidth, int insetHeight, bool flipX, int w, int h) const;
    /// [HUD] one line of text on a dark panel.
    void text(const std::string& text, int w, int h);

private:
    void drawCameraQuads(const gl::Program& p, const CameraQuads& quads, const CameraMatrices& cam) const;

    void useLitProgram(const gl::Program& p, const CameraMatrices& cam) const;

    GpuScene gpu_;
    SunLight sun_;
    SceneFog fog_;
    uint32_t smokeTexture_ = 0;
    glm::mat4 worldToSmoke_{1.0f};
    float smokeAbsorption_ = 0.0f;
    gl::Program meshProgram_, prepassProgram_, skyProgram_, blitProgram_, costlyProgram_;
    GLuint panelVao_ = 0, panelVbo_ = 0;  // one unit quad (z = 0, normal +Z) for the camera quads
    GLuint emptyVao_ = 0;                 // for gl_VertexID full-screen triangles
    LegacySpriteRenderer legacySprites_;
    Hud hud_;
    bool reversedZ_ = false;
};

}  // namespace cube
