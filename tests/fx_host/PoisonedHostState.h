#pragma once
// The poisoned host (PoisonedHostTest.cpp): GL state a legacy engine may leave behind, one value
// at a time, each set to a non-default value that would change the plugin's image or its
// uploads if it reached them (an enable comes with the parameters that make it bite: alpha test
// with GREATER 0.5, stencil test with NEVER, cull face with FRONT_AND_BACK). Compatibility-only
// poisons exist only in a compatibility-profile context (osMesaCompatibilityProfile()).
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace fxtest {

struct HostPoison {
    std::string name;
    bool compatibility = false;
    std::function<void()> apply;
};

/// Every poison of the current context's profile.
const std::vector<HostPoison>& hostPoisons();

/// The host state the poisons touch (and a few the plugin must not touch either), read back:
/// name -> values. Compared before and after each plugin call.
using HostStateReadback = std::map<std::string, std::vector<double>>;
HostStateReadback readHostState();
/// "name: before -> after" per differing value; empty when equal.
std::string diffHostState(const HostStateReadback& before, const HostStateReadback& after);

/// GL's initial values for everything the poisons touch (applyDefaultHostState() and the rest).
void resetHostState();

}  // namespace fxtest
