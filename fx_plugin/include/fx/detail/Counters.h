#pragma once
// The counters that cross the C boundary in more than one layout: fx::Stats, fxStats2 and
// fxStats; the counts of fx::ReactionStats and fxReactionStats2. The fields share their names,
// so one copy serves each pair: the library's C entries (fx_plugin/src/CApi.cpp) fill the C
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

/// `to` with the counts of ReactionStats (fx/Types.h: alive, emitted, dropped) taken from `from`;
/// the name and technique are strings in one layout and char arrays in the other.
template <class From, class To>
To withReactionCounts(const From& from, To to) {
    to.alive = from.alive;
    to.emitted = from.emitted;
    to.dropped = from.dropped;
    return to;
}

}  // namespace detail
}  // namespace fx
