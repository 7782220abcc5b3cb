#pragma once
// A read-only description of the reaction schema (ReactionSchema.cpp enforces it) for editing
// tools, and the running value of any key as YAML flow text. Nothing here validates: the table
// states what the loader checks, and tests/fx_reactions/KeyTableTest.cpp loads each bound and
// a value just past it to prove that the two agree.
#include <string>
#include <vector>

#include "fx/Plugin.h"
#include "reactions/ReactionDesc.h"

namespace fx {

/// Every key of a reaction, in reactions/README.md order (built once, never changes).
const std::vector<ReactionKeyInfo>& reactionKeyTable();

/// `key` (a ReactionKeyInfo::key) of `desc` as YAML flow text ("1.2", "[3, 5]", "soft",
/// "[asphalt, kerb]", "[{t: 0, rgba: [1, 1, 1, 1]}]"); "" for an unknown key. Numbers use the
/// shortest text that reads back to the same float.
std::string reactionValueText(const ReactionDesc& desc, const std::string& key);

}  // namespace fx
