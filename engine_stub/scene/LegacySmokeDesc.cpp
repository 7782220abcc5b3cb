#include "scene/LegacySmokeDesc.h"

#include <cmath>
#include <set>

#include <yaml-cpp/yaml.h>

namespace cube {

namespace {

std::string where(const std::string& file, const YAML::Node& n) {
    const YAML::Mark m = n.Mark();
    return file + ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1);
}

bool readFloat(const std::string& file, const YAML::Node& n, const char* key, float lo, float hi,
               float* out, std::string* error) {
    try {
        double v = n.as<double>();
        if (!std::isfinite(v) || v < lo || v > hi) {
            *error = where(file, n) + ": " + key + ": expected a number in [" + std::to_string(lo) +
                     ", " + std::to_string(hi) + "]";
            return false;
        }
        *out = float(v);
        return true;
    } catch (const YAML::Exception&) {
        *error = where(file, n) + ": " + key + ": expected a number";
        return false;
    }
}

}  // namespace

namespace {
// Reads every reaction of the 'reactions' list; may throw YAML::Exception (caught by the caller).
bool readReactions(const std::string& path, const YAML::Node& list, std::vector<LegacySmokeDesc>* out,
                   std::string* error);
}  // namespace

bool loadLegacySmoke(const std::string& path, std::vector<LegacySmokeDesc>* out, std::string* error) {
    YAML::Node root;
    try {
        root = YAML::LoadFile(path);
    } catch (const YAML::BadFile&) {
        *error = path + ": cannot open the legacy smoke file";
        return false;
    } catch (const YAML::Exception& e) {
        *error = path + ":" + std::to_string(e.mark.line + 1) + ": " + e.msg;
        return false;
    }
    if (!root.IsMap()) {
        *error = path + ": expected a map with a 'reactions' list";
        return false;
    }
    const YAML::Node list = root["reactions"];
    if (!list || !list.IsSequence()) {
        *error = path + ": expected a map with a 'reactions' list";
        return false;
    }
    try {
        return readReactions(path, list, out, error);
    } catch (const YAML::Exception& e) {
        *error = path + ":" + std::to_string(e.mark.line + 1) + ": " + e.msg;
        return false;
    }
}

namespace {
bool readReactions(const std::string& path, const YAML::Node& list, std::vector<LegacySmokeDesc>* out,
                   std::string* error) {
    std::vector<LegacySmokeDesc> result;
    for (const YAML::Node& r : list) {
        if (!r.IsMap()) {
            *error = where(path, r) + ": expected a reaction map";
            return false;
        }
        LegacySmokeDesc d;
        for (const auto& kv : r) {
            const std::string key = kv.first.Scalar();
            const YAML::Node& v = kv.second;
            bool ok = true;
            float size[2];
            if (key == "name") d.name = v.Scalar();
            else if (key == "wheels") {
                d.wheels = v.Scalar();
                if (d.wheels != "rear" && d.wheels != "front" && d.wheels != "all") {
                    *error = where(path, v) + ": wheels: expected rear, front or all";
                    return false;
                }
            } else if (key == "slip_threshold") ok = readFloat(path, v, "slip_threshold", 0, 1, &d.slipThreshold, error);
            else if (key == "rate") ok = readFloat(path, v, "rate", 0, 10000, &d.rate, error);
            else if (key == "capacity") {
                float c = 0;
                ok = readFloat(path, v, "capacity", 1, 100000, &c, error);
                d.capacity = int(c);
            } else if (key == "lifetime") ok = readFloat(path, v, "lifetime", 0.01f, 60, &d.lifetime, error);
            else if (key == "size") {
                if (!v.IsSequence() || v.size() != 2) {
                    *error = where(path, v) + ": size: expected [start, end] in metres";
                    return false;
                }
                ok = readFloat(path, v[0], "size[0]", 0.01f, 100, &size[0], error) &&
                     readFloat(path, v[1], "size[1]", 0.01f, 100, &size[1], error);
                d.startSize = size[0];
                d.endSize = size[1];
            } else if (key == "rise_speed") ok = readFloat(path, v, "rise_speed", -10, 10, &d.riseSpeed, error);
            else if (key == "hover") ok = readFloat(path, v, "hover", 0, 10, &d.hover, error);
            else if (key == "alpha") ok = readFloat(path, v, "alpha", 0, 1, &d.alpha, error);
            else if (key == "tint") {
                if (!v.IsSequence() || v.size() != 3) {
                    *error = where(path, v) + ": tint: expected [r, g, b] in 0..1";
                    return false;
                }
                for (int i = 0; i < 3 && ok; ++i) ok = readFloat(path, v[i], "tint", 0, 1, &d.tint[i], error);
            } else {
                *error = where(path, kv.first) + ": unknown key '" + key + "'";
                return false;
            }
            if (!ok) return false;
        }
        if (d.name.empty()) {
            *error = where(path, r) + ": a reaction needs a name";
            return false;
        }
        result.push_back(d);
    }
    *out = std::move(result);
    return true;
}
}  // namespace

}  // namespace cube
