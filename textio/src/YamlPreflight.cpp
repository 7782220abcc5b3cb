#include "textio/YamlPreflight.h"

#include <algorithm>
#include <sstream>
#include <vector>

#include <yaml-cpp/depthguard.h>    // YAML::DeepRecursion (not included by yaml.h)
#include <yaml-cpp/eventhandler.h>  // YAML::EventHandler (idem)
#include <yaml-cpp/yaml.h>

#include "textio/TextCheck.h"

namespace textio {

namespace {
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
}  // namespace

bool preflightYaml(const std::string& text, size_t maxBytes, int maxNesting, YamlProblem* problem,
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
        DocumentCounter counter(&starts);
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
