#pragma once
// The plugin's versioned entry point (one exported function taking the host's imports and
// returning the plugin, or null on a version mismatch) and the interface the host drives.
#include <cstdint>
#include <memory>
#include <string>

#include "fx/Diagnostic.h"
#include "fx/HostAdapter.h"
#include "fx/Types.h"

namespace fx {

constexpr uint32_t kApiVersion = 1;

/// How particles are drawn. `FromReaction` uses each reaction's own `render.technique`.
enum class Technique : uint8_t { FromReaction = 0, Hard, Soft, Spherical };

/// Run-time switches. Defaults: every reaction draws its own technique at full resolution.
struct RenderOptions {
    Technique techniqueOverride = Technique::FromReaction;
    bool quarterRes = false;       ///< particles into a half x half target, depth-aware composite
    bool bilinearUpsample = false; ///< quarter-res composite with plain bilinear (for comparison only)
};

class Plugin {
public:
    virtual ~Plugin() = default;

    /// SpecialFX::Init: loads every reaction from a .yaml file or a directory of them. On error
    /// nothing running is replaced, every problem is appended to `out`, and false is returned.
    virtual bool loadReactions(const std::string& path, Diagnostics* out) = 0;
    /// Checks the loaded files for changes and reloads them; a bad edit keeps the running set.
    /// Returns true when a new set went live.
    virtual bool pollHotReload(Diagnostics* out) = 0;

    virtual int reactionCount() const = 0;
    virtual std::string reactionName(int index) const = 0;
    /// Reaction::Continue: advances reaction `index` by dt seconds. `currentVehicleCollisionAmount`
    /// (may be null) is the host's collision impulse this step, 0..1.
    virtual void continueReaction(int index, float dt, float* currentVehicleCollisionAmount) = 0;

    virtual void setRenderOptions(const RenderOptions& options) = 0;
    virtual RenderOptions renderOptions() const = 0;
    /// The hook into the host's particle bucket: declares this view's particle passes. Declares
    /// nothing when no particle is visible, so the host allocates nothing for it.
    virtual void declarePasses(const ViewInfo& view, FrameBuilder& frame) = 0;

    virtual Stats stats() const = 0;
};

struct PluginImports {
    uint32_t apiVersion = kApiVersion;
    HostAdapter* host = nullptr;
    std::string shaderDir;   ///< where shaders/ lives; empty = the build's source tree
    std::string dataDir;     ///< where data/ (smoke atlas) lives; empty = the build's source tree
    uint64_t seed = 0;       ///< global random seed for the reactions; 0 = the plugin's default
};

}  // namespace fx

/// The entry point. Returns null when `imports.apiVersion` differs from the plugin's or host is null.
std::unique_ptr<fx::Plugin> fxCreatePlugin(const fx::PluginImports& imports);
