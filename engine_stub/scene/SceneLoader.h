#pragma once
// glTF 2.0 scene loading (.gltf + external/embedded buffers, or .glb) into SceneData.
// Four stages, one file each: GltfReader (bytes, GLB container, tinygltf), GltfValidator (JSON
// nesting pre-scan, the rules tinygltf accepts silently), MeshBuilder (buffers, accessors,
// primitives), SceneAssembler (the node tree, linear time).
//
// Contract: bad data never crashes and never reads out of bounds. Every accessor, bufferView and
// buffer range, component type, index, node reference and transform is validated before use; on
// any failure loadScene returns false, fills the error (named code + a message that names the file
// and says what was expected) and leaves `out` untouched.

#include "scene/SceneData.h"

#include <string>
#include <vector>

namespace cube {

/// One code per validation rule; tests assert the code, people read the message.
enum class SceneErrorCode {
    None = 0,
    FileNotFound,   ///< the scene file does not exist, is not a regular file, or cannot be read
    ParseError,     ///< not glTF: bad JSON, truncated file, bad GLB header (tinygltf's text kept)
    MissingBuffer,  ///< a buffer's data cannot be had: missing/short .bin, bad data URI, no BIN
    AccessorOutOfRange,  ///< accessor or bufferView range outside its bufferView/buffer
    IndexOutOfRange,     ///< a vertex index >= the primitive's vertex count
    BadAttribute,        ///< POSITION missing, wrong type/componentType, counts disagree, NaN data
    MissingTexture,      ///< an image (URI, data URI or bufferView) cannot be loaded
    MissingNode,         ///< requireNodes: a node the caller needs is absent
    Empty,               ///< the scene has no meshes
    BadNode,       ///< node/child index out of range, cycle, shared child, malformed transform
    BadReference,  ///< an index to a mesh, accessor, bufferView, material or image is invalid
    Unsupported,   ///< valid glTF this loader does not handle: sparse, non-triangles, required
                   ///< extensions (each named)
    TooLarge,      ///< a file past 256 MiB or more nodes than the loader's limit
    TooDeep,       ///< JSON nested past 128 levels, or a node hierarchy past 4096 levels
    InvalidGltf,   ///< breaks a glTF rule (asset.version, a property of the wrong type); the
                   ///< message names the Khronos validator's rule, e.g. [UNKNOWN_ASSET_MAJOR_VERSION]
    BadUri,        ///< a buffer/image uri leaves the model's folder (absolute, "..", a scheme)
};

/// Stable name of a code ("AccessorOutOfRange"), for logs and test output.
const char* sceneErrorCodeName(SceneErrorCode code);

/// Defaults: code None, empty file and message.
struct SceneError {
    SceneErrorCode code = SceneErrorCode::None;
    std::string file;  ///< the path handed to loadScene (or SceneData::sourcePath)
    std::string
        message;  ///< starts with the file: "race.gltf: accessor 3 (POSITION of mesh ...) ..."
    /// "<CodeName>: <message>"
    std::string str() const;
};

/// Loads a .gltf or .glb file (chosen by the "glTF" magic, the extension only names what was
/// expected in errors). Uses the default scene (scene 0 when none is marked; all parentless nodes
/// when the file has no scenes). `out` is replaced only on success; `error` may be null.
/// Features read past (textures, skins, animations, cameras, used extensions) are listed once
/// each in out->warnings.
bool loadScene(const std::string& path, SceneData* out, SceneError* error);

/// Checks that every name in `names` is a node of `scene`; on the first absent one returns false
/// with MissingNode naming the node and scene.sourcePath.
bool requireNodes(const SceneData& scene, const std::vector<std::string>& names, SceneError* error);

}  // namespace cube
