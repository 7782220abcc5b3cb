#include "fx/Api.h"

// The version of this library, as opposed to fx::kApiVersion, which is the version of the headers
// a host was compiled against.
extern "C" uint32_t fxApiVersion() { return fx::kApiVersion; }
