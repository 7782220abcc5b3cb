#pragma once
// The project's one GLSL source loader (engine, plugin and harness all build their programs from
// it): reads a stage's file through a ShaderReader, expands `#include "file"`, inserts `#define`s
// after `#version`, writes `#line` markers that carry the file, and translates a driver's info
// log back to "file:line: message" lines naming the file the line is really in. Failures have
// named codes (ShaderError). It calls no GL: each side compiles with its own loader (the plugin
// through its private one, the engine through its glad), and both link this library.
//
// Include rules: names are resolved by the reader (a folder, or the plugin's embedded copies);
// each file is expanded once per stage (a second #include of it is skipped, like an include
// guard); nesting deeper than kMaxIncludeDepth is an error. The driver sees `#line` markers that
// put file k's line n at line k * 10000 + n (source-string number k as well; drivers disagree on
// which they keep). Files are limited to 9999 lines and kMaxShaderBytes.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace textio {

enum class ShaderError {
    None = 0,
    FileNotFound,      ///< the reader could not give a file (missing, not a regular file, too big)
    MalformedInclude,  ///< `#include` without a "file" in quotes
    IncludeTooDeep,    ///< nesting deeper than kMaxIncludeDepth
    FileTooLong,       ///< a file of 10000 lines or more
    MissingVersion,    ///< the top file has no #version line
    CompileFailed,     ///< the driver refused a stage (the message has file:line)
    LinkFailed,        ///< the driver refused to link the stages
};
const char* shaderErrorName(ShaderError code);

/// A stage's source ready to compile, and the file behind each GLSL source-string number.
struct ShaderSource {
    std::string text;
    std::vector<std::string> files;  ///< files[k]: lines k * 10000 + n (and source string k)
};

constexpr int kMaxIncludeDepth = 8;
constexpr size_t kMaxShaderBytes = size_t(1) << 20;

/// Gives the text of shader file `name`, or false with a reason in *why.
using ShaderReader = std::function<bool(const std::string& name, std::string* text, std::string* why)>;
/// Reads `dir`/`name` through SafeFile (regular files only, never blocking, kMaxShaderBytes).
ShaderReader folderShaderReader(const std::string& dir);

/// Whether the top file must carry its own `#version` line (the plugin's files do; the engine's
/// scene shaders leave it to the loader). The result starts with the top file's own #version line
/// (330 core for every stage but the plugin's compute shader, 430 core), else "#version 330 core".
enum class VersionLine { Required, Implied };

/// Expands `name` and its includes. `defines` is inserted verbatim right after the #version line
/// (e.g. "#define FX_SPHERICAL 1\n"). On failure returns the code with "file:line: message"
/// in *error.
ShaderError expandShaderSource(const ShaderReader& read, const std::string& name, const std::string& defines,
                               ShaderSource* out, std::string* error,
                               VersionLine version = VersionLine::Required);

/// Rewrites a driver info log ("0:12(5): error: ..." Mesa, "0(12) : error ..." NVIDIA,
/// "ERROR: 0:12: ..." AMD/Intel) into "file:line: message" lines; lines it cannot parse are
/// kept, prefixed with `fallbackFile`.
std::string translateInfoLog(const std::string& log, const std::vector<std::string>& files,
                             const std::string& fallbackFile);

}  // namespace textio
