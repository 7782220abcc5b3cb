#pragma once
// The plugin's GLSL programs: sources through the project's one loader (textio/ShaderSource.h),
// read from the shaders embedded in the library (dir empty) or from a folder (dir, for live
// edits), compiled and linked with the plugin's private GL table. Every failure is reported as
// "file:line: message" lines naming the file the line is really in (an error inside
// particles_common.glsl names particles_common.glsl).
#include <cstdint>
#include <string>
#include <vector>

#include "fx/Diagnostic.h"
#include "base/TextIo.h"

namespace fx {

/// The embedded copies when `dir` is empty, else the folder `dir`.
ShaderReader shaderReader(const std::string& dir);

/// Reads `dir`/`name` (or the embedded `name` when `dir` is empty), expanding includes, as
/// expandShaderSource. Returns false with "file:line: message" in *error.
bool loadShaderSource(const std::string& dir, const std::string& name, const std::string& defines,
                      ShaderSource* out, std::string* error);

/// Builds a program from two stage files, or with `fragmentFile` empty a compute program from
/// `vertexFile` alone (the caller checks the context has ARB_compute_shader). Returns the GL
/// program name, or 0 with every compile or link message in *error ("file:line: message" lines);
/// nothing leaks on failure. Changes no bound GL state (no glUseProgram).
uint32_t buildProgram(const std::string& dir, const std::string& vertexFile,
                      const std::string& fragmentFile, const std::string& defines,
                      std::string* error);
/// The same through any reader (a snapshot, below).
uint32_t buildProgram(const ShaderReader& read, const std::string& vertexFile,
                      const std::string& fragmentFile, const std::string& defines,
                      std::string* error);

/// How many programs this process has built (each buildProgram call), how many of those while a
/// frame was declared or ran (FrameScope open), and how many inside a pass. prepareGl and a
/// shader reload build every program the reactions and options draw with: a host that calls
/// prepareGl again after changing options or reactions sees inFrame stay put, and no pass ever
/// compiles (ProgramCache.h). Tests read these; nothing else does.
struct ProgramBuildCounts {
    uint64_t built = 0;
    uint64_t inFrame = 0;
    uint64_t inPass = 0;
};
ProgramBuildCounts programBuildCounts();

/// Marks a span of a frame for programBuildCounts: declaring passes (Plugin::declarePasses,
/// declareShadowPasses), running one (`pass`: the C boundary's pass trampoline, the immediate
/// path's passes). Nests; one thread, as the plugin.
class FrameScope {
public:
    enum Kind { Declare, Pass };
    explicit FrameScope(Kind kind);
    ~FrameScope();
    FrameScope(const FrameScope&) = delete;
    FrameScope& operator=(const FrameScope&) = delete;

private:
    Kind kind_;
};

/// Size and modification time of every plugin shader in the override folder `shaderDir`: the
/// billboard, stateless and mega programs' files and their includes ("particles" or "mega" in the
/// name; the engine's own shaders there are not ours), hashed. A change means an edit to reload.
/// No file is opened: a FIFO dropped there cannot block the poll.
uint64_t shaderStamp(const std::string& shaderDir);

/// A reader that keeps the text of every file it gave out and gives the same text again on each
/// later read of that name, whatever the file holds by then. A program set built through one
/// snapshot, and any variant of it built later (a contrast power a reload asks for), is built from
/// one version of each file: the version that built and went live, never a later broken edit.
ShaderReader snapshotShaderReader(ShaderReader read);

/// "file:line: message" lines of a build error as ShaderBuild diagnostics (file and line
/// split out where the line has them).
void addShaderDiagnostics(const std::string& text, Diagnostics* out);

/// The build errors of one load or reload, each distinct line once: one cause (a syntax error
/// in fs_particles_soft.glsl) fails every variant built from the file (unlit, lit, general
/// power, ...) with the same "file:line: message", and the user is told it once.
class ShaderErrorLog {
public:
    /// Adds the lines of one build's error not seen before (in order) and returns those lines
    /// ("" when every one was already there).
    std::string add(const std::string& error);
    bool empty() const { return lines_.empty(); }
    /// Every distinct line, joined by newlines.
    std::string text() const;

private:
    std::vector<std::string> lines_;
};

}  // namespace fx
