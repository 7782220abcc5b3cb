#include "YamlCheck.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "reactions/ReactionDesc.h"

namespace fx {
namespace {

// yaml-cpp gives plain scalars the tag "?" and quoted ones "!"; an explicit !!str also means text.
bool isText(const YAML::Node& node) {
    const std::string& tag = node.Tag();
    return tag == "!" || tag == "tag:yaml.org,2002:str";
}

std::string trimmed(const std::string& s) {
    size_t b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return std::string();
    size_t e = s.find_last_not_of(" \t");
    return s.substr(b, e - b + 1);
}

// The YAML 1.2 spellings of the non-finite floats (and the C ones from_chars would accept).
bool isNonFiniteWord(std::string s) {
    if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.erase(0, 1);
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) {
        return static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    });
    return s == ".nan" || s == ".inf" || s == "nan" || s == "inf" || s == "infinity" ||
           s.rfind("nan(", 0) == 0;
}

std::string formatNumber(double v) {
    std::ostringstream o;
    o << v;
    return o.str();
}

std::string rangeText(double lo, double hi) {
    return "[" + formatNumber(lo) + ", " + formatNumber(hi) + "]";
}

enum class NumberParse { Ok, NotNumber, NotFinite, Overflow };

NumberParse parseDouble(const std::string& text, double* out) {
    std::string s = trimmed(text);
    if (isNonFiniteWord(s)) return NumberParse::NotFinite;
    const char* b = s.data();
    const char* e = s.data() + s.size();
    if (b != e && *b == '+') ++b;
    if (b == e) return NumberParse::NotNumber;
    double v = 0.0;
    auto r = std::from_chars(b, e, v, std::chars_format::general);
    if (r.ptr != e) return NumberParse::NotNumber;
    if (r.ec == std::errc::result_out_of_range) return NumberParse::Overflow;
    if (r.ec != std::errc()) return NumberParse::NotNumber;
    if (!std::isfinite(v)) return NumberParse::NotFinite;
    *out = v;
    return NumberParse::Ok;
}

}  // namespace

YamlCheck::YamlCheck(std::string file, Diagnostics* out) : file_(std::move(file)), out_(out) {}

void YamlCheck::report(ErrorCode code, const YAML::Mark& mark, const std::string& key,
                       const std::string& message) {
    ++errors_;
    if (!out_ || reported_ > kMaxDiagnosticsPerFile) return;
    Diagnostic d;
    d.file = file_;
    if (reported_ == kMaxDiagnosticsPerFile) {
        d.code = ErrorCode::TooManyErrors;
        d.message = "more than " + std::to_string(kMaxDiagnosticsPerFile) +
                    " errors; the rest of this file is not listed";
    } else {
        d.code = code;
        d.line = mark.line >= 0 ? mark.line + 1 : 0;
        d.column = mark.column >= 0 ? mark.column + 1 : 0;
        d.key = key;
        d.message = message;
    }
    ++reported_;
    out_->push_back(std::move(d));
}

int YamlCheck::levelOf(const std::string& key) {
    if (key.empty()) return 0;
    int level = 1;
    for (char c : key) level += (c == '.' || c == '[') ? 1 : 0;
    return level;
}

int YamlCheck::subtreeDepth(const YAML::Node& node, int limit) {
    // Iterative: an explicit stack, no recursion, and a visit budget so an alias-heavy document
    // (a DAG that expands exponentially) costs a bounded amount of work.
    constexpr int kVisitBudget = 20000;
    std::vector<std::pair<YAML::Node, int>> stack;
    stack.emplace_back(node, 0);
    int deepest = 0;
    int visits = 0;
    while (!stack.empty() && visits < kVisitBudget) {
        YAML::Node n = stack.back().first;
        int depth = stack.back().second;
        stack.pop_back();
        ++visits;
        if (!n.IsMap() && !n.IsSequence()) continue;
        deepest = std::max(deepest, depth + 1);
        if (deepest > limit) return deepest;
        for (auto it = n.begin(); it != n.end(); ++it) {
            if (n.IsMap()) {
                stack.emplace_back(it->first, depth + 1);
                stack.emplace_back(it->second, depth + 1);
            } else {
                stack.emplace_back(*it, depth + 1);
            }
        }
    }
    return deepest;
}

std::string YamlCheck::describe(const YAML::Node& node) {
    switch (node.Type()) {
    case YAML::NodeType::Map: return "a map";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Null: return "nothing";
    case YAML::NodeType::Undefined: return "nothing";
    case YAML::NodeType::Scalar: break;
    }
    const std::string& s = node.Scalar();
    std::string r = "'";
    constexpr size_t kShown = 40;
    for (size_t i = 0; i < s.size() && i < kShown; ++i) {
        unsigned char c = static_cast<unsigned char>(s[i]);
        if (c < 0x20 || c == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", c);
            r += buf;
        } else {
            r += static_cast<char>(c);
        }
    }
    if (s.size() > kShown) r += "...";
    return r + "'";
}

void YamlCheck::wrongType(const YAML::Node& node, const std::string& key,
                          const std::string& expected) {
    int level = levelOf(key);
    int below = subtreeDepth(node, kMaxNesting - level);
    if (level + below > kMaxNesting) {
        report(ErrorCode::TooDeep, node.Mark(), key,
               "nesting deeper than " + std::to_string(kMaxNesting) + " levels; expected " +
                   expected);
        return;
    }
    report(ErrorCode::WrongType, node.Mark(), key,
           "expected " + expected + ", got " + describe(node));
}

bool YamlCheck::isMap(const YAML::Node& node, const std::string& key) {
    if (node.IsMap()) return true;
    wrongType(node, key, "a map");
    return false;
}

bool YamlCheck::isList(const YAML::Node& node, const std::string& key, size_t minCount,
                       size_t maxCount) {
    std::string expected = minCount == maxCount
                               ? "a list of " + std::to_string(minCount)
                               : "a list of " + std::to_string(minCount) + " to " +
                                     std::to_string(maxCount);
    if (!node.IsSequence()) {
        wrongType(node, key, expected + " entries");
        return false;
    }
    size_t n = node.size();
    if (n < minCount || n > maxCount) {
        report(ErrorCode::OutOfRange, node.Mark(), key,
               "expected " + expected + " entries, got " + std::to_string(n));
        return false;
    }
    return true;
}

bool YamlCheck::number(const YAML::Node& node, const std::string& key, double lo, double hi,
                       float* out) {
    const std::string expected = "a number in " + rangeText(lo, hi);
    if (!node.IsScalar() || isText(node)) {
        wrongType(node, key, expected);
        return false;
    }
    double v = 0.0;
    switch (parseDouble(node.Scalar(), &v)) {
    case NumberParse::Ok: break;
    case NumberParse::NotNumber:
        wrongType(node, key, expected);
        return false;
    case NumberParse::NotFinite:
        report(ErrorCode::NotFinite, node.Mark(), key,
               "expected a finite number in " + rangeText(lo, hi) + ", got " + describe(node));
        return false;
    case NumberParse::Overflow:
        report(ErrorCode::OutOfRange, node.Mark(), key,
               "expected " + expected + ", got " + describe(node));
        return false;
    }
    if (!(v >= lo && v <= hi)) {
        report(ErrorCode::OutOfRange, node.Mark(), key,
               "expected " + expected + ", got " + describe(node));
        return false;
    }
    *out = static_cast<float>(v);
    return true;
}

bool YamlCheck::integer(const YAML::Node& node, const std::string& key, long long lo,
                        long long hi, int* out) {
    const std::string expected =
        "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!node.IsScalar() || isText(node)) {
        wrongType(node, key, expected);
        return false;
    }
    std::string s = trimmed(node.Scalar());
    const char* b = s.data();
    const char* e = s.data() + s.size();
    if (b != e && *b == '+') ++b;
    bool negative = b != e && *b == '-';
    long long v = 0;
    auto r = std::from_chars(b, e, v);
    if (r.ptr != e || b == e) {
        double d = 0.0;
        NumberParse p = parseDouble(s, &d);
        if (p == NumberParse::NotFinite) {
            report(ErrorCode::NotFinite, node.Mark(), key,
                   "expected " + expected + ", got " + describe(node));
        } else if (p == NumberParse::Ok && d < 0.0 && lo >= 0) {
            report(ErrorCode::NegativeCount, node.Mark(), key,
                   "expected " + expected + ", got the negative " + describe(node));
        } else {
            wrongType(node, key, expected);
        }
        return false;
    }
    if (r.ec == std::errc::result_out_of_range || v < lo || v > hi) {
        if (negative && lo >= 0) {
            report(ErrorCode::NegativeCount, node.Mark(), key,
                   "expected " + expected + ", got the negative " + describe(node));
        } else {
            report(ErrorCode::OutOfRange, node.Mark(), key,
                   "expected " + expected + ", got " + describe(node));
        }
        return false;
    }
    *out = static_cast<int>(v);
    return true;
}

bool YamlCheck::boolean(const YAML::Node& node, const std::string& key, bool* out) {
    if (node.IsScalar() && !isText(node)) {
        std::string s = trimmed(node.Scalar());
        if (s == "true" || s == "True" || s == "TRUE") {
            *out = true;
            return true;
        }
        if (s == "false" || s == "False" || s == "FALSE") {
            *out = false;
            return true;
        }
    }
    wrongType(node, key, "true or false");
    return false;
}

bool YamlCheck::choice(const YAML::Node& node, const std::string& key,
                       const std::vector<std::string>& words, int* out) {
    std::string list;
    for (const std::string& w : words) list += (list.empty() ? "" : "|") + w;
    if (!node.IsScalar()) {
        wrongType(node, key, "one of " + list);
        return false;
    }
    int i = 0;
    for (const std::string& w : words) {
        if (node.Scalar() == w) {
            *out = i;
            return true;
        }
        ++i;
    }
    report(ErrorCode::InvalidEnum, node.Mark(), key,
           "expected one of " + list + ", got " + describe(node));
    return false;
}

bool YamlCheck::name(const YAML::Node& node, const std::string& key, std::string* out) {
    const char* expected = "a name of 1-64 characters from A-Z a-z 0-9 _ - .";
    if (!node.IsScalar()) {
        wrongType(node, key, expected);
        return false;
    }
    const std::string& s = node.Scalar();
    bool ok = !s.empty() && s.size() <= 64;
    for (char c : s) {
        ok = ok && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.');
    }
    if (!ok) {
        report(ErrorCode::WrongType, node.Mark(), key,
               std::string("expected ") + expected + ", got " + describe(node));
        return false;
    }
    *out = s;
    return true;
}

MapReader::MapReader(YamlCheck& check, const YAML::Node& map, std::string mapPath,
                     std::initializer_list<const char*> known)
    : path_(std::move(mapPath)) {
    std::vector<std::pair<std::string, YAML::Mark>> seen;
    for (auto it = map.begin(); it != map.end(); ++it) {
        const YAML::Node k = it->first;  // a copy: it-> yields a temporary proxy
        if (!k.IsScalar()) {
            check.report(ErrorCode::UnknownKey, k.Mark(), path_,
                         "expected a key word, got " + YamlCheck::describe(k));
            continue;
        }
        const std::string& word = k.Scalar();
        std::string where = path(word.c_str());
        auto dup = std::find_if(seen.begin(), seen.end(),
                                [&](const auto& s) { return s.first == word; });
        if (dup != seen.end()) {
            check.report(ErrorCode::DuplicateKey, k.Mark(), where,
                         "key given twice (first at line " + std::to_string(dup->second.line + 1) +
                             ")");
            continue;
        }
        seen.emplace_back(word, k.Mark());
        bool isKnown = false;
        std::string list;
        for (const char* w : known) {
            isKnown = isKnown || word == w;
            list += (list.empty() ? "" : ", ") + std::string(w);
        }
        if (!isKnown) {
            check.report(ErrorCode::UnknownKey, k.Mark(), where,
                         "unknown key " + YamlCheck::describe(k) + "; expected one of " + list);
            continue;
        }
        entries_.emplace_back(word, it->second);
    }
}

const YAML::Node* MapReader::get(const char* key) const {
    for (const auto& e : entries_) {
        if (e.first == key) return &e.second;
    }
    return nullptr;
}

std::string MapReader::path(const char* key) const {
    return path_.empty() ? std::string(key) : path_ + "." + key;
}

}  // namespace fx
