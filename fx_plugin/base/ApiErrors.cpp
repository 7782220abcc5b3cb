#include "base/ApiErrors.h"

#include <cstdio>
#include <cstring>
#include <mutex>

namespace fx {

ErrorCode ApiErrors::refuse(ErrorCode code, const char* function, const std::string& what) {
    ++count_;
    Seen* entry = nullptr;
    for (Seen& s : seen_) {
        if (s.code == code && std::strcmp(s.function, function) == 0) entry = &s;
    }
    if (!entry) {
        seen_.push_back(Seen{function, code, 0});
        entry = &seen_.back();
    }
    ++entry->times;
    if (!host_ || entry->times > kRepeatsLogged + 1) return code;
    std::string line = std::string("fx: error[") + errorCodeName(code) + "] " + function + ": " + what;
    if (entry->times == kRepeatsLogged + 1) {
        line = std::string("fx: error[") + errorCodeName(code) + "] " + function +
               ": repeated; further occurrences are counted in Stats::apiErrors, not logged";
    }
    host_->log(LogLevel::Error, line.c_str());
    return code;
}

namespace {

class StderrHost final : public HostAdapter {
public:
    void* getProcAddress(const char*) override { return nullptr; }
    int wheelCount() const override { return 0; }
    WheelContact wheel(int) const override { return {}; }
    void log(LogLevel, const char* message) override { std::fprintf(stderr, "%s\n", message); }
};

std::mutex g_withoutHostMutex;

// Never destroyed, like the C table's set of live plugins: a refusal may come from a static
// destructor at exit.
ApiErrors& withoutHost() {
    static auto* errors = new ApiErrors(new StderrHost());
    return *errors;
}

}  // namespace

ErrorCode refuseWithoutHost(ErrorCode code, const char* function, const std::string& what) {
    std::lock_guard<std::mutex> lock(g_withoutHostMutex);
    return withoutHost().refuse(code, function, what);
}

int refusalsWithoutHost() {
    std::lock_guard<std::mutex> lock(g_withoutHostMutex);
    return withoutHost().count();
}

}  // namespace fx
