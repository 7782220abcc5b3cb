// The fx_host's world (flat-coloured quads with the host's own two small shaders), its scripted
// car (fx::HostAdapter) and the one-frame driver.
#include <glad/gl.h>

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "FxTestHost.h"

namespace fxtest {

namespace {

const char* kSceneVs = R"(#version 330 core
layout(location = 0) in vec3 aPos;
uniform mat4 uView;
uniform mat4 uProj;
out float vDepth;
void main() {
    vec4 v = uView * vec4(aPos, 1.0);
    vDepth = -v.z;
    gl_Position = uProj * v;
}
)";
const char* kColourFs = R"(#version 330 core
uniform vec3 uColour;
out vec4 oColour;
void main() { oColour = vec4(uColour, 1.0); }
)";
const char* kDepthFs = R"(#version 330 core
in float vDepth;
out vec4 oDepth;
void main() { oDepth = vec4(vDepth); }
)";

struct SceneGl {
    GLuint colour = 0, depth = 0, vao = 0, vbo = 0;
};

SceneGl& sceneGl() {
    static SceneGl g;
    if (!g.colour) {
        g.colour = compileTestProgram(kSceneVs, kColourFs);
        g.depth = compileTestProgram(kSceneVs, kDepthFs);
        glGenVertexArrays(1, &g.vao);
        glGenBuffers(1, &g.vbo);
        glBindVertexArray(g.vao);
        glBindBuffer(GL_ARRAY_BUFFER, g.vbo);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
        glBindVertexArray(0);
    }
    return g;
}

// The state every host pass starts from (a previous plugin test may have left anything).
void hostPassState() {
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
}

void drawQuads(GLuint program, const std::vector<SceneQuad>& quads, const fx::ViewInfo& view,
               bool colour) {
    SceneGl& g = sceneGl();
    std::vector<glm::vec3> verts;
    for (const SceneQuad& q : quads) {
        const glm::vec3 a = q.origin, b = q.origin + q.edgeU, c = q.origin + q.edgeU + q.edgeV,
                        d = q.origin + q.edgeV;
        verts.insert(verts.end(), {a, b, c, a, c, d});
    }
    glUseProgram(program);
    glUniformMatrix4fv(glGetUniformLocation(program, "uView"), 1, GL_FALSE, &view.view[0][0]);
    glUniformMatrix4fv(glGetUniformLocation(program, "uProj"), 1, GL_FALSE, &view.proj[0][0]);
    glBindVertexArray(g.vao);
    glBindBuffer(GL_ARRAY_BUFFER, g.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(verts.size() * sizeof(glm::vec3)), verts.data(),
                 GL_STREAM_DRAW);
    const GLint colourLoc = glGetUniformLocation(program, "uColour");
    for (size_t i = 0; i < quads.size(); ++i) {
        if (colour) glUniform3fv(colourLoc, 1, &quads[i].colour[0]);
        glDrawArrays(GL_TRIANGLES, GLint(i * 6), 6);
    }
    glBindVertexArray(0);
    glUseProgram(0);
}

// glClipControl is GL 4.5 (the tests' glad is 3.3 core): fetched by hand where it is used.
void clipControl(bool zeroToOne) {
    using ClipControlFn = void (*)(GLenum, GLenum);
    static const auto fn = reinterpret_cast<ClipControlFn>(osMesaProcAddress()("glClipControl"));
    constexpr GLenum kLowerLeft = 0x8CA1, kNegativeOneToOne = 0x935E, kZeroToOne = 0x935F;
    if (fn) fn(kLowerLeft, zeroToOne ? kZeroToOne : kNegativeOneToOne);
}

// The "opaque" pass's body, into the bound framebuffer.
void drawOpaqueScene(const std::vector<SceneQuad>& q, const fx::ViewInfo& view, glm::vec3 skyColour, bool reversed,
                     bool zeroToOne) {
    hostPassState();
    glClearColor(skyColour.r, skyColour.g, skyColour.b, 1.0f);
    glClearDepth(reversed ? 0.0 : 1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    clipControl(zeroToOne);
    if (reversed) glDepthFunc(GL_GEQUAL);
    drawQuads(sceneGl().colour, q, view, true);
    // The particle passes run with the host's clip control still set (as in a real
    // reversed-Z engine); the graph's executor resets it after the frame.
    if (reversed) glDepthFunc(GL_LESS);
}

}  // namespace

void TestScene::declareHostPasses(TestFrameGraph& graph, const fx::ViewInfo& view) {
    const std::vector<SceneQuad> q = quads;
    const glm::vec3 skyColour = sky;
    const float background = depthBackground < 0.0f ? view.farPlane : depthBackground;
    const bool reversed = reversedZ;
    graph.addPass("prepass", {}, {graph.sceneDepth()}, [q, view, background, reversed](fx::PassContext& ctx) {
        ctx.bindForDraw(fx::Target{TestFrameGraph::kSceneDepth});
        hostPassState();
        glClearColor(background, background, background, background);  // sky: nothing drawn
        glClearDepth(reversed ? 0.0 : 1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        clipControl(reversed);
        if (reversed) glDepthFunc(GL_GEQUAL);
        drawQuads(sceneGl().depth, q, view, false);
        clipControl(false);
        glDepthFunc(GL_LESS);
    });
    graph.addPass("opaque", {}, {graph.sceneColor()}, [q, view, skyColour, reversed](fx::PassContext& ctx) {
        ctx.bindForDraw(fx::Target{TestFrameGraph::kSceneColor});
        drawOpaqueScene(q, view, skyColour, reversed, reversed);
    });
}

void TestScene::drawOpaque(const fx::ViewInfo& view) const {
    glViewport(0, 0, view.width, view.height);
    drawOpaqueScene(quads, view, sky, reversedZ, reversedZ || clipZeroToOne);
}

void useReversedZ(fx::ViewInfo* view) {
    // glm's zero-to-one projection with near and far swapped maps near to 1 and far to 0.
    const float fovY = 2.0f * std::atan(1.0f / view->proj[1][1]);
    const float aspect = view->proj[1][1] / view->proj[0][0];
    view->proj = glm::perspectiveRH_ZO(fovY, aspect, view->farPlane, view->nearPlane);
    view->depth = fx::DepthConvention::ReversedZ;
}



SceneQuad TestScene::ground(float halfExtent, glm::vec3 colour, float y) {
    SceneQuad q;
    q.origin = glm::vec3(-halfExtent, y, halfExtent);
    q.edgeU = glm::vec3(2.0f * halfExtent, 0.0f, 0.0f);
    q.edgeV = glm::vec3(0.0f, 0.0f, -2.0f * halfExtent);
    q.colour = colour;
    return q;
}

SceneQuad TestScene::wallZ(float z, float x0, float x1, float y0, float y1, glm::vec3 colour) {
    SceneQuad q;
    q.origin = glm::vec3(x0, y0, z);
    q.edgeU = glm::vec3(x1 - x0, 0.0f, 0.0f);
    q.edgeV = glm::vec3(0.0f, y1 - y0, 0.0f);
    q.colour = colour;
    return q;
}

fx::ViewInfo makeView(glm::vec3 eye, glm::vec3 target, int width, int height, float nearPlane,
                      float farPlane) {
    fx::ViewInfo v;
    v.name = "fx_host";
    v.eye = eye;
    v.view = glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f));
    v.proj = glm::perspective(glm::radians(60.0f), float(width) / float(height), nearPlane, farPlane);
    v.nearPlane = nearPlane;
    v.farPlane = farPlane;
    v.width = width;
    v.height = height;
    return v;
}

glm::vec3 projectToPixel(const fx::ViewInfo& view, glm::vec3 world) {
    const glm::vec4 clip = view.proj * view.view * glm::vec4(world, 1.0f);
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return glm::vec3((ndc.x * 0.5f + 0.5f) * float(view.width),
                     (ndc.y * 0.5f + 0.5f) * float(view.height), ndc.z);
}

TestHostAdapter::TestHostAdapter() {
    // A car at the origin facing -z: front axle at z = -1.3, rear axle at z = +1.3.
    const float xs[4] = {-0.8f, 0.8f, -0.8f, 0.8f};
    const float zs[4] = {-1.3f, -1.3f, 1.3f, 1.3f};
    for (int i = 0; i < 4; ++i) {
        wheels_[i].position = glm::vec3(xs[i], 0.0f, zs[i]);
        wheels_[i].velocity = glm::vec3(0.0f);
        wheels_[i].surface = fx::Surface::Asphalt;
        wheels_[i].grounded = true;
        wheels_[i].rear = i >= 2;
        wheels_[i].slip = 0.0f;
    }
}

void TestHostAdapter::setRearSlip(float slip) {
    wheels_[2].slip = wheels_[3].slip = slip;
}

void TestHostAdapter::log(fx::LogLevel level, const char* message) {
    messages_.push_back(message ? message : "");
    if (level == fx::LogLevel::Error) errors_.push_back(messages_.back());
}

bool TestHostAdapter::logged(const std::string& fragment) const {
    for (const std::string& m : messages_) {
        if (m.find(fragment) != std::string::npos) return true;
    }
    return false;
}

void renderFrame(TestFrameGraph& graph, TestScene& scene, const fx::ViewInfo& view,
                 const std::function<void(fx::FrameBuilder&)>& declareParticles) {
    graph.beginFrame();
    scene.declareHostPasses(graph, view);
    if (declareParticles) {
        graph.beginPluginPasses();
        declareParticles(graph);
        graph.endPluginPasses();
    }
    graph.execute();
    clipControl(false);  // a reversed-Z scene leaves it set for the particle passes
}

}  // namespace fxtest
