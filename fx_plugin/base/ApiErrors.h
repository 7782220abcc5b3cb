#pragma once
// How the plugin refuses an invalid call: the call has no effect, returns the named code, the
// host's log gets "fx: error[Code] function: what was expected" and Stats::apiErrors counts it.
// A host that repeats the same mistake every frame gets the message the first kRepeatsLogged
// times for each (function, code) pair and a count after that, not a flooded log.
#include <cstdint>
#include <string>
#include <vector>

#include "fx/Diagnostic.h"
#include "fx/HostAdapter.h"

namespace fx {

class ApiErrors {
public:
    static constexpr int kRepeatsLogged = 3;

    explicit ApiErrors(HostAdapter* host) : host_(host) {}

    /// Reports one refused call and returns `code` (so callers can `return errors.refuse(...)`).
    ErrorCode refuse(ErrorCode code, const char* function, const std::string& what);
    int count() const { return count_; }

private:
    struct Seen {
        const char* function;
        ErrorCode code;
        int times;
    };
    HostAdapter* host_;
    int count_ = 0;
    std::vector<Seen> seen_;
};

/// Where a refusal goes when no plugin's host can hear it: a descriptor refused by create (which
/// is not read past the check it failed), a null, destroyed or foreign handle. Writes the same
/// "fx: error[Code] function: ..." line to stderr, with the same repeat limit per (function,
/// code), behind a mutex (a dead handle may be used from any thread).
ErrorCode refuseWithoutHost(ErrorCode code, const char* function, const std::string& what);
/// How many refusals refuseWithoutHost has taken in this process.
int refusalsWithoutHost();

}  // namespace fx
