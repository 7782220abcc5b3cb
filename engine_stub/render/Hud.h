#pragma once
// HUD bucket: a line of text (stb_easy_font) on a dark panel, in pixels from the top-left.
#include <string>
#include <vector>

#include "gl/Gl.h"
#include "gl/Program.h"

namespace cube {

class Hud {
public:
    ~Hud();
    bool init(std::string* error);
    /// Records the text; draw() uploads and draws it into the bound framebuffer.
    void setText(const std::string& text) { text_ = text; }
    void draw(int viewportWidth, int viewportHeight);

private:
    gl::Program program_;
    GLuint vao_ = 0, vbo_ = 0;
    std::string text_;
    std::vector<float> triangles_;
};

}  // namespace cube
