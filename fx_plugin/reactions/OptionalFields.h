#pragma once
// The reaction schema's optional fields (ReactionSchema.cpp): a key of a map that may be absent
// (the default stays) and, when given, is checked like YamlCheck checks a required one, with the
// key's path in the message. Each returns or sets nothing for an absent key.
#include <string>
#include <vector>

#include "reactions/YamlCheck.h"

namespace fx {
namespace schema {

inline std::string joined(const std::vector<std::string>& words) {
    std::string list;
    for (const std::string& w : words) list += (list.empty() ? "" : "|") + w;
    return list;
}

inline std::string indexed(const std::string& path, size_t i) {
    return path + "[" + std::to_string(i) + "]";
}

// An optional number: absent keeps the default; returns false only when given and invalid.
inline bool optNumber(YamlCheck& c, const MapReader& m, const char* key, double lo, double hi,
               float* out) {
    const YAML::Node* n = m.get(key);
    return !n || c.number(*n, m.path(key), lo, hi, out);
}

inline bool optInteger(YamlCheck& c, const MapReader& m, const char* key, long long lo, long long hi,
                int* out) {
    const YAML::Node* n = m.get(key);
    return !n || c.integer(*n, m.path(key), lo, hi, out);
}

// `[min, max]` (or one number meaning [v, v]), each in [lo, hi], min <= max.
inline void optRange(YamlCheck& c, const MapReader& m, const char* key, double lo, double hi,
              float* outMin, float* outMax) {
    const YAML::Node* n = m.get(key);
    if (!n) return;
    const std::string p = m.path(key);
    if (n->IsScalar()) {
        float v = 0.0f;
        if (c.number(*n, p, lo, hi, &v)) *outMin = *outMax = v;
        return;
    }
    if (!c.isList(*n, p, 2, 2)) return;
    float v[2] = {*outMin, *outMax};
    bool ok = true;
    size_t i = 0;
    for (auto it = n->begin(); it != n->end(); ++it, ++i) ok = c.number(*it, indexed(p, i), lo, hi, &v[i]) && ok;
    if (!ok) return;
    if (v[0] > v[1]) {
        c.report(ErrorCode::OutOfRange, n->Mark(), p,
                 "expected [min, max] with min <= max, got [" + std::to_string(v[0]) + ", " +
                     std::to_string(v[1]) + "]");
        return;
    }
    *outMin = v[0];
    *outMax = v[1];
}

template <class Enum>
void optChoice(YamlCheck& c, const MapReader& m, const char* key,
               const std::vector<std::string>& words, Enum first, Enum* out) {
    const YAML::Node* n = m.get(key);
    int i = 0;
    if (n && c.choice(*n, m.path(key), words, &i)) {
        *out = static_cast<Enum>(static_cast<int>(first) + i);
    }
}

}  // namespace schema
}  // namespace fx
