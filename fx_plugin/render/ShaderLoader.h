#pragma once
// The plugin's GLSL programs: sources through the project's one loader (shader/ShaderSource.h),
// read from the shaders embedded in the library (dir empty) or from a folder (dir, for live
// edits), compiled and linked with the plugin's private GL table. Every failure is reported as
// "file:line: message" lines naming the file the line is really in (an error inside
// particles_common.glsl names particles_common.glsl).
#include <cstdint>
#include <string>
#include <vector>

#include "shader/ShaderSource.h"

namespace fx {

/// The embedded copies when `dir` is empty, else the folder `dir`.
ShaderReader shaderReader(const std::string& dir);

/// Reads `dir`/`name` (or the embedded `name` when `dir` is empty), expanding includes, as
/// expandShaderSource. Returns false with "file:line: message" in *error.
bool loadShaderSource(const std::string& dir, const std::string& name, const std::string& defines,
                      ShaderSource* out, std::string* error);

/// Builds a program from two stage files. Returns the GL program name, or 0 with every compile
/// or link message in *error ("file:line: message" lines); nothing leaks on failure. Changes no
/// bound GL state (no glUseProgram).
uint32_t buildProgram(const std::string& dir, const std::string& vertexFile,
                      const std::string& fragmentFile, const std::string& defines,
                      std::string* error);

}  // namespace fx
