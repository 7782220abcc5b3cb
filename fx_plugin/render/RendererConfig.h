#pragma once
// What the particle renderers (ParticleRenderer, MegaRenderer) are made with, and what they do
// alike: log through the host, load the private GL table, check that the host's targets have the
// view's size, and keep one view's recorded draw alive until the host has run its passes.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "fx/Diagnostic.h"
#include "fx/HostAdapter.h"
#include "fx/Types.h"
#include "base/ParallelFor.h"

namespace fx {

class ApiErrors;

/// Defaults: no host (nothing is logged, and GL cannot be loaded), shaders and atlas embedded in
/// the library, refused calls not counted.
struct RendererConfig {
    HostAdapter* host = nullptr;
    std::string shaderDir;        ///< empty = the shaders embedded in the library
    std::string dataDir;          ///< empty = the atlas embedded in the library
    ApiErrors* errors = nullptr;  ///< where SizeMismatch is reported (may be null)
    Jobs jobs;                    ///< the host's job system (none: the work stays on the calling thread)
};

/// `message` through the config's host; nothing without one.
void logTo(const RendererConfig& config, LogLevel level, const std::string& message);

/// A renderer's first load step: the plugin's private GL table, filled through the host (never a
/// global loader). False when it cannot be: logged as "fx: <what> disabled: <why>" and added to
/// `diagnostics`.
bool loadGlFor(const RendererConfig& config, const char* what, Diagnostics* diagnostics);

/// Told "the scene targets are ..., ViewInfo ...; they must be equal; nothing drawn" when a pass's
/// targets do not fit its view (the renderer reports it as SizeMismatch).
using SizeMismatchReport = std::function<void(const std::string& what)>;

/// True when `first` (and `second`, if valid: targets the pass declared, sceneColor or
/// sceneDepth) have the view's size; otherwise tells `report` and returns false.
bool targetsFitView(PassContext& ctx, const ViewInfo& view, Target first, Target second,
                    const SizeMismatchReport& report);

/// A view's record for the pass bodies: one whose passes the host has dropped is held only by
/// `records` and is reused (with its buffers), else a new one is added.
template <class Record>
std::shared_ptr<Record> reuseRecord(std::vector<std::shared_ptr<Record>>& records) {
    for (const std::shared_ptr<Record>& r : records) {
        if (r.use_count() == 1) return r;
    }
    records.push_back(std::make_shared<Record>());
    return records.back();
}

}  // namespace fx
