#pragma once
// Lookup by name in fxbench's fixed tables (modes, scenarios): any entry type with a
// `const char* name`.
#include <string>
#include <vector>

namespace fxbench {

/// The entry of `table` called `name`, or null.
template <class T>
const T* findNamed(const std::vector<T>& table, const std::string& name) {
    for (const T& entry : table)
        if (name == entry.name) return &entry;
    return nullptr;
}

/// "a, b, c": the names in table order, for messages and --help.
template <class T>
std::string namedList(const std::vector<T>& table) {
    std::string s;
    for (const T& entry : table) s += (s.empty() ? "" : ", ") + std::string(entry.name);
    return s;
}

}  // namespace fxbench
