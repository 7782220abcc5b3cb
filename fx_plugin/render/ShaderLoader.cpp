#include "ShaderLoader.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>

#include "render/EmbeddedResources.h"
#include "render/PrivateGl.h"

namespace fx {

// `dir` empty: the copies embedded in the library; else the folder `dir` (live edits).
ShaderReader shaderReader(const std::string& dir) {
    if (!dir.empty()) return folderShaderReader(dir);
    return [](const std::string& name, std::string* text, std::string* why) {
        const embedded::Resource* r = embedded::find(name.c_str());
        if (!r) {
            *why = "no shader \"" + name + "\" is embedded in the plugin";
            return false;
        }
        text->assign(reinterpret_cast<const char*>(r->data), r->size);
        return true;
    };
}

namespace {

// A shader's (or, with `program`, a program's) info log, up to its first terminating zero.
std::string infoLog(GLuint object, bool program) {
    GLint length = 0;
    if (program) {
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    } else {
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    }
    std::string log(static_cast<size_t>(length > 1 ? length : 1), '\0');
    if (program) {
        glGetProgramInfoLog(object, length, nullptr, &log[0]);
    } else {
        glGetShaderInfoLog(object, length, nullptr, &log[0]);
    }
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log;
}

GLuint compileStage(GLenum stage, const ShaderReader& read, const std::string& file,
                    const std::string& defines, std::string* error) {
    ShaderSource src;
    if (expandShaderSource(read, file, defines, &src, error) != ShaderError::None) return 0;
    const GLuint shader = glCreateShader(stage);
    const char* text = src.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        *error = translateInfoLog(infoLog(shader, false), src.files, file);
        if (error->empty()) *error = file + ":0: compile failed (the driver gave no log)";
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

}  // namespace

bool loadShaderSource(const std::string& dir, const std::string& name, const std::string& defines,
                      ShaderSource* out, std::string* error) {
    return expandShaderSource(shaderReader(dir), name, defines, out, error) == ShaderError::None;
}

ShaderReader snapshotShaderReader(ShaderReader read) {
    auto files = std::make_shared<std::map<std::string, std::string>>();
    return [read = std::move(read), files](const std::string& name, std::string* text, std::string* why) {
        const auto it = files->find(name);
        if (it != files->end()) {
            *text = it->second;
            return true;
        }
        if (!read(name, text, why)) return false;  // not kept: a missing file is asked for again
        (*files)[name] = *text;
        return true;
    };
}

void addShaderDiagnostics(const std::string& text, Diagnostics* out) {
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(start, end - start);
        start = end + 1;
        if (line.empty()) continue;
        Diagnostic d;
        d.code = ErrorCode::ShaderBuild;
        d.message = line;
        const size_t c1 = line.find(':');
        const size_t c2 = c1 == std::string::npos ? c1 : line.find(':', c1 + 1);
        if (c2 != std::string::npos && c2 > c1 + 1 && line.find_first_not_of("0123456789", c1 + 1) == c2) {
            d.file = line.substr(0, c1);
            d.line = std::atoi(line.c_str() + c1 + 1);
            const size_t text0 = line.find_first_not_of(' ', c2 + 1);
            d.message = line.substr(text0 == std::string::npos ? line.size() : text0);
        }
        out->push_back(d);
    }
}

std::string ShaderErrorLog::add(const std::string& error) {
    std::string fresh;
    size_t start = 0;
    while (start < error.size()) {
        size_t end = error.find('\n', start);
        if (end == std::string::npos) end = error.size();
        std::string line = error.substr(start, end - start);
        start = end + 1;
        if (line.empty() || std::find(lines_.begin(), lines_.end(), line) != lines_.end()) continue;
        fresh += (fresh.empty() ? "" : "\n") + line;
        lines_.push_back(std::move(line));
    }
    return fresh;
}

std::string ShaderErrorLog::text() const {
    std::string all;
    for (const std::string& l : lines_) all += (all.empty() ? "" : "\n") + l;
    return all;
}

namespace {
ProgramBuildCounts gCounts;
int gFrameDepth = 0, gPassDepth = 0;
}  // namespace

ProgramBuildCounts programBuildCounts() { return gCounts; }

FrameScope::FrameScope(Kind kind) : kind_(kind) {
    ++gFrameDepth;
    if (kind_ == Pass) ++gPassDepth;
}
FrameScope::~FrameScope() {
    --gFrameDepth;
    if (kind_ == Pass) --gPassDepth;
}

uint32_t buildProgram(const std::string& dir, const std::string& vertexFile,
                      const std::string& fragmentFile, const std::string& defines,
                      std::string* error) {
    return buildProgram(shaderReader(dir), vertexFile, fragmentFile, defines, error);
}

uint32_t buildProgram(const ShaderReader& read, const std::string& vertexFile,
                      const std::string& fragmentFile, const std::string& defines,
                      std::string* error) {
    ++gCounts.built;  // tried: a failing build costs the compile as well
    if (gFrameDepth > 0) ++gCounts.inFrame;
    if (gPassDepth > 0) ++gCounts.inPass;
    if (fragmentFile.empty()) {
        // A compute program (ARB_compute_shader: the caller checked the context has it).
        const GLuint cs = compileStage(GL_COMPUTE_SHADER, read, vertexFile, defines, error);
        if (!cs) return 0;
        const GLuint program = glCreateProgram();
        glAttachShader(program, cs);
        glLinkProgram(program);
        glDetachShader(program, cs);
        glDeleteShader(cs);
        GLint ok = GL_FALSE;
        glGetProgramiv(program, GL_LINK_STATUS, &ok);
        if (ok != GL_TRUE) {
            *error = vertexFile + ":0: link failed: " + infoLog(program, true);
            glDeleteProgram(program);
            return 0;
        }
        return program;
    }
    const GLuint vs = compileStage(GL_VERTEX_SHADER, read, vertexFile, defines, error);
    if (!vs) return 0;
    const GLuint fs = compileStage(GL_FRAGMENT_SHADER, read, fragmentFile, defines, error);
    if (!fs) {
        glDeleteShader(vs);
        return 0;
    }
    const GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDetachShader(program, vs);
    glDetachShader(program, fs);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        *error = vertexFile + "+" + fragmentFile + ":0: link failed: " + infoLog(program, true);
        glDeleteProgram(program);
        return 0;
    }
    return program;
}

uint64_t shaderStamp(const std::string& shaderDir) {
    uint64_t h = 1469598103934665603ull;
    auto mix = [&](uint64_t v) {
        h ^= v;
        h *= 1099511628211ull;
    };
    std::error_code ec;
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(shaderDir, ec)) {
        const std::string name = e.path().filename().string();
        const bool ours = name.find("particles") != std::string::npos || name.find("mega") != std::string::npos;
        if (ours && e.path().extension() == ".glsl") files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
        for (char c : f.filename().string()) mix(uint64_t(uint8_t(c)));
        mix(uint64_t(std::filesystem::file_size(f, ec)));
        mix(uint64_t(std::filesystem::last_write_time(f, ec).time_since_epoch().count()));
        mix(uint64_t(std::filesystem::status(f, ec).type()));  // a FIFO put in a file's place
    }
    return h;
}

}  // namespace fx
