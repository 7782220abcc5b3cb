#pragma once
// Typed, reporting reads of a yaml-cpp node tree: the validation layer under the reaction schema.
// Every read either stores a value and returns true, or appends one Diagnostic (code, file,
// 1-based line/column from the node's Mark, dotted key, "expected ..., got ..." message) and
// returns false leaving the destination untouched, so the caller keeps its default and goes on to
// report the next problem. Nothing here recurses into data deeper than the schema asks for,
// except subtreeDepth(), which is iterative and bounded.
#include <cstddef>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "fx/Diagnostic.h"

namespace fx {

class YamlCheck {
public:
    /// `out` may be null (errors are still counted).
    YamlCheck(std::string file, Diagnostics* out);

    /// Appends a diagnostic; past kMaxDiagnosticsPerFile it appends one TooManyErrors and then
    /// only counts.
    void report(ErrorCode code, const YAML::Mark& mark, const std::string& key,
                const std::string& message);
    int errors() const { return errors_; }
    const std::string& file() const { return file_; }

    /// Reports WrongType (or TooDeep when the offending value nests past kMaxNesting).
    void wrongType(const YAML::Node& node, const std::string& key, const std::string& expected);

    bool isMap(const YAML::Node& node, const std::string& key);
    /// A list of [minCount, maxCount] entries; OutOfRange when the length is outside.
    bool isList(const YAML::Node& node, const std::string& key, size_t minCount, size_t maxCount);

    /// A finite number in [lo, hi] (plain scalar; quoted strings are text, not numbers).
    bool number(const YAML::Node& node, const std::string& key, double lo, double hi, float* out);
    /// An integer in [lo, hi]; a negative value is NegativeCount when lo >= 0.
    bool integer(const YAML::Node& node, const std::string& key, long long lo, long long hi,
                 int* out);
    bool boolean(const YAML::Node& node, const std::string& key, bool* out);
    /// One of `words` (exact spelling); stores its index.
    bool choice(const YAML::Node& node, const std::string& key,
                const std::vector<std::string>& words, int* out);
    /// A reaction name: 1-64 characters of [A-Za-z0-9_.-].
    bool name(const YAML::Node& node, const std::string& key, std::string* out);

    /// "'fast'", "a map", "a list", "nothing": what a message says it got.
    static std::string describe(const YAML::Node& node);
    /// 1-based nesting level of the value at a dotted key ("" is the document root, level 0).
    static int levelOf(const std::string& key);
    /// Collection levels below `node` (a scalar is 0), counted up to `limit` + 1 and no further;
    /// visits at most a bounded number of nodes (aliases can make a small file a huge tree).
    static int subtreeDepth(const YAML::Node& node, int limit);

private:
    std::string file_;
    Diagnostics* out_;
    size_t reported_ = 0;
    int errors_ = 0;
};

/// The entries of one YAML map, checked once: keys that are not words, keys not in `known`
/// (UnknownKey) and keys given twice (DuplicateKey) are reported on construction.
class MapReader {
public:
    MapReader(YamlCheck& check, const YAML::Node& map, std::string mapPath,
              std::initializer_list<const char*> known);
    /// The value of `key`, or null when the map does not have it.
    const YAML::Node* get(const char* key) const;
    /// "path.key" (or "key" at the root).
    std::string path(const char* key) const;
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::vector<std::pair<std::string, YAML::Node>> entries_;  ///< known keys, first occurrence
};

}  // namespace fx
