#include "ShaderLoader.h"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "io/SafeFile.h"
#include "render/EmbeddedResources.h"
#include "render/PrivateGl.h"

namespace fx {
namespace {

// `dir` empty: the copy embedded in the library; else the file `dir`/`name` (live edits).
bool readShader(const std::string& dir, const std::string& name, std::string* out) {
    if (dir.empty()) {
        const embedded::Resource* r = embedded::find(name.c_str());
        if (!r) return false;
        out->assign(reinterpret_cast<const char*>(r->data), r->size);
        return true;
    }
    // Never blocks on a FIFO, reads regular files only, at most 1 MiB (a shader is a few KiB).
    return fxio::readFileBounded(dir + "/" + name, size_t(1) << 20, out, nullptr, nullptr);
}

// Line numbers carry the file: file k's line n is reported as k * kFileLineStride + n. Source-string
// numbers alone are not reliable (Mesa 22 reports some errors inside an include with source 0).
constexpr int kFileLineStride = 10000;

std::string lineDirective(int line, int file) {
    return "#line " + std::to_string(file * kFileLineStride + line) + " " + std::to_string(file) + "\n";
}

bool startsWithDirective(const std::string& line, const char* directive, size_t* at) {
    const size_t p = line.find_first_not_of(" \t");
    if (p == std::string::npos) return false;
    const std::string d(directive);
    if (line.compare(p, d.size(), d) != 0) return false;
    *at = p + d.size();
    return true;
}

struct Expander {
    const std::string& dir;
    std::string* out;
    std::vector<std::string>* files;
    std::set<std::string> seen;
    bool sawVersion = false;

    // `where` is "file:line" of the #include that asked for `name` (empty for the top file).
    bool expand(const std::string& name, int depth, const std::string& where, std::string* error) {
        const std::string prefix = where.empty() ? name : where;
        if (depth > kMaxIncludeDepth) {
            *error = prefix + ": #include nested deeper than " + std::to_string(kMaxIncludeDepth) +
                     " levels at \"" + name + "\"";
            return false;
        }
        if (!seen.insert(name).second) return true;
        std::string text;
        if (!readShader(dir, name, &text)) {
            *error = prefix + (dir.empty() ? ": no shader \"" + name + "\" is embedded in the plugin"
                                           : ": cannot open shader file \"" + dir + "/" + name + "\"");
            return false;
        }
        const int index = static_cast<int>(files->size());
        files->push_back(name);
        std::istringstream lines(text);
        std::string line;
        int lineNo = 0;
        bool marked = false;
        while (std::getline(lines, line)) {
            ++lineNo;
            if (lineNo >= kFileLineStride) {
                *error = name + ":" + std::to_string(lineNo) + ": shader file longer than " +
                         std::to_string(kFileLineStride - 1) + " lines";
                return false;
            }
            if (!line.empty() && line.back() == '\r') line.pop_back();
            size_t at = 0;
            if (startsWithDirective(line, "#version", &at)) {
                // Emitted once by the caller, ahead of the defines.
                if (depth == 0) sawVersion = true;
                continue;
            }
            if (!marked) {
                *out += lineDirective(lineNo, index);
                marked = true;
            }
            if (startsWithDirective(line, "#include", &at)) {
                const size_t a = line.find('"', at);
                const size_t b = a == std::string::npos ? a : line.find('"', a + 1);
                const std::string here = name + ":" + std::to_string(lineNo);
                if (b == std::string::npos || b == a + 1) {
                    *error = here + ": malformed #include, expected #include \"file\"";
                    return false;
                }
                if (!expand(line.substr(a + 1, b - a - 1), depth + 1, here, error)) return false;
                *out += lineDirective(lineNo + 1, index);
                continue;
            }
            *out += line;
            *out += '\n';
        }
        return true;
    }
};

// Parses the location at the start of one info-log line; returns the rest (the message).
bool parseLocation(const std::string& line, int* file, int* lineNo, std::string* message) {
    size_t p = 0;
    if (line.compare(0, 6, "ERROR:") == 0 || line.compare(0, 8, "WARNING:") == 0) {
        p = line.find(':') + 1;
        while (p < line.size() && line[p] == ' ') ++p;
    }
    auto number = [&](int* v) {
        const size_t s = p;
        while (p < line.size() && std::isdigit(static_cast<unsigned char>(line[p]))) ++p;
        if (p == s) return false;
        *v = std::atoi(line.c_str() + s);
        return true;
    };
    if (!number(file) || p >= line.size()) return false;
    if (line[p] == ':') {  // Mesa "0:12(5):", AMD "0:12:"
        ++p;
        if (!number(lineNo)) return false;
        if (p < line.size() && line[p] == '(') {
            const size_t close = line.find(')', p);
            if (close == std::string::npos) return false;
            p = close + 1;
        }
    } else if (line[p] == '(') {  // NVIDIA "0(12) :"
        ++p;
        if (!number(lineNo) || p >= line.size() || line[p] != ')') return false;
        ++p;
    } else {
        return false;
    }
    while (p < line.size() && (line[p] == ' ' || line[p] == ':')) ++p;
    *message = line.substr(p);
    return true;
}

GLuint compileStage(GLenum stage, const std::string& dir, const std::string& file,
                    const std::string& defines, std::string* error) {
    ShaderSource src;
    if (!loadShaderSource(dir, file, defines, &src, error)) return 0;
    const GLuint shader = glCreateShader(stage);
    const char* text = src.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<size_t>(length > 1 ? length : 1), '\0');
        glGetShaderInfoLog(shader, length, nullptr, &log[0]);
        log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
        *error = translateInfoLog(log, src.files, file);
        if (error->empty()) *error = file + ":0: compile failed (the driver gave no log)";
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

}  // namespace

bool loadShaderSource(const std::string& dir, const std::string& name, const std::string& defines,
                      ShaderSource* out, std::string* error) {
    std::string body;
    out->files.clear();
    Expander expander{dir, &body, &out->files, {}, false};
    if (!expander.expand(name, 0, std::string(), error)) return false;
    if (!expander.sawVersion) {
        *error = name + ":1: missing #version (expected \"#version 330 core\" on the first line)";
        return false;
    }
    out->text = "#version 330 core\n" + defines + body;
    return true;
}

std::string translateInfoLog(const std::string& log, const std::vector<std::string>& files,
                             const std::string& fallbackFile) {
    std::istringstream lines(log);
    std::string line, result;
    while (std::getline(lines, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        int file = 0, lineNo = 0;
        std::string message;
        const bool parsed = parseLocation(line, &file, &lineNo, &message);
        if (parsed && lineNo >= kFileLineStride) {
            file = lineNo / kFileLineStride;
            lineNo %= kFileLineStride;
        }
        if (parsed && file >= 0 && file < static_cast<int>(files.size())) {
            result += files[static_cast<size_t>(file)] + ":" + std::to_string(lineNo) + ": " + message;
        } else {
            result += fallbackFile + ":0: " + line;
        }
        result += '\n';
    }
    if (!result.empty()) result.pop_back();
    return result;
}

uint32_t buildProgram(const std::string& dir, const std::string& vertexFile,
                      const std::string& fragmentFile, const std::string& defines,
                      std::string* error) {
    const GLuint vs = compileStage(GL_VERTEX_SHADER, dir, vertexFile, defines, error);
    if (!vs) return 0;
    const GLuint fs = compileStage(GL_FRAGMENT_SHADER, dir, fragmentFile, defines, error);
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
        GLint length = 0;
        glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<size_t>(length > 1 ? length : 1), '\0');
        glGetProgramInfoLog(program, length, nullptr, &log[0]);
        log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
        *error = vertexFile + "+" + fragmentFile + ":0: link failed: " + log;
        glDeleteProgram(program);
        return 0;
    }
    return program;
}

}  // namespace fx
