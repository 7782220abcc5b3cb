#include "textio/ShaderSource.h"

#include <cctype>
#include <cstdlib>
#include <set>
#include <sstream>

#include "textio/SafeFile.h"

namespace textio {
namespace {

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
    const ShaderReader& read;
    std::string* out;
    std::vector<std::string>* files;
    std::set<std::string> seen;
    bool sawVersion = false;
    std::string versionLine = "#version 330 core";  ///< the top file's own, where it has one
    ShaderError code = ShaderError::None;

    // `where` is "file:line" of the #include that asked for `name` (empty for the top file).
    bool expand(const std::string& name, int depth, const std::string& where, std::string* error) {
        const std::string prefix = where.empty() ? name : where;
        if (depth > kMaxIncludeDepth) {
            code = ShaderError::IncludeTooDeep;
            *error = prefix + ": #include nested deeper than " + std::to_string(kMaxIncludeDepth) +
                     " levels at \"" + name + "\"";
            return false;
        }
        if (!seen.insert(name).second) return true;
        std::string text, why;
        if (!read(name, &text, &why)) {
            *error = prefix + ": " + why;
            code = ShaderError::FileNotFound;
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
                code = ShaderError::FileTooLong;
                *error = name + ":" + std::to_string(lineNo) + ": shader file longer than " +
                         std::to_string(kFileLineStride - 1) + " lines";
                return false;
            }
            if (!line.empty() && line.back() == '\r') line.pop_back();
            size_t at = 0;
            if (startsWithDirective(line, "#version", &at)) {
                // Emitted once by the caller, ahead of the defines.
                if (depth == 0 && !sawVersion) {
                    sawVersion = true;
                    versionLine = line;  // "#version 330 core", or "#version 430 core" (compute)
                }
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
                    code = ShaderError::MalformedInclude;
                    *error = here + ": malformed #include, expected #include \"file\"";
                    return false;
                }
                if (!expand(line.substr(a + 1, b - a - 1), depth + 1, here, error)) return false;
                *out += lineDirective(lineNo + 1, index);
                continue;
            }
            *out += line;
            *out += '\n';
            // An #include inside a group the preprocessor skips (#ifdef FX_MEGA_SHADE with the
            // define off) is expanded all the same, and the #line that follows it is skipped with
            // the group: the lines after it would be counted on from the included file's length.
            // A marker after each group boundary puts the count right again wherever it resumes.
            if (startsWithDirective(line, "#else", &at) || startsWithDirective(line, "#elif", &at) ||
                startsWithDirective(line, "#endif", &at)) {
                *out += lineDirective(lineNo + 1, index);
            }
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

}  // namespace

const char* shaderErrorName(ShaderError code) {
    switch (code) {
    case ShaderError::None: return "None";
    case ShaderError::FileNotFound: return "FileNotFound";
    case ShaderError::MalformedInclude: return "MalformedInclude";
    case ShaderError::IncludeTooDeep: return "IncludeTooDeep";
    case ShaderError::FileTooLong: return "FileTooLong";
    case ShaderError::MissingVersion: return "MissingVersion";
    case ShaderError::CompileFailed: return "CompileFailed";
    case ShaderError::LinkFailed: return "LinkFailed";
    }
    return "Unknown";
}

ShaderReader folderShaderReader(const std::string& dir) {
    return [dir](const std::string& name, std::string* text, std::string* why) {
        // Never blocks on a FIFO, reads regular files only, at most 1 MiB (a shader is a few KiB).
        std::string reason;
        if (textio::readFileBounded(dir + "/" + name, kMaxShaderBytes, text, nullptr, &reason)) return true;
        *why = "cannot open shader file \"" + dir + "/" + name + "\" (" + reason + ")";
        return false;
    };
}

ShaderError expandShaderSource(const ShaderReader& read, const std::string& name, const std::string& defines,
                               ShaderSource* out, std::string* error, VersionLine version) {
    std::string body;
    out->files.clear();
    Expander expander{read, &body, &out->files, {}, false};
    if (!expander.expand(name, 0, std::string(), error)) return expander.code;
    if (!expander.sawVersion && version == VersionLine::Required) {
        *error = name + ":1: missing #version (expected \"#version 330 core\" on the first line)";
        return ShaderError::MissingVersion;
    }
    out->text = expander.versionLine + "\n" + defines + body;
    return ShaderError::None;
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

}  // namespace textio
