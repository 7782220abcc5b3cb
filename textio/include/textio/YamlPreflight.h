#pragma once
// The first pass both YAML loaders (reaction files in the plugin, the engine's legacy smoke file)
// make before they build a node tree: the size limit, the text check (textio/TextCheck.h), and an
// events-only parse that finds syntax errors anywhere and counts documents. Not YAML::LoadAll: on
// some malformed input (a stray ',' at document level) yaml-cpp 0.7 yields empty documents
// forever without consuming anything, and LoadAll collects them until memory runs out; counting
// with a cap and checking for progress avoids that. Header-only, like SafeFile.h.
//
// What went wrong is a YamlError of this library's own; each loader turns it into its own
// diagnostic code (the plugin's and the engine's are fx::ErrorCode, of the same names).
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include <yaml-cpp/depthguard.h>    // YAML::DeepRecursion (not included by yaml.h)
#include <yaml-cpp/eventhandler.h>  // YAML::EventHandler (idem)
#include <yaml-cpp/yaml.h>

#include "textio/TextCheck.h"

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

/// What the first pass found wrong: a named code, where, and what was expected.
struct YamlProblem {
    YamlError code = YamlError::None;
    YAML::Mark mark = YAML::Mark::null_mark();
    std::string message;
};

namespace detail {
class DocumentCounter : public YAML::EventHandler {
public:
    explicit DocumentCounter(std::vector<YAML::Mark>* starts) : starts_(starts) {}
    void OnDocumentStart(const YAML::Mark& mark) override { starts_->push_back(mark); }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
    void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
    void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
    void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
    void OnSequenceEnd() override {}
    void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
    void OnMapEnd() override {}

private:
    std::vector<YAML::Mark>* starts_;
};
}  // namespace detail

/// True when `text` may go to YAML::Load: at most `maxBytes`, UTF-8 text, syntactically valid,
/// at most one document (*hasDocument says whether there is one). Otherwise false with the
/// problem (FileTooLarge, SyntaxError or TooDeep; `maxNesting` is named in the message).
inline bool preflightYaml(const std::string& text, size_t maxBytes, int maxNesting, YamlProblem* problem,
                          bool* hasDocument) {
    if (text.size() > maxBytes) {
        *problem = {YamlError::FileTooLarge, YAML::Mark::null_mark(),
                    "file is " + std::to_string(text.size()) + " bytes; expected at most " + std::to_string(maxBytes)};
        return false;
    }
    NonTextByte bad;
    if (!isYamlText(text, &bad)) {
        *problem = {YamlError::SyntaxError, yamlMarkAt(bad.line, bad.column), bad.message()};
        return false;
    }
    std::vector<YAML::Mark> starts;
    try {
        std::istringstream stream(text);
        YAML::Parser parser(stream);
        detail::DocumentCounter counter(&starts);
        while (starts.size() < 2 && parser.HandleNextDocument(counter)) {
        }
    } catch (const YAML::DeepRecursion& e) {
        *problem = {YamlError::TooDeep, e.mark,
                    "nesting deeper than " + std::to_string(maxNesting) + " levels (" + e.msg + ")"};
        return false;
    } catch (const YAML::Exception& e) {
        *problem = {YamlError::SyntaxError, e.mark, "malformed YAML: " + e.msg};
        return false;
    }
    if (starts.size() >= 2) {
        if (starts[1].pos == starts[0].pos) {  // no progress: the parser is stuck on garbage
            const size_t at = static_cast<size_t>(std::max(starts[0].pos, 0));
            const char c = at < text.size() ? text[at] : ' ';
            *problem = {YamlError::SyntaxError, starts[0],
                        c > ' ' ? std::string("malformed YAML: unexpected '") + c + "'"
                                : std::string("malformed YAML: the parser cannot continue here")};
        } else {
            *problem = {YamlError::SyntaxError, starts[1], "expected one YAML document, found a second one"};
        }
        return false;
    }
    *hasDocument = !starts.empty();
    return true;
}

}  // namespace textio
