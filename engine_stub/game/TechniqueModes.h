#pragma once
// The engine's technique override words in one table: `--mode WORD`, the HUD line and the
// panel's technique combo read it. They are the public fx::Technique values (the run-time
// override), not the reaction-file words: those (stateless included) are the plugin's
// TechniqueTable, which the engine reaches only through reactionSchema().
#include <cstddef>
#include <string>

#include "fx/Plugin.h"

namespace cube {

struct TechniqueMode {
    const char* word;         ///< `--mode` word
    fx::Technique technique;  ///< what it sets as RenderOptions::techniqueOverride
    const char* label;        ///< HUD and panel
};

/// Row i is fx::Technique(i): the panel's combo index is the enum value.
inline constexpr TechniqueMode kTechniqueModes[] = {
    {"reaction", fx::Technique::FromReaction, "per reaction"},
    {"hard", fx::Technique::Hard, "hard"},
    {"soft", fx::Technique::Soft, "soft"},
    {"spherical", fx::Technique::Spherical, "spherical"},
    {"mega", fx::Technique::Mega, "mega"},
};
inline constexpr size_t kTechniqueModeCount = sizeof kTechniqueModes / sizeof kTechniqueModes[0];

/// The row of `--mode` word `word`, or null.
inline const TechniqueMode* findTechniqueMode(const std::string& word) {
    for (const TechniqueMode& m : kTechniqueModes)
        if (word == m.word) return &m;
    return nullptr;
}

/// The row of an override value (an out-of-range value reads as the first row).
inline const TechniqueMode& techniqueMode(fx::Technique t) {
    return size_t(t) < kTechniqueModeCount ? kTechniqueModes[size_t(t)] : kTechniqueModes[0];
}

/// The row after `t`'s, the first after the last: the M key's cycle, in the table's order.
inline const TechniqueMode& nextTechniqueMode(fx::Technique t) {
    for (size_t i = 0; i < kTechniqueModeCount; ++i)
        if (kTechniqueModes[i].technique == t) return kTechniqueModes[(i + 1) % kTechniqueModeCount];
    return kTechniqueModes[0];
}

}  // namespace cube
