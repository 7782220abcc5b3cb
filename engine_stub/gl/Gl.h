#pragma once
// The engine's single way to see GL: glad's 3.3 core loader (with KHR_debug, ARB_timer_query).
#include <glad/gl.h>

#include <string>

namespace cube::gl {

/// GL errors and KHR_debug messages of severity HIGH/MEDIUM seen since start-up. Tests assert
/// this stays 0; debug builds also print each message.
int errorCount();
/// Last such message (empty if none).
std::string lastError();
/// Drains glGetError() and adds what it finds to errorCount(); returns how many were pending.
int checkErrors(const char* where);
void resetErrorCount();
/// True when the context has KHR_debug (groups, labels, callback).
bool hasDebug();
/// Waits for every GL command issued so far (frame timing with a CPU clock).
void finish();

/// RAII GL debug group: the pass, bucket or view name shows in debuggers (RenderDoc, apitrace).
class DebugGroup {
public:
    explicit DebugGroup(const char* name);
    ~DebugGroup();
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
};

}  // namespace cube::gl
