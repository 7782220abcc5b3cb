#pragma once
// The reaction file schema: which keys exist, their types, ranges and cross-field rules.
// reactions/README.md documents the same tables for people editing the files.
#include <vector>

#include <yaml-cpp/yaml.h>

#include "YamlCheck.h"
#include "reactions/ReactionDesc.h"

namespace fx {

/// Reads one parsed document (`reactions: [...]`) into `out`, reporting every problem it finds
/// to `check` (it does not stop at the first). When check.errors() grew, `out` holds partial
/// results that the caller must discard.
void readReactionDocument(YamlCheck& check, const YAML::Node& root,
                          std::vector<ReactionDesc>* out);

}  // namespace fx
