#pragma once
// GLSL programs loaded from shaders/ (vs_*.glsl / fs_*.glsl) through the project's one source
// loader (textio/ShaderSource.h: `#include "file"` from the same folder, `#line`
// markers that carry the file). Compile and link errors are reported as "file:line: message"
// with the original file and line, not the concatenated source's.
#include <string>
#include <vector>

#include "gl/Gl.h"

namespace cube::gl {

/// An owned GL program. A program that failed to build has id 0 and draws nothing.
class Program {
public:
    Program() = default;
    ~Program();
    Program(Program&& other) noexcept;
    Program& operator=(Program&& other) noexcept;
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    /// Builds vs + fs from `dir` (default: paths::shaders()). `defines` is inserted after #version.
    static bool load(const std::string& vsFile, const std::string& fsFile, Program* out,
                     std::string* error, const std::string& defines = "",
                     const std::string& dir = "");

    GLuint id() const { return id_; }
    bool valid() const { return id_ != 0; }
    /// Uniform location (-1 when the uniform is absent or optimised out).
    GLint uniform(const char* name) const;

private:
    GLuint id_ = 0;
};

}  // namespace cube::gl
