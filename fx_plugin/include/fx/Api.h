#pragma once
// Versioning and symbol export of the plugin's API.
//
// Versioning policy: the API version is MAJOR.MINOR and equals the CubeFx package version's first
// two numbers. A MINOR release only adds (new virtual functions at the end of an interface, new
// fields at the end of a struct with defaults that keep the old behaviour, new error codes); a
// host built against MAJOR.m runs with any plugin MAJOR.n where n >= m. Anything else is a new
// MAJOR. fxCreatePlugin() refuses a host whose MAJOR differs or whose MINOR is newer than the
// plugin's (ErrorCode::VersionMismatch); fxApiVersion() tells a host at run time which plugin it
// loaded, before it builds any import table. The C++ types cross the boundary (std::string,
// std::function, std::unique_ptr): host and plugin must use the same C++ standard library ABI
// (libstdc++ with the same _GLIBCXX_USE_CXX11_ABI setting).
#include <cstdint>

#if defined(FX_BUILDING_PLUGIN)
#define FX_API __attribute__((visibility("default")))
#else
#define FX_API
#endif

#define FX_API_VERSION_MAJOR 1
#define FX_API_VERSION_MINOR 3

namespace fx {

/// MAJOR << 16 | MINOR of the headers the host is compiled against.
constexpr uint32_t kApiVersion = (uint32_t(FX_API_VERSION_MAJOR) << 16) | uint32_t(FX_API_VERSION_MINOR);
constexpr uint32_t apiVersionMajor(uint32_t version) { return version >> 16; }
constexpr uint32_t apiVersionMinor(uint32_t version) { return version & 0xFFFFu; }

}  // namespace fx

/// The API version of the plugin library actually loaded (MAJOR << 16 | MINOR). Needs no GL
/// context and no plugin instance; safe from any thread.
extern "C" FX_API uint32_t fxApiVersion();
