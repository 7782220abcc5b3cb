#include "platform/Trace.h"

namespace cube {

namespace {
bool g_on = false;
std::vector<std::string>& store() {
    static std::vector<std::string> s;
    return s;
}
}  // namespace

void Trace::enable(bool on) { g_on = on; }
bool Trace::enabled() { return g_on; }
void Trace::clear() { store().clear(); }
void Trace::call(const char* name) {
    if (g_on && store().size() < 1000000) store().emplace_back(name);
}
const std::vector<std::string>& Trace::calls() { return store(); }

}  // namespace cube
