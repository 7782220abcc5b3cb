#include "render/Hud.h"

#include <stb_easy_font.h>

namespace cube {

Hud::~Hud() {
    gl::deleteVertexArray(vao_, vbo_);
}

bool Hud::init(std::string* error) {
    if (!gl::Program::load("vs_hud.glsl", "fs_hud.glsl", &program_, error)) return false;
    gl::createVec2VertexArray(&vao_, &vbo_);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    return true;
}

void Hud::draw(int viewportWidth, int viewportHeight) {
    if (text_.empty() || !program_.valid() || viewportWidth < 64 || viewportHeight < 32) return;
    // stb_easy_font writes quads of {x, y, z, rgba8}; 270 bytes per character is its stated bound.
    static char quads[64 * 1024];
    std::string text = text_.substr(0, 200);
    const float scale = viewportHeight >= 600 ? 2.0f : 1.0f;
    const int numQuads = stb_easy_font_print(0.0f, 0.0f, text.data(), nullptr, quads, sizeof quads);
    const float textW = float(stb_easy_font_width(text.data())) * scale;
    triangles_.clear();
    auto quad = [&](float x0, float y0, float x1, float y1) {
        triangles_.insert(triangles_.end(), {x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1});
    };
    const float ox = 10.0f, oy = 10.0f, pad = 6.0f;
    quad(ox - pad, oy - pad, ox + textW + pad, oy + 12.0f * scale + pad);  // panel first
    const size_t panelFloats = triangles_.size();
    for (int q = 0; q < numQuads; ++q) {
        const float* v = reinterpret_cast<const float*>(quads + q * 4 * 16);
        quad(ox + v[0] * scale, oy + v[1] * scale, ox + v[8] * scale, oy + v[9] * scale);
    }
    glUseProgram(program_.id());
    glUniform2f(program_.uniform("uViewport"), float(viewportWidth), float(viewportHeight));
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(triangles_.size() * sizeof(float)), triangles_.data(),
                 GL_STREAM_DRAW);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUniform4f(program_.uniform("uColor"), 0.0f, 0.0f, 0.0f, 0.55f);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(panelFloats / 2));
    glUniform4f(program_.uniform("uColor"), 1.0f, 1.0f, 1.0f, 1.0f);
    glDrawArrays(GL_TRIANGLES, GLsizei(panelFloats / 2), GLsizei((triangles_.size() - panelFloats) / 2));
    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glUseProgram(0);
}

}  // namespace cube
