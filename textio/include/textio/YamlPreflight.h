#pragma once
// The first pass both YAML loaders (reaction files in the plugin, the engine's legacy smoke file)
// make before they build a node tree: the size limit, the text check (textio/TextCheck.h), and an
// events-only parse that finds syntax errors anywhere and counts documents. Not YAML::LoadAll: on
// some malformed input (a stray ',' at document level) yaml-cpp 0.7 yields empty documents
// forever without consuming anything, and LoadAll collects them until memory runs out; counting
// with a cap and checking for progress avoids that.
//
// What went wrong is a YamlError of this library's own; each loader turns it into its own
// diagnostic code with errorCodeAs.
#include <cstddef>
#include <string>

#include <yaml-cpp/mark.h>

namespace textio {

/// A mark at a 0-based line and column.
inline YAML::Mark yamlMarkAt(int line0, int column0) {
    YAML::Mark m = YAML::Mark::null_mark();
    m.line = line0;
    m.column = column0;
    return m;
}

/// Why the first pass refused a text.
enum class YamlError {
    None = 0,
    FileTooLarge,  ///< more than the loader's byte limit
    SyntaxError,   ///< not UTF-8 text, malformed YAML, or more than one document
    TooDeep,       ///< nesting deeper than the loader's limit
};

/// `error` as a loader's own code enum, which has members of these four names (fx::ErrorCode,
/// which the plugin and the engine report with, does), so the library names neither side.
template <class Code>
Code errorCodeAs(YamlError error) {
    switch (error) {
        case YamlError::None: return Code::None;
        case YamlError::FileTooLarge: return Code::FileTooLarge;
        case YamlError::SyntaxError: return Code::SyntaxError;
        case YamlError::TooDeep: return Code::TooDeep;
    }
    return Code::SyntaxError;
}

/// What the first pass found wrong: a named code, where, and what was expected.
struct YamlProblem {
    YamlError code = YamlError::None;
    YAML::Mark mark = YAML::Mark::null_mark();
    std::string message;
};

/// True when `text` may go to YAML::Load: at most `maxBytes`, UTF-8 text, syntactically valid,
/// at most one document (*hasDocument says whether there is one). Otherwise false with the
/// problem (FileTooLarge, SyntaxError or TooDeep; `maxNesting` is named in the message).
bool preflightYaml(const std::string& text, size_t maxBytes, int maxNesting, YamlProblem* problem,
                   bool* hasDocument);

}  // namespace textio
