#include "gl/Program.h"

#include <cctype>
#include <set>
#include <sstream>

#include "gl/Paths.h"
#include "io/SafeFile.h"

namespace cube::gl {

namespace {

// Shaders are small text files; the shared opener never blocks on a FIFO and refuses more.
constexpr size_t kMaxShaderBytes = 1u << 20;

bool readFile(const std::string& path, std::string* out, std::string* why) {
    return fxio::readFileBounded(path, kMaxShaderBytes, out, nullptr, why);
}

bool expand(const std::string& dir, const std::string& name, int depth, std::string* out,
            std::vector<std::string>* files, std::set<std::string>* seen, std::string* error,
            const std::string& includedFrom) {
    if (depth > 8) {
        *error = includedFrom + ": #include nested deeper than 8 levels at '" + name + "'";
        return false;
    }
    if (seen->count(name)) return true;  // each file once (include guard by name)
    seen->insert(name);
    std::string text, why;
    if (!readFile(dir + "/" + name, &text, &why)) {
        *error = (includedFrom.empty() ? std::string() : includedFrom + ": ") + "cannot open shader '" +
                 dir + "/" + name + "': " + why;
        return false;
    }
    const int fileIndex = int(files->size());
    files->push_back(name);
    std::istringstream lines(text);
    std::string line;
    int lineNo = 0;
    *out += "#line 1 " + std::to_string(fileIndex) + "\n";
    while (std::getline(lines, line)) {
        ++lineNo;
        size_t p = line.find_first_not_of(" \t");
        if (p != std::string::npos && line.compare(p, 8, "#include") == 0) {
            size_t a = line.find('"', p), b = a == std::string::npos ? a : line.find('"', a + 1);
            if (b == std::string::npos) {
                *error = name + ":" + std::to_string(lineNo) + ": malformed #include, expected \"file\"";
                return false;
            }
            if (!expand(dir, line.substr(a + 1, b - a - 1), depth + 1, out, files, seen, error,
                        name + ":" + std::to_string(lineNo)))
                return false;
            *out += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(fileIndex) + "\n";
            continue;
        }
        if (p != std::string::npos && line.compare(p, 8, "#version") == 0) {
            *out += "\n";  // the caller emits #version first
            continue;
        }
        *out += line + "\n";
    }
    return true;
}

GLuint compile(GLenum stage, const std::string& source, const std::vector<std::string>& files,
               std::string* error) {
    GLuint s = glCreateShader(stage);
    const char* src = source.c_str();
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
        std::string log(size_t(len > 0 ? len : 1), '\0');
        glGetShaderInfoLog(s, len, nullptr, log.data());
        *error = mapInfoLog(log.c_str(), files);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

}  // namespace

bool preprocessShader(const std::string& dir, const std::string& name, const std::string& defines,
                      std::string* source, std::vector<std::string>* files, std::string* error) {
    std::set<std::string> seen;
    std::string body;
    if (!expand(dir, name, 0, &body, files, &seen, error, "")) return false;
    *source = "#version 330 core\n" + defines + (defines.empty() ? "" : "\n") + body;
    return true;
}

std::string mapInfoLog(const std::string& log, const std::vector<std::string>& files) {
    std::istringstream in(log);
    std::string line, out;
    while (std::getline(in, line)) {
        // Mesa: "0:12(5): error: ..."   NVIDIA: "0(12) : error C0000: ..."
        size_t i = 0;
        while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) ++i;
        if (i > 0 && i < line.size() && (line[i] == ':' || line[i] == '(')) {
            int src = std::atoi(line.substr(0, i).c_str());
            size_t j = i + 1, k = j;
            while (k < line.size() && std::isdigit(static_cast<unsigned char>(line[k]))) ++k;
            if (k > j && src >= 0 && src < int(files.size())) {
                std::string rest = line.substr(k);
                size_t colon = rest.find(':');
                out += files[size_t(src)] + ":" + line.substr(j, k - j) + ":" +
                       (colon == std::string::npos ? rest : rest.substr(colon + 1)) + "\n";
                continue;
            }
        }
        if (!line.empty()) out += line + "\n";
    }
    return out;
}

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
    std::string vsSrc, fsSrc;
    std::vector<std::string> vsFiles, fsFiles;
    if (!preprocessShader(dir, vsFile, defines, &vsSrc, &vsFiles, error)) return false;
    if (!preprocessShader(dir, fsFile, defines, &fsSrc, &fsFiles, error)) return false;
    GLuint vs = compile(GL_VERTEX_SHADER, vsSrc, vsFiles, error);
    if (!vs) return false;
    GLuint fs = compile(GL_FRAGMENT_SHADER, fsSrc, fsFiles, error);
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
        GLint len = 0;
        glGetProgramiv(prog, GL_INFO_LOG_LENGTH, &len);
        std::string log(size_t(len > 0 ? len : 1), '\0');
        glGetProgramInfoLog(prog, len, nullptr, log.data());
        *error = vsFile + " + " + fsFile + ": link failed: " + log.c_str();
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
