#pragma once
// Draws the tweak panel's Dear ImGui draw lists with the engine's own GL layer (glad, loaded
// through the platform's getProcAddress). Not ImGui's packaged OpenGL 3 back end: that one
// carries its own loader (imgui_impl_opengl3_loader.h), which dlopens libGL and asks GLX for
// entry points, so it finds nothing in an OSMesa or EGL context, and the panel must render
// headless too (tests, screenshots). One renderer for every back end keeps the pixels equal.
//
// State: draw() changes program, vertex array, GL_ARRAY_BUFFER, texture unit 0's 2D texture
// and sampler, blend (enable, separate functions and equations), depth test, face culling and
// the scissor test and box, and puts every one of them back as it found it. It draws into
// whatever framebuffer and viewport are bound.
#include <string>

#include "gl/Gl.h"
#include "gl/Program.h"

struct ImDrawData;

namespace cube {

class PanelRenderer : gl::NonCopyable {
public:
    ~PanelRenderer();

    /// Builds the program and uploads the font atlas of the current ImGui context (an R8
    /// texture: the atlas's coverage). False + "file:line: message" when the shaders do not build.
    bool init(std::string* error);
    bool ready() const { return program_.valid() && font_ != 0; }
    /// Draws `data` into the bound framebuffer, sized `width` x `height` pixels. Draws nothing
    /// before a successful init().
    void draw(const ImDrawData& data, int width, int height);

private:
    gl::Program program_;
    GLuint vao_ = 0, vbo_ = 0, ebo_ = 0, font_ = 0;
    GLint viewportLoc_ = -1, atlasLoc_ = -1;
};

}  // namespace cube
