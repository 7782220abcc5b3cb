#include "ShaderLoader.h"

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
    return expandShaderSource(shaderReader(dir), name, defines, out, error) == ShaderError::None;
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
