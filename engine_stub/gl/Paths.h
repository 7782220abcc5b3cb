#pragma once
#include <string>

namespace cube::paths {

/// The project root that holds shaders/, data/ and reactions/. Defaults to the source tree the
/// binary was built from; the CUBE_ROOT environment variable overrides it (installed copies).
std::string root();
std::string shaders();    ///< root()/shaders, or CUBE_SHADER_DIR
/// CUBE_SHADER_DIR when set, else empty: the folder the fx plugin reads its shaders from instead
/// of the copies embedded in it.
std::string shaderOverride();
std::string data();       ///< root()/data
std::string reactions();  ///< root()/reactions

}  // namespace cube::paths
