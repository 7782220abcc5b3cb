#pragma once
// In-place edits of a YAML file's text at the positions yaml-cpp's parser reports (Node::Mark),
// so that saving an edited value rewrites only that value's characters: comments, key order,
// spacing and every other line stay byte for byte. Handles plain and quoted scalars, flow
// sequences and maps ([0.1, 0.2], {t: 0, rgba: [...]}) and block-style maps; each function
// refuses (false + a message saying where and what it expected) rather than guess.
#include <cstddef>
#include <string>

#include <yaml-cpp/yaml.h>

namespace cube::panel {

/// A byte range [begin, end) of the text.
struct TextSpan {
    size_t begin = 0;
    size_t end = 0;
};

/// The characters of scalar `node` in `text`: a plain scalar on one line, or a '...' / "..."
/// quoted one including its quotes.
bool scalarSpan(const std::string& text, const YAML::Node& node, TextSpan* span, std::string* error);
/// The characters of flow collection `node` ('[' or '{' to its matching bracket, quoted text
/// skipped).
bool flowSpan(const std::string& text, const YAML::Node& node, TextSpan* span, std::string* error);
/// scalarSpan for a scalar, flowSpan for a flow collection; a block collection is refused.
bool valueSpan(const std::string& text, const YAML::Node& node, TextSpan* span, std::string* error);

/// `text` with `span` replaced by `with`.
std::string replaced(const std::string& text, TextSpan span, const std::string& with);

/// Replaces the value of scalar `node` with `value` (written plain; a quoted scalar keeps its
/// quote character). False + error when the node is not a single-line scalar.
bool replaceScalar(std::string* text, const YAML::Node& node, const std::string& value, std::string* error);

/// Adds `key: value` as the last entry of block map `map` (same indentation as its keys), on
/// its own line after the map's last line. False + error for a flow or empty map.
bool appendToBlockMap(std::string* text, const YAML::Node& map, const std::string& key,
                      const std::string& value, std::string* error);

/// The whole line (with its '\n') that holds block sequence entry `item` (a flow map or scalar
/// on one line after "- "): `span` covers it. False + error otherwise.
bool sequenceItemLine(const std::string& text, const YAML::Node& item, TextSpan* span, std::string* error);

/// A number as a YAML scalar: integers as integers; other values with the shortest text that
/// reads back to the same float, keeping a decimal point when `likeText` had one ("2.0").
std::string formatNumber(double value, bool integer, const std::string& likeText = "");

}  // namespace cube::panel
