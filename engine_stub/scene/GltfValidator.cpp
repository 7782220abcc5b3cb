#include "scene/GltfValidator.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cstdio>

#include "scene/GltfCommon.h"

namespace cube::gltf {

namespace {

using Json = nlohmann::json;

// A value as it appears in the file, short, never throwing on bad UTF-8.
std::string show(const Json& v) {
    const std::string s = v.dump(-1, ' ', false, Json::error_handler_t::replace);
    return s.size() <= 40 ? s : s.substr(0, 37) + "...";
}

// What a required extension is, for the message (users know "Draco", not the identifier).
const char* extensionHint(const std::string& name) {
    if (name == "KHR_draco_mesh_compression") return " (Draco mesh compression)";
    if (name == "EXT_meshopt_compression") return " (meshoptimizer compression)";
    if (name == "KHR_mesh_quantization") return " (quantized vertex attributes)";
    if (name == "KHR_texture_basisu") return " (Basis Universal textures)";
    if (name == "EXT_texture_webp") return " (WebP textures)";
    return "";
}

std::string percentDecoded(const std::string& s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '%' && i + 2 < s.size() && std::isxdigit(static_cast<unsigned char>(s[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(s[i + 2]))) {
            out += char(std::stoi(s.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

// External files must sit in the model's folder or below it: no absolute path, no scheme, no
// ".." segment (also when percent-encoded). Empty when the uri is acceptable.
std::string uriProblem(const std::string& raw) {
    if (raw.compare(0, 5, "data:") == 0) return "";
    const std::string uri = percentDecoded(raw);
    if (uri.empty()) return "is empty";
    if (uri[0] == '/' || uri[0] == '\\') return "is an absolute path";
    const size_t colon = uri.find(':');
    if (colon != std::string::npos && uri.find('/') > colon) return "has a scheme (only relative paths and data: URIs)";
    size_t start = 0;
    for (;;) {
        const size_t end = uri.find_first_of("/\\", start);
        if (uri.compare(start, end == std::string::npos ? std::string::npos : end - start, "..") == 0 &&
            (end == std::string::npos ? uri.size() - start : end - start) == 2)
            return "has a '..' segment";
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return "";
}

class Validator {
public:
    Validator(const std::string& path, SceneError* error, std::vector<std::string>* warnings)
        : path_(path), error_(error), warnings_(warnings) {}

    bool run(const Json& root) {
        if (!root.is_object()) return bad(SceneErrorCode::ParseError, "TYPE_MISMATCH", "the top level is not a JSON object");
        return asset(root) && extensions(root) && arrays(root) && nodes(root) && uris(root, "buffers") &&
               uris(root, "images") && ignored(root);
    }

private:
    bool bad(SceneErrorCode code, const char* rule, const std::string& detail) {
        // `rule`: the Khronos glTF-Validator issue code, or "" for this loader's own limits.
        return fail(path_, error_, code, *rule ? detail + " [" + rule + "]" : detail);
    }
    void warn(const std::string& text) {
        if (warnings_) warnings_->push_back(path_ + ": " + text);
    }

    bool asset(const Json& root) {
        const auto a = root.find("asset");
        if (a == root.end() || !a->is_object())
            return bad(SceneErrorCode::InvalidGltf, "UNDEFINED_PROPERTY", "has no 'asset' object, expected {\"version\": \"2.0\"}");
        const auto v = a->find("version");
        if (v == a->end() || !v->is_string())
            return bad(SceneErrorCode::InvalidGltf, "UNDEFINED_PROPERTY", "asset.version is missing, expected \"2.0\"");
        const std::string s = v->get<std::string>();
        int major = -1, minor = -1;
        char tail = 0;
        if (std::sscanf(s.c_str(), "%d.%d%c", &major, &minor, &tail) != 2 || major < 0 || minor < 0)
            return bad(SceneErrorCode::InvalidGltf, "PATTERN_MISMATCH", "asset.version is '" + s + "', expected <major>.<minor> such as \"2.0\"");
        if (major != 2)
            return bad(SceneErrorCode::InvalidGltf, "UNKNOWN_ASSET_MAJOR_VERSION",
                       "asset.version is '" + s + "': this loader reads glTF 2.x only");
        const auto mv = a->find("minVersion");
        if (mv != a->end() && (!mv->is_string() || mv->get<std::string>() != "2.0"))
            return bad(SceneErrorCode::Unsupported, "UNKNOWN_ASSET_MINOR_VERSION",
                       "asset.minVersion is " + show(*mv) + ": this loader implements glTF 2.0");
        return true;
    }

    bool extensions(const Json& root) {
        std::vector<std::string> used, required;
        for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
            const auto it = root.find(key);
            if (it == root.end()) continue;
            if (!it->is_array()) return bad(SceneErrorCode::InvalidGltf, "TYPE_MISMATCH", std::string(key) + " is not an array of names");
            for (const Json& e : *it) {
                if (!e.is_string()) return bad(SceneErrorCode::InvalidGltf, "ARRAY_TYPE_MISMATCH", std::string(key) + " holds a non-string " + show(e));
                (key[10] == 'U' ? used : required).push_back(e.get<std::string>());
            }
        }
        if (!required.empty()) {
            std::string names;
            for (const std::string& r : required) names += (names.empty() ? "'" : ", '") + r + "'" + extensionHint(r);
            return bad(SceneErrorCode::Unsupported, "UNSUPPORTED_EXTENSION",
                       "requires extension " + names + ", which this loader does not support; "
                       "re-export the model without it");
        }
        for (const std::string& u : used) warn("extension '" + u + "' is used but not supported; ignored");
        return true;
    }

    bool arrays(const Json& root) {
        for (const char* key : {"accessors", "animations", "buffers", "bufferViews", "cameras", "images", "materials",
                                "meshes", "nodes", "samplers", "scenes", "skins", "textures"}) {
            const auto it = root.find(key);
            if (it == root.end()) continue;
            if (!it->is_array()) return bad(SceneErrorCode::InvalidGltf, "TYPE_MISMATCH", std::string("'") + key + "' is not an array");
            for (size_t i = 0; i < it->size(); ++i) {
                if (!(*it)[i].is_object())
                    return bad(SceneErrorCode::InvalidGltf, "TYPE_MISMATCH",
                               std::string(key) + "[" + std::to_string(i) + "] is not an object");
            }
        }
        return true;
    }

    bool numbers(const Json& n, const std::string& label, const char* field, size_t want) {
        const auto it = n.find(field);
        if (it == n.end()) return true;
        if (!it->is_array())
            return bad(SceneErrorCode::BadNode, "TYPE_MISMATCH", label + " " + field + " is " + show(*it) +
                                                                     ", expected an array of " + std::to_string(want) + " numbers");
        if (it->size() != want)
            return bad(SceneErrorCode::BadNode, "ARRAY_LENGTH_NOT_IN_LIST", label + " " + field + " has " +
                                                                                std::to_string(it->size()) + " numbers, expected " +
                                                                                std::to_string(want));
        for (size_t k = 0; k < it->size(); ++k) {
            if (!(*it)[k].is_number())
                return bad(SceneErrorCode::BadNode, "ARRAY_TYPE_MISMATCH", label + " " + field + "[" + std::to_string(k) + "] is " +
                                                                         show((*it)[k]) + ", expected a number");
        }
        return true;
    }

    bool nodes(const Json& root) {
        const auto it = root.find("nodes");
        if (it == root.end()) return true;
        if (it->size() > kMaxNodes)
            return bad(SceneErrorCode::TooLarge, "", "has " + std::to_string(it->size()) +
                                                                   " nodes, expected at most " + std::to_string(kMaxNodes));
        if (!hierarchyDepth(*it)) return false;
        for (size_t i = 0; i < it->size(); ++i) {
            const Json& n = (*it)[i];
            const auto name = n.find("name");
            const std::string label = "node " + std::to_string(i) +
                                      (name != n.end() && name->is_string() ? " ('" + name->get<std::string>() + "')" : "");
            if (!numbers(n, label, "matrix", 16) || !numbers(n, label, "translation", 3) ||
                !numbers(n, label, "rotation", 4) || !numbers(n, label, "scale", 3))
                return false;
            if (n.contains("matrix") && (n.contains("translation") || n.contains("rotation") || n.contains("scale")))
                return bad(SceneErrorCode::BadNode, "NODE_MATRIX_TRS",
                           label + " has both 'matrix' and translation/rotation/scale, expected one or the other");
            const auto children = n.find("children");
            if (children != n.end()) {
                if (!children->is_array())
                    return bad(SceneErrorCode::BadNode, "TYPE_MISMATCH", label + " children is not an array of node indices");
                for (const Json& c : *children) {
                    if (!c.is_number_integer())
                        return bad(SceneErrorCode::BadNode, "ARRAY_TYPE_MISMATCH",
                                   label + " children holds " + show(c) + ", expected node indices");
                }
            }
            for (const char* ref : {"mesh", "camera", "skin"}) {
                const auto r = n.find(ref);
                if (r != n.end() && !r->is_number_integer())
                    return bad(SceneErrorCode::BadNode, "TYPE_MISMATCH",
                               label + " " + ref + " is " + show(*r) + ", expected an index");
            }
        }
        return true;
    }

    // The depth limit before tinygltf builds a model of a 100,000-level chain. Linear: each node's
    // depth is set once, from the first ancestor whose depth is known. Bad indices, second
    // parents and cycles are left to SceneAssembler, which names them.
    bool hierarchyDepth(const Json& nodes) {
        const size_t count = nodes.size();
        std::vector<int> parent(count, -1);
        for (size_t i = 0; i < count; ++i) {
            const auto children = nodes[i].find("children");
            if (children == nodes[i].end() || !children->is_array()) continue;
            for (const Json& c : *children) {
                if (!c.is_number_integer()) continue;
                const long long k = c.get<long long>();
                if (k >= 0 && size_t(k) < count && parent[size_t(k)] == -1 && size_t(k) != i) parent[size_t(k)] = int(i);
            }
        }
        std::vector<int> depth(count, 0);  // 0 = not known yet; roots are 1
        std::vector<char> onChain(count, 0);
        std::vector<size_t> chain;
        for (size_t i = 0; i < count; ++i) {
            chain.clear();
            int j = int(i);
            while (j >= 0 && depth[size_t(j)] == 0 && !onChain[size_t(j)]) {
                onChain[size_t(j)] = 1;
                chain.push_back(size_t(j));
                j = parent[size_t(j)];
            }
            // Reached a node on this chain (a cycle) or one known to be in or under a cycle (-1):
            // no depth to give; SceneAssembler reports the cycle.
            const bool cycle = j >= 0 && (depth[size_t(j)] == 0 || depth[size_t(j)] < 0);
            int d = j >= 0 && !cycle ? depth[size_t(j)] : 0;
            for (auto k = chain.rbegin(); k != chain.rend(); ++k) {
                d = cycle ? -1 : d + 1;
                depth[*k] = d;
                onChain[*k] = 0;
                if (d > kMaxHierarchyDepth) {
                    return bad(SceneErrorCode::TooDeep, "",
                               "node " + std::to_string(*k) + " is " + std::to_string(d) +
                                   " levels below its root; expected at most " + std::to_string(kMaxHierarchyDepth) +
                                   " levels of node hierarchy");
                }
            }
        }
        return true;
    }

    bool uris(const Json& root, const char* key) {
        const auto it = root.find(key);
        if (it == root.end()) return true;
        for (size_t i = 0; i < it->size(); ++i) {
            const auto u = (*it)[i].find("uri");
            if (u == (*it)[i].end()) continue;
            if (!u->is_string()) return bad(SceneErrorCode::InvalidGltf, "TYPE_MISMATCH", std::string(key) + "[" + std::to_string(i) + "].uri is not a string");
            const std::string uri = u->get<std::string>();
            const std::string why = uriProblem(uri);
            if (!why.empty())
                return bad(SceneErrorCode::BadUri, "INVALID_URI",
                           std::string(key) + "[" + std::to_string(i) + "].uri '" + shortUri(uri) + "' " + why +
                               "; expected a file in the model's folder or below it");
        }
        return true;
    }

    // Valid glTF this loader reads past: each named once, so nobody wonders where it went.
    bool ignored(const Json& root) {
        const struct {
            const char* key;
            const char* what;
        } features[] = {{"textures", "texture(s) ignored: surfaces use baseColorFactor only"},
                        {"skins", "skin(s) ignored: meshes are drawn in their bind pose"},
                        {"animations", "animation(s) ignored: the model is static"},
                        {"cameras", "camera(s) ignored: the game places its own"}};
        for (const auto& f : features) {
            const auto it = root.find(f.key);
            if (it != root.end() && !it->empty()) warn(std::to_string(it->size()) + " " + f.what);
        }
        return true;
    }

    const std::string& path_;
    SceneError* error_;
    std::vector<std::string>* warnings_;
};

}  // namespace

bool checkJsonNesting(const std::string& path, const char* json, size_t size, int maxDepth,
                      SceneError* error) {
    int depth = 0;
    bool inString = false;
    size_t line = 1;
    for (size_t i = 0; i < size; ++i) {
        const char c = json[i];
        if (c == '\n') ++line;
        if (inString) {
            if (c == '\\') ++i;  // the escaped character cannot end the string
            else if (c == '"') inString = false;
            continue;
        }
        if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > maxDepth) {
                return fail(path, error, SceneErrorCode::TooDeep,
                            "line " + std::to_string(line) + ": JSON nested deeper than " +
                                std::to_string(maxDepth) + " levels; expected glTF's shallow structure (is `extras` "
                                "generated?)");
            }
        } else if (c == ']' || c == '}') {
            if (depth > 0) --depth;
        }
    }
    return true;
}

bool validateGltfJson(const std::string& path, const char* json, size_t size, SceneError* error,
                      std::vector<std::string>* warnings) {
    const Json root = Json::parse(json, json + size, nullptr, /*allow_exceptions=*/false);
    if (root.is_discarded()) return true;  // tinygltf reports the syntax error
    return Validator(path, error, warnings).run(root);
}

}  // namespace cube::gltf
