#include "scene/SceneLoader.h"

#include "scene/GltfCommon.h"
#include "scene/GltfReader.h"
#include "scene/GltfValidator.h"
#include "scene/MeshBuilder.h"
#include "scene/SceneAssembler.h"

namespace cube {

const char* sceneErrorCodeName(SceneErrorCode code) {
    switch (code) {
        case SceneErrorCode::None: return "None";
        case SceneErrorCode::FileNotFound: return "FileNotFound";
        case SceneErrorCode::ParseError: return "ParseError";
        case SceneErrorCode::MissingBuffer: return "MissingBuffer";
        case SceneErrorCode::AccessorOutOfRange: return "AccessorOutOfRange";
        case SceneErrorCode::IndexOutOfRange: return "IndexOutOfRange";
        case SceneErrorCode::BadAttribute: return "BadAttribute";
        case SceneErrorCode::MissingTexture: return "MissingTexture";
        case SceneErrorCode::MissingNode: return "MissingNode";
        case SceneErrorCode::Empty: return "Empty";
        case SceneErrorCode::BadNode: return "BadNode";
        case SceneErrorCode::BadReference: return "BadReference";
        case SceneErrorCode::Unsupported: return "Unsupported";
        case SceneErrorCode::TooLarge: return "TooLarge";
        case SceneErrorCode::TooDeep: return "TooDeep";
        case SceneErrorCode::InvalidGltf: return "InvalidGltf";
        case SceneErrorCode::BadUri: return "BadUri";
    }
    return "Unknown";
}

std::string SceneError::str() const {
    return std::string(sceneErrorCodeName(code)) + ": " + message;
}

bool loadScene(const std::string& path, SceneData* out, SceneError* error) {
    SceneData scene;
    scene.sourcePath = path;
    try {
        // Limits before parsing: size (readGltfFile), JSON nesting (a byte scan), then the rules
        // tinygltf would accept silently; only then the recursive parsers see the text.
        gltf::GltfFile file;
        if (!gltf::readGltfFile(path, &file, error)) return false;
        if (!gltf::checkJsonNesting(path, file.json, file.jsonSize, gltf::kMaxJsonDepth, error))
            return false;
        if (!gltf::validateGltfJson(path, file.json, file.jsonSize, error, &scene.warnings))
            return false;
        tinygltf::Model model;
        gltf::ImageState images;
        std::string tinygltfWarnings;
        if (!gltf::parseGltf(path, file, &model, &images, &tinygltfWarnings, error)) return false;
        const gltf::Context ctx{path, model, error};
        std::vector<size_t> meshFirst;
        if (!gltf::buildMeshes(ctx, images, tinygltfWarnings, &scene, &meshFirst)) return false;
        if (!gltf::assembleScene(ctx, meshFirst, &scene)) return false;
    } catch (const std::exception& e) {  // e.g. bad_alloc on a hostile file
        return gltf::fail(path, error, SceneErrorCode::ParseError,
                          std::string("conversion failed: ") + e.what());
    }
    *out = std::move(scene);
    if (error) *error = SceneError{};
    return true;
}

bool requireNodes(const SceneData& scene, const std::vector<std::string>& names,
                  SceneError* error) {
    for (const std::string& name : names) {
        if (scene.findNode(name) < 0) {
            if (error) {
                error->code = SceneErrorCode::MissingNode;
                error->file = scene.sourcePath;
                error->message = scene.sourcePath + ": node '" + name +
                                 "' not found, expected a node with exactly that name";
            }
            return false;
        }
    }
    return true;
}

}  // namespace cube
