#include "gl/Program.h"

#include "gl/Paths.h"
#include "textio/ShaderSource.h"

namespace cube::gl {

namespace {

// The info log of a shader (glGetShaderiv, glGetShaderInfoLog) or a program (glGetProgramiv,
// glGetProgramInfoLog), up to its first NUL.
template <class GetIv, class GetLog>
std::string infoLog(GLuint object, GetIv getIv, GetLog getLog) {
    GLint len = 0;
    getIv(object, GL_INFO_LOG_LENGTH, &len);
    std::string log(size_t(len > 0 ? len : 1), '\0');
    getLog(object, len, nullptr, log.data());
    return log.c_str();
}

GLuint compile(GLenum stage, const std::string& file, const textio::ShaderSource& source, std::string* error) {
    GLuint s = glCreateShader(stage);
    const char* src = source.text.c_str();
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        *error = textio::translateInfoLog(infoLog(s, glGetShaderiv, glGetShaderInfoLog), source.files, file);
        if (error->empty()) *error = file + ":0: compile failed (the driver gave no log)";
        glDeleteShader(s);
        return 0;
    }
    return s;
}

}  // namespace

Program::~Program() {
    if (id_) glDeleteProgram(id_);
}
Program::Program(Program&& other) noexcept : id_(other.id_) { other.id_ = 0; }
Program& Program::operator=(Program&& other) noexcept {
    if (this != &other) {
        if (id_) glDeleteProgram(id_);
        id_ = other.id_;
        other.id_ = 0;
    }
    return *this;
}

bool Program::load(const std::string& vsFile, const std::string& fsFile, Program* out,
                   std::string* error, const std::string& defines, const std::string& dirIn) {
    const std::string dir = dirIn.empty() ? paths::shaders() : dirIn;
    // The project's one source loader (includes, #line, named errors); GL through the engine's glad.
    const textio::ShaderReader read = textio::folderShaderReader(dir);
    const std::string extra = defines.empty() ? std::string() : defines + "\n";
    textio::ShaderSource vsSrc, fsSrc;
    const auto implied = textio::VersionLine::Implied;  // the engine's files start without #version
    if (textio::expandShaderSource(read, vsFile, extra, &vsSrc, error, implied) != textio::ShaderError::None)
        return false;
    if (textio::expandShaderSource(read, fsFile, extra, &fsSrc, error, implied) != textio::ShaderError::None)
        return false;
    GLuint vs = compile(GL_VERTEX_SHADER, vsFile, vsSrc, error);
    if (!vs) return false;
    GLuint fs = compile(GL_FRAGMENT_SHADER, fsFile, fsSrc, error);
    if (!fs) {
        glDeleteShader(vs);
        return false;
    }
    GLuint prog = glCreateProgram();
    glAttachShader(prog, vs);
    glAttachShader(prog, fs);
    glLinkProgram(prog);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        *error = vsFile + " + " + fsFile + ": link failed: " + infoLog(prog, glGetProgramiv, glGetProgramInfoLog);
        glDeleteProgram(prog);
        return false;
    }
    Program p;
    p.id_ = prog;
    *out = std::move(p);
    return true;
}

GLint Program::uniform(const char* name) const {
    return id_ ? glGetUniformLocation(id_, name) : -1;
}

}  // namespace cube::gl
