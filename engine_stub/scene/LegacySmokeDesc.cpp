#include "scene/LegacySmokeDesc.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "textio/SafeFile.h"
#include "textio/YamlPreflight.h"

namespace cube {

namespace {

using fx::ErrorCode;

// Collects diagnostics for one file, capped like the reaction loader's.
class Report {
public:
    Report(const std::string& file, fx::Diagnostics* diags) : file_(file), diags_(diags) {}
    void add(ErrorCode code, const YAML::Mark& mark, const std::string& key, const std::string& message) {
        ++errors_;
        if (!diags_) return;
        if (errors_ > kMaxListed) {
            if (errors_ == kMaxListed + 1) push(ErrorCode::TooManyErrors, YAML::Mark::null_mark(), "",
                                                "more errors follow; fix these first");
            return;
        }
        push(code, mark, key, message);
    }
    int errors() const { return errors_; }

private:
    static constexpr int kMaxListed = 100;
    void push(ErrorCode code, const YAML::Mark& mark, const std::string& key, const std::string& message) {
        fx::Diagnostic d;
        d.code = code;
        d.file = file_;
        d.line = mark.line >= 0 ? mark.line + 1 : 0;
        d.column = mark.column >= 0 ? mark.column + 1 : 0;
        d.key = key;
        d.message = message;
        diags_->push_back(std::move(d));
    }
    std::string file_;
    fx::Diagnostics* diags_;
    int errors_ = 0;
};

// Collection levels of `root`, counted until they pass kLegacyMaxNesting and no further. Aliases
// make the parsed tree a DAG that expands exponentially (nine levels of ten aliases each is 10^9
// paths in a few hundred bytes), so the walk is iterative, depth-first (a path past the limit is
// found after at most limit + 1 pops per level), stops at the first level past the limit, and
// stops after kLegacyNestingVisits nodes whatever it found, as the reaction loader's
// YamlCheck::subtreeDepth does.
int nesting(const YAML::Node& root) {
    std::vector<std::pair<YAML::Node, int>> stack;
    stack.emplace_back(root, 0);
    int deepest = 0;
    for (int visits = 0; !stack.empty() && visits < kLegacyNestingVisits; ++visits) {
        const YAML::Node n = stack.back().first;
        const int depth = stack.back().second;
        stack.pop_back();
        if (!n.IsMap() && !n.IsSequence()) continue;
        deepest = std::max(deepest, depth);
        if (deepest > kLegacyMaxNesting) return deepest;
        if (n.IsSequence()) {
            for (const YAML::Node& c : n) stack.emplace_back(c, depth + 1);
        } else {
            for (const auto& kv : n) stack.emplace_back(kv.second, depth + 1);
        }
    }
    return deepest;
}

// Every map must name each key once: yaml-cpp would silently keep one of them.
bool checkUniqueKeys(const YAML::Node& map, const std::string& path, Report& r) {
    std::map<std::string, YAML::Mark> seen;
    bool ok = true;
    for (const auto& kv : map) {
        const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : std::string("?");
        const auto [it, inserted] = seen.emplace(key, kv.first.Mark());
        if (!inserted) {
            r.add(ErrorCode::DuplicateKey, kv.first.Mark(), path.empty() ? key : path + "." + key,
                  "key '" + key + "' appears twice in this map (first at line " +
                      std::to_string(it->second.line + 1) + "); expected each key once");
            ok = false;
        }
    }
    return ok;
}

class Reader {
public:
    Reader(Report& r) : r_(r) {}

    bool number(const YAML::Node& n, const std::string& key, double lo, double hi, double* out) {
        if (!n.IsScalar()) {
            r_.add(ErrorCode::WrongType, n.Mark(), key, "expected a number in [" + fmt(lo) + ", " + fmt(hi) + "]");
            return false;
        }
        double v = 0.0;
        std::istringstream s(n.Scalar());
        s.imbue(std::locale::classic());
        const std::string& t = n.Scalar();
        if (t == ".nan" || t == ".NaN" || t == ".NAN" || t == ".inf" || t == "-.inf" || t == "+.inf" ||
            t == ".Inf" || t == "-.Inf") {
            r_.add(ErrorCode::NotFinite, n.Mark(), key, "'" + t + "' is not finite; expected a number in [" +
                                                            fmt(lo) + ", " + fmt(hi) + "]");
            return false;
        }
        if (!(s >> v) || !s.eof()) {
            r_.add(ErrorCode::WrongType, n.Mark(), key, "'" + t + "' is not a number; expected a number in [" +
                                                            fmt(lo) + ", " + fmt(hi) + "]");
            return false;
        }
        if (!std::isfinite(v)) {
            r_.add(ErrorCode::NotFinite, n.Mark(), key, "'" + t + "' is not finite");
            return false;
        }
        if (v < lo || v > hi) {
            r_.add(ErrorCode::OutOfRange, n.Mark(), key, fmt(v) + " is outside [" + fmt(lo) + ", " + fmt(hi) + "]");
            return false;
        }
        *out = v;
        return true;
    }

    bool real(const YAML::Node& n, const std::string& key, float lo, float hi, float* out) {
        double v = 0.0;
        if (!number(n, key, lo, hi, &v)) return false;
        *out = float(v);
        return true;
    }

    bool count(const YAML::Node& n, const std::string& key, int lo, int hi, int* out) {
        if (n.IsScalar()) {
            const std::string& t = n.Scalar();
            const bool whole = !t.empty() && t.find_first_not_of("+-0123456789") == std::string::npos;
            if (!whole) {
                double v = 0.0;
                std::istringstream s(t);
                if ((s >> v) && s.eof() && std::isfinite(v) && v < 0) {
                    r_.add(ErrorCode::NegativeCount, n.Mark(), key, "'" + t + "' is negative; expected a whole number in [" +
                                                                        std::to_string(lo) + ", " + std::to_string(hi) + "]");
                } else {
                    r_.add(ErrorCode::WrongType, n.Mark(), key,
                           "'" + t + "' is not a whole number; expected a whole number in [" + std::to_string(lo) +
                               ", " + std::to_string(hi) + "]");
                }
                return false;
            }
        }
        double v = 0.0;
        if (n.IsScalar() && !n.Scalar().empty() && n.Scalar()[0] == '-' && n.Scalar() != "-0") {
            r_.add(ErrorCode::NegativeCount, n.Mark(), key, "'" + n.Scalar() + "' is negative; expected a whole number in [" +
                                                                std::to_string(lo) + ", " + std::to_string(hi) + "]");
            return false;
        }
        if (!number(n, key, lo, hi, &v)) return false;
        *out = int(v);
        return true;
    }

    bool vec(const YAML::Node& n, const std::string& key, size_t size, float lo, float hi, float* out,
             const char* expected) {
        if (!n.IsSequence() || n.size() != size) {
            r_.add(ErrorCode::WrongType, n.Mark(), key, std::string("expected ") + expected);
            return false;
        }
        bool ok = true;
        for (size_t i = 0; i < size; ++i)
            ok = real(n[i], key + "[" + std::to_string(i) + "]", lo, hi, &out[i]) && ok;
        return ok;
    }

    void reaction(const YAML::Node& r, const std::string& at, LegacySmokeDesc* d) {
        if (!r.IsMap()) {
            r_.add(ErrorCode::WrongType, r.Mark(), at, "expected a reaction map (name, wheels, rate, ...)");
            return;
        }
        checkUniqueKeys(r, at, r_);
        bool named = false;
        for (const auto& kv : r) {
            const std::string k = kv.first.IsScalar() ? kv.first.Scalar() : std::string("?");
            const std::string key = at + "." + k;
            const YAML::Node& v = kv.second;
            float pair[2] = {d->startSize, d->endSize};
            if (k == "name") {
                if (!v.IsScalar() || v.Scalar().empty()) {
                    r_.add(ErrorCode::WrongType, v.Mark(), key, "expected a non-empty name");
                } else {
                    d->name = v.Scalar();
                    named = true;
                }
            } else if (k == "wheels") {
                if (!v.IsScalar() || (v.Scalar() != "rear" && v.Scalar() != "front" && v.Scalar() != "all")) {
                    r_.add(ErrorCode::InvalidEnum, v.Mark(), key, "expected rear, front or all");
                } else {
                    d->wheels = v.Scalar();
                }
            } else if (k == "slip_threshold") real(v, key, 0, 1, &d->slipThreshold);
            else if (k == "rate") real(v, key, 0, 10000, &d->rate);
            else if (k == "capacity") count(v, key, 1, 100000, &d->capacity);
            else if (k == "lifetime") real(v, key, 0.01f, 60, &d->lifetime);
            else if (k == "size") {
                if (vec(v, key, 2, 0.01f, 100, pair, "[start, end] in metres, each in [0.01, 100]")) {
                    d->startSize = pair[0];
                    d->endSize = pair[1];
                }
            } else if (k == "rise_speed") real(v, key, -10, 10, &d->riseSpeed);
            else if (k == "hover") real(v, key, 0, 10, &d->hover);
            else if (k == "alpha") real(v, key, 0, 1, &d->alpha);
            else if (k == "tint") {
                float t[3];
                if (vec(v, key, 3, 0, 1, t, "[r, g, b], each in [0, 1]")) d->tint = glm::vec3(t[0], t[1], t[2]);
            } else {
                r_.add(ErrorCode::UnknownKey, kv.first.Mark(), key,
                       "unknown key '" + k + "'; expected name, wheels, slip_threshold, rate, capacity, "
                       "lifetime, size, rise_speed, hover, alpha or tint");
            }
        }
        if (!named) r_.add(ErrorCode::MissingKey, r.Mark(), at + ".name", "a reaction needs a name");
    }

private:
    static std::string fmt(double v) {
        std::ostringstream s;
        s << v;
        return s.str();
    }
    Report& r_;
};

bool loadChecked(const std::string& text, Report& report, std::vector<LegacySmokeDesc>* result) {
    // The reaction loader's first pass (textio/YamlPreflight.h): size, text, syntax, one document.
    textio::YamlProblem problem;
    bool hasDocument = false;
    if (!textio::preflightYaml(text, kLegacyMaxFileBytes, kLegacyMaxNesting, &problem, &hasDocument)) {
        report.add(textio::errorCodeAs<ErrorCode>(problem.code), problem.mark, "", problem.message);
        return false;
    }
    const YAML::Node root = YAML::Load(text);
    if (!hasDocument || root.IsNull()) {
        report.add(ErrorCode::EmptyFile, YAML::Mark::null_mark(), "",
                   "the file holds nothing; expected a map with a 'reactions' list");
        return false;
    }
    if (nesting(root) > kLegacyMaxNesting) {
        report.add(ErrorCode::TooDeep, root.Mark(), "",
                   "nesting deeper than " + std::to_string(kLegacyMaxNesting) + " levels");
        return false;
    }
    if (!root.IsMap()) {
        report.add(ErrorCode::WrongType, root.Mark(), "", "expected a map with a 'reactions' list");
        return false;
    }
    checkUniqueKeys(root, "", report);
    for (const auto& kv : root) {
        const std::string k = kv.first.IsScalar() ? kv.first.Scalar() : std::string("?");
        if (k != "reactions")
            report.add(ErrorCode::UnknownKey, kv.first.Mark(), k, "unknown key '" + k + "'; expected 'reactions'");
    }
    const YAML::Node list = root["reactions"];
    if (!list) {
        report.add(ErrorCode::MissingKey, root.Mark(), "reactions", "expected a 'reactions' list");
        return false;
    }
    if (!list.IsSequence()) {
        report.add(ErrorCode::WrongType, list.Mark(), "reactions", "expected a list of reaction maps");
        return false;
    }
    if (list.size() > size_t(kLegacyMaxReactions)) {
        report.add(ErrorCode::OutOfRange, list.Mark(), "reactions",
                   std::to_string(list.size()) + " reactions; expected at most " +
                       std::to_string(kLegacyMaxReactions));
        return false;
    }
    Reader reader(report);
    std::map<std::string, int> names;
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string at = "reactions[" + std::to_string(i) + "]";
        LegacySmokeDesc d;
        reader.reaction(list[i], at, &d);
        if (!d.name.empty()) {
            const auto [it, inserted] = names.emplace(d.name, list[i].Mark().line + 1);
            if (!inserted)
                report.add(ErrorCode::DuplicateName, list[i].Mark(), at + ".name",
                           "reaction name '" + d.name + "' is already used at line " + std::to_string(it->second));
        }
        result->push_back(d);
    }
    return report.errors() == 0;
}

}  // namespace

bool loadLegacySmokeText(const std::string& text, const std::string& nameForMessages,
                         std::vector<LegacySmokeDesc>* out, fx::Diagnostics* diags) {
    Report report(nameForMessages, diags);
    const size_t firstDiag = diags ? diags->size() : 0;
    std::vector<LegacySmokeDesc> result;
    bool ok = false;
    try {  // nothing escapes: yaml-cpp reports through exceptions, allocation can fail
        ok = loadChecked(text, report, &result);
    } catch (const YAML::Exception& e) {
        report.add(ErrorCode::SyntaxError, e.mark, "", "malformed YAML: " + e.msg);
    } catch (const std::exception& e) {
        report.add(ErrorCode::SyntaxError, YAML::Mark::null_mark(), "", std::string("unreadable YAML: ") + e.what());
    }
    if (!ok || report.errors() != 0) {
        if (diags) {  // in file order (keys are checked in several passes), the overflow note last
            std::stable_sort(diags->begin() + std::ptrdiff_t(firstDiag), diags->end(),
                             [](const fx::Diagnostic& a, const fx::Diagnostic& b) {
                                 auto rank = [](const fx::Diagnostic& d) {
                                     return d.code == ErrorCode::TooManyErrors ? INT_MAX : d.line;
                                 };
                                 return rank(a) != rank(b) ? rank(a) < rank(b) : a.column < b.column;
                             });
        }
        return false;
    }
    *out = std::move(result);
    return true;
}

bool loadLegacySmoke(const std::string& path, std::vector<LegacySmokeDesc>* out, fx::Diagnostics* diags) {
    std::string text;
    textio::FileError code = textio::FileError::None;
    std::string why;
    if (!textio::readFileBounded(path, kLegacyMaxFileBytes, &text, &code, &why)) {
        if (diags) {
            fx::Diagnostic d;
            d.code = code == textio::FileError::TooLarge ? ErrorCode::FileTooLarge : ErrorCode::FileNotFound;
            d.file = path;
            d.message = (code == textio::FileError::TooLarge ? "legacy smoke file is " : "cannot open legacy smoke file: ") +
                        why + (code == textio::FileError::NotRegular ? "; expected a .yaml file" : "");
            diags->push_back(std::move(d));
        }
        return false;
    }
    return loadLegacySmokeText(text, path, out, diags);
}

bool loadLegacySmoke(const std::string& path, std::vector<LegacySmokeDesc>* out, std::string* error) {
    fx::Diagnostics diags;
    if (loadLegacySmoke(path, out, &diags)) return true;
    error->clear();
    for (size_t i = 0; i < diags.size(); ++i) *error += (i ? "\n" : "") + diags[i].str();
    if (error->empty()) *error = path + ": legacy smoke file could not be loaded";
    return false;
}

}  // namespace cube
