#pragma once
// The counters that cross the C boundary in more than one layout: fx::Stats, fxStats2 and
// fxStats; fx::ParticleCheck, fxParticleCheck2 and fxParticleCheck. The fields share their names,
// so one copy serves every pair: the library's C entries (fx_plugin/src/CApi.cpp) fill the C
// structs from the plugin's, the C++ layer (PluginBridge.h) reads them back. Header-only, as the
// rest of fx/detail.

namespace fx {
namespace detail {

/// `to` with every field of Stats (fx/Types.h) taken from `from`.
template <class From, class To>
To withStats(const From& from, To to) {
    to.reactions = from.reactions;
    to.particlesAlive = from.particlesAlive;
    to.particleCapacity = from.particleCapacity;
    to.particlesDrawn = from.particlesDrawn;
    to.reloads = from.reloads;
    to.reloadErrors = from.reloadErrors;
    to.apiErrors = from.apiErrors;
    return to;
}

/// `to` with every field of ParticleCheck (fx/Types.h) taken from `from`.
template <class From, class To>
To withParticleCheck(const From& from, To to) {
    to.alive = from.alive;
    to.capacity = from.capacity;
    to.nonFinite = from.nonFinite;
    return to;
}

}  // namespace detail
}  // namespace fx
