#pragma once
// Filling the plugin's private GL table (render/PrivateGl.h). Kept apart from the table's header
// so a test that has its own glad can load the plugin's table too: the two gl.h never meet.
#include <string>

#include "fx/Diagnostic.h"

namespace fx {

class HostAdapter;

/// Loads the table through `host.getProcAddress` if it is not loaded yet. Needs the host's
/// context current. Returns false with the reason in *error when the host hands out no GL 3.3
/// core entry points.
bool loadPrivateGl(HostAdapter& host, std::string* error);
/// Same, from a plain proc-address function (tests and tools that have no HostAdapter).
bool loadPrivateGl(void* (*getProcAddress)(const char* name), std::string* error);
/// A renderer's first step (ParticleRenderer, MegaRenderer): the table through `host` (null: no
/// host). On failure appends the NoGlContext diagnostic to *diagnostics and returns false with the
/// reason in *error, for the renderer's own log line.
bool loadPrivateGlOrDiagnose(HostAdapter* host, Diagnostics* diagnostics, std::string* error);
/// True once a load succeeded. A load succeeds only when every entry point some path of the
/// plugin calls is there (else *error names the null ones); optional features whose entry points
/// are missing (KHR_debug groups, ARB_clip_control) are switched off, one warning line through the
/// host that loaded it.
bool privateGlLoaded();
/// True when the table is loaded and a context is current on this thread (glGetString answers).
bool privateGlContextCurrent();
/// The next load starts over (through whichever host asks next). The entry points stay as they
/// are until then. The C table calls this when its last plugin is destroyed.
void forgetPrivateGl();
/// What the last load switched off ("" = nothing).
const std::string& privateGlSwitchedOff();

}  // namespace fx
