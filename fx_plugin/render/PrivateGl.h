#pragma once
// The plugin's private GL loader: glad's GL 3.3 compatibility-profile table (core plus the
// compatibility-only entry points the state guard uses in a compatibility context, and
// ARB_clip_control) with every symbol renamed (fxglad_*,
// FXGLAD_GL_*; see fx_plugin/cmake/PrivateGlad.cmake), filled only through the host's
// getProcAddress. Plugin code includes this instead of <glad/gl.h> and calls gl* as usual; the
// names cannot clash with a host's own glad, and none of them leaves the library.
#include <fx_glad/gl.h>

#include "render/PrivateGlLoader.h"
