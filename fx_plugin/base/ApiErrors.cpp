#include "base/ApiErrors.h"

#include <cstring>

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

}  // namespace fx
