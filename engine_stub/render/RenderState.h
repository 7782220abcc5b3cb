#pragma once
// The engine back end's state helper. Every scene pass starts from the engine's default state
// (depth test off, LESS, depth writes on, no culling, no blending, program 0, vertex array 0),
// applies what it needs with apply(), and puts the defaults back with ScopedPassState's
// destructor, so no pass depends on what the previous one left behind. (The plugin has its own,
// stricter guard that restores whatever the host had: fx_plugin/render/GlStateGuard.h.)
#include "gl/Gl.h"

namespace cube {

/// Defaults: the engine's default state (see above).
struct PassState {
    bool depthTest = false;
    GLenum depthFunc = GL_LESS;
    bool depthWrite = true;
    bool cullFace = false;
};

/// Applies `state` now; restores the engine's default state when it goes out of scope.
class ScopedPassState {
public:
    explicit ScopedPassState(const PassState& state);
    ~ScopedPassState();
    ScopedPassState(const ScopedPassState&) = delete;
    ScopedPassState& operator=(const ScopedPassState&) = delete;
};

}  // namespace cube
