#pragma once
// Small helpers the tweak panel's files share (TweakPanel.cpp, TweakPanelRamp.cpp): key names,
// YAML flow values and the schema tooltip. Panel-internal.
#include <cstdio>
#include <string>

#include <imgui.h>
#include <yaml-cpp/yaml.h>

#include "fx/Plugin.h"

namespace cube::panel {

// A printf format showing `unit` after the number ('%' in a unit doubled).
inline std::string numberFormat(const char* number, const std::string& unit) {
    std::string f = number;
    if (unit.empty()) return f;
    f += " ";
    for (char c : unit) f += c == '%' ? std::string("%%") : std::string(1, c);
    return f;
}

inline std::string shortKey(const std::string& key) {
    const size_t dot = key.rfind('.');
    return dot == std::string::npos ? key : key.substr(dot + 1);
}

inline std::string section(const std::string& key) {
    const size_t dot = key.find('.');
    return dot == std::string::npos ? std::string() : key.substr(0, dot);
}

inline std::string baseName(const std::string& path) {
    const size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

inline YAML::Node parseValue(const std::string& text) {
    try {
        return YAML::Load(text);
    } catch (const YAML::Exception&) {
        return YAML::Node();
    }
}

inline float asFloat(const YAML::Node& n, float fallback = 0.0f) {
    try {
        return n && n.IsScalar() ? n.as<float>() : fallback;
    } catch (const YAML::Exception&) {
        return fallback;
    }
}

inline void tooltip(const fx::ReactionKeyInfo& info) {
    if (!ImGui::IsItemHovered()) return;
    std::string range;
    char buf[96];
    switch (info.kind) {
        case fx::ReactionKeyInfo::Kind::Number:
        case fx::ReactionKeyInfo::Kind::Integer:
        case fx::ReactionKeyInfo::Kind::NumberRange:
            std::snprintf(buf, sizeof buf, "range [%g, %g]", info.min, info.max);
            range = buf;
            break;
        case fx::ReactionKeyInfo::Kind::ChoiceList:
        case fx::ReactionKeyInfo::Kind::ColorRamp:
            std::snprintf(buf, sizeof buf, "%g to %g entries", info.min, info.max);
            range = buf;
            break;
        default: break;
    }
    if (!info.unit.empty()) range += (range.empty() ? "unit: " : ", unit: ") + info.unit;
    ImGui::SetTooltip("%s\n%s%s%s", info.key.c_str(), info.help.c_str(), range.empty() ? "" : "\n", range.c_str());
}

}  // namespace cube::panel
