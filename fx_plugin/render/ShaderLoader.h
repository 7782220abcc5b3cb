#pragma once
// The plugin's own GLSL loader (it does not share the host's): reads <name> from the shaders
// embedded in the library (dir empty) or from a folder (dir, for live edits), expands
// `#include "file"` from the same place, inserts `#define`s after `#version`, compiles and
// links, and reports every failure as "file:line: message" lines naming the file the line is
// really in (an error inside particles_common.glsl names particles_common.glsl).
//
// Include rules: the name is resolved in the shader directory only; each file is expanded once
// per program stage (a second #include of it is skipped, like an include guard); nesting deeper
// than kMaxIncludeDepth is an error. The driver sees `#line` markers that put file k's line n at
// line k * 10000 + n (source-string number k as well; drivers disagree on which they keep) and
// its info log is translated back through the file table. Files are limited to 9999 lines.
#include <cstdint>
#include <string>
#include <vector>

namespace fx {

/// A stage's source ready to compile, and the file behind each GLSL source-string number.
struct ShaderSource {
    std::string text;
    std::vector<std::string> files;  ///< files[k]: lines k * 10000 + n (and source string k)
};

constexpr int kMaxIncludeDepth = 8;

/// Reads `dir`/`name` (or the embedded `name` when `dir` is empty), expanding includes.
/// `defines` is inserted verbatim right after #version
/// (e.g. "#define FX_SPHERICAL 1\n"). Returns false with "file:line: message" in *error when a
/// file cannot be read, an #include is malformed or nested too deep, or #version is missing.
bool loadShaderSource(const std::string& dir, const std::string& name, const std::string& defines,
                      ShaderSource* out, std::string* error);

/// Rewrites a driver info log ("0:12(5): error: ..." Mesa, "0(12) : error ..." NVIDIA,
/// "ERROR: 0:12: ..." AMD/Intel) into "file:line: message" lines; lines it cannot parse are
/// kept, prefixed with `fallbackFile`.
std::string translateInfoLog(const std::string& log, const std::vector<std::string>& files,
                             const std::string& fallbackFile);

/// Builds a program from two stage files. Returns the GL program name, or 0 with every compile
/// or link message in *error ("file:line: message" lines); nothing leaks on failure. Changes no
/// bound GL state (no glUseProgram).
uint32_t buildProgram(const std::string& dir, const std::string& vertexFile,
                      const std::string& fragmentFile, const std::string& defines,
                      std::string* error);

}  // namespace fx
