#include "render/FillRateProbe.h"

#include <chrono>

#include "render/ScopedGlState.h"
#include "rtt/Clear.h"
#include "rtt/RenderTargetPool.h"
#include "rtt/ScopedTargetBinding.h"

namespace cube {

FillRateProbe::~FillRateProbe() {
    if (texture_) glDeleteTextures(1, &texture_);
    gl::deleteVertexArray(vao_, vbo_);
}

bool FillRateProbe::init(std::string* error) {
    if (!gl::Program::load("vs_fill_probe.glsl", "fs_fill_probe.glsl", &program_, error)) return false;
    ScopedGlState guard;
    std::vector<uint8_t> texels(64 * 64 * 4);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            uint8_t* t = &texels[size_t(y * 64 + x) * 4];
            t[0] = t[1] = t[2] = uint8_t(200 + ((x ^ y) & 31));
            t[3] = uint8_t(96 + ((x * y) & 63));
        }
    glGenTextures(1, &texture_);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    gl::createVec2VertexArray(&vao_, &vbo_);
    return true;
}

std::vector<double> FillRateProbe::drawTimesMs(rtt::RenderTargetPool& pool, const std::vector<uint8_t>& mask,
                                               int w, int h, int repeats) {
    std::vector<double> ms;
    if (!program_.valid() || mask.size() != size_t(w) * size_t(h)) return ms;
    vertices_.clear();
    for (int row = 0; row < h; ++row) {
        const float y0 = float(h - 1 - row), y1 = y0 + 1.0f;  // GL rows count from the bottom
        const uint8_t* m = &mask[size_t(row) * size_t(w)];
        for (int x = 0; x < w;) {
            if (!m[x]) {
                ++x;
                continue;
            }
            const int start = x;
            while (x < w && m[x]) ++x;
            const float x0 = float(start), x1 = float(x);
            const float quad[12] = {x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1};
            vertices_.insert(vertices_.end(), quad, quad + 12);
        }
    }
    if (vertices_.empty()) return ms;

    rtt::RenderTargetDesc desc;
    desc.width = w;
    desc.height = h;
    desc.name = "fxbench.fill_limit";
    const rtt::RenderTargetHandle target = pool.acquire(desc);
    if (!target.valid()) return ms;
    {
        rtt::ScopedTargetBinding bind(pool, target);
        ScopedGlState guard;
        glBindVertexArray(vao_);
        glBindBuffer(GL_ARRAY_BUFFER, vbo_);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices_.size() * sizeof(float)), vertices_.data(), GL_STREAM_DRAW);
        glUseProgram(program_.id());
        glUniform2f(program_.uniform("uViewSize"), float(w), float(h));
        glUniform1i(program_.uniform("uTex"), 0);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, texture_);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glDisable(GL_SCISSOR_TEST);
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        glBlendEquation(GL_FUNC_ADD);
        const GLsizei count = GLsizei(vertices_.size() / 2);
        for (int i = -1; i < repeats; ++i) {  // i = -1: untimed (shader variant compile, upload)
            rtt::ClearValues cv;
            cv.color[0] = {0.2f, 0.3f, 0.4f, 1.0f};
            rtt::clear(pool, target, cv);
            glFinish();
            const auto t0 = std::chrono::steady_clock::now();
            glDrawArrays(GL_TRIANGLES, 0, count);
            glFinish();
            const double t = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            if (i >= 0) ms.push_back(t);
        }
    }
    pool.release(target);
    return ms;
}

}  // namespace cube
