#pragma once
// The air a reaction's particles move in, as a reactions/*.yaml file describes it: turbulence (the
// curl of a noise potential) and a vortex around a vertical axis. Plain data, read by the loader
// (reactions/) and evaluated by the simulation (sim/CurlNoise.h, which has the fields' formulas).

namespace fx {

/// Defaults: off (strength 0), 2 m eddies, pattern drifting at 0.5 m/s, 3 octaves.
struct TurbulenceDesc {
    float strength = 0.0f;  ///< [0, 50] m/s, scale of the turbulent velocity; 0 = off
    float scale = 2.0f;     ///< [0.01, 1000] m, size of the largest eddies
    float speed = 0.5f;     ///< [0, 100] m/s, how fast the pattern evolves
    int octaves = 3;        ///< [1, 6]
    bool enabled() const { return strength > 0.0f; }
};

/// Defaults: off (strength 0), 1 m core radius.
struct VortexDesc {
    float strength = 0.0f;  ///< [-50, 50] m/s tangential speed at the core radius; < 0 turns clockwise
    float radius = 1.0f;    ///< [0.01, 100] m core radius (solid-body rotation inside)
    bool enabled() const { return strength != 0.0f; }
};

}  // namespace fx
