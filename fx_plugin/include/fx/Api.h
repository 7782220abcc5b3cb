#pragma once
// Versioning of the plugin's API, for the C++ layer (fx/Plugin.h). The boundary itself is C
// (fx/fx.h): the library exports fxApiVersion, fxGetApi and fxErrorCodeName and nothing else;
// every C++ type in include/fx/ lives in these headers only, compiled into the host.
//
// Versioning policy: the API version is MAJOR.MINOR and equals the CubeFx package version's first
// two numbers. A MINOR release only adds (functions at the end of fxApi, fields at the end of a
// descriptor with zero meaning the old behaviour, new error codes); a host built against MAJOR.m
// runs with any plugin MAJOR.n where n >= m. Anything else is a new MAJOR. 2.0 is one: the C++
// entry point fxCreatePlugin is now inline in fx/Plugin.h over the C table, so a host written
// against 1.x compiles unchanged against these headers (PluginImports::apiVersion 1.0 .. 1.3 is
// served by the 2.0 table), but a binary built against 1.x must be rebuilt: the library no
// longer exports C++ symbols.
#include <cstdint>

#include "fx/fx.h"

// No C++ symbol crosses the library boundary any more; kept so 1.x headers' spelling compiles.
#define FX_API

namespace fx {

/// MAJOR << 16 | MINOR of the headers the host is compiled against.
constexpr uint32_t kApiVersion = FX_API_VERSION;
constexpr uint32_t apiVersionMajor(uint32_t version) { return version >> 16; }
constexpr uint32_t apiVersionMinor(uint32_t version) { return version & 0xFFFFu; }
/// The last 1.x minor; a C++ host asking for 1.0 .. this gets the 2.0 table through the C++ layer.
constexpr uint32_t kLastApiVersion1 = (1u << 16) | 3u;

}  // namespace fx
