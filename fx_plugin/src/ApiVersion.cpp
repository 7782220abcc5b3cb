// Keeps the library non-empty while its parts are written; holds the API version string.
#include "fx/Plugin.h"

namespace fx {
const char* apiVersionString() { return "fx_plugin api 1"; }
}  // namespace fx
