#pragma once
// The shared text-input library (cube_textio, textio/ at the top level) as the plugin's code
// names it: fxio:: for file reading and the YAML first pass, and the shader loader's names in
// namespace fx, where the plugin's programs use them unqualified. The library is linked into
// libcubefx.so privately; nothing here reaches the public headers.
#include "textio/SafeFile.h"
#include "textio/ShaderSource.h"
#include "textio/YamlPreflight.h"

namespace fxio = textio;

namespace fx {

using textio::ShaderError;
using textio::ShaderReader;
using textio::ShaderSource;
using textio::VersionLine;
using textio::expandShaderSource;
using textio::folderShaderReader;
using textio::kMaxIncludeDepth;
using textio::kMaxShaderBytes;
using textio::shaderErrorName;
using textio::translateInfoLog;

}  // namespace fx
