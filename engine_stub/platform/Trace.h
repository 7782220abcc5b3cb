#pragma once
// A record of the CUBE call sequence (Init / update / render). Off by default; tests switch it on
// and read it back to check that calls happen in the documented order.
#include <string>
#include <vector>

namespace cube {

class Trace {
public:
    static void enable(bool on);
    static bool enabled();
    static void clear();
    /// Appends `name` when enabled; cheap no-op otherwise.
    static void call(const char* name);
    static const std::vector<std::string>& calls();
};

}  // namespace cube
