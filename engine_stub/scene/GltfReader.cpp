#include "scene/GltfReader.h"

#include <stb_image.h>

#include <cstring>
#include <filesystem>

#include "textio/SafeFile.h"

namespace cube::gltf {

namespace {

namespace fs = std::filesystem;

// ---- file system callbacks handed to tinygltf ----------------------------------------------

struct FsState {
    fs::path baseDir;  // canonical directory of the scene file
};

// True when `path` resolves (symlinks and ".." followed) to a place inside the model's folder.
bool insideBase(const std::string& path, const FsState& state) {
    std::error_code ec;
    const fs::path real = fs::weakly_canonical(fs::path(path), ec);
    if (ec) return false;
    const std::string base = state.baseDir.string();
    const std::string r = real.string();
    return r.size() > base.size() && r.compare(0, base.size(), base) == 0 &&
           (base.back() == '/' || r[base.size()] == '/');
}

// External files are looked up next to the scene file only (tinygltf would also try the working
// directory, which makes a load depend on where the program was started). Whether the file
// really lies inside the folder is checked when it is read, so the message can say so.
bool fsFileExists(const std::string& path, void* user) {
    const auto* state = static_cast<const FsState*>(user);
    const std::string base = state->baseDir.string();
    std::error_code ec;
    return path.compare(0, base.size(), base) == 0 && fs::exists(path, ec);
}

std::string fsExpandFilePath(const std::string& path, void*) { return path; }  // no shell expansion

bool fsReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* user) {
    const auto* state = static_cast<const FsState*>(user);
    std::string why;
    if (!insideBase(path, *state)) {
        why = "'" + path + "' resolves to a place outside the model's folder";
    } else if (textio::readFileBounded(path, size_t(kMaxFileBytes), out, nullptr, &why)) {
        return true;
    }
    if (err) *err += why;
    return false;
}

bool fsWriteWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&,
                      void*) {
    if (err) *err += "the scene loader never writes files";
    return false;
}

// ---- image callback: never decodes, only notes what arrived ---------------------------------

// Images are not needed by SceneData (colours come from baseColorFactor), so nothing is decoded.
// Bytes from a URI are a complete in-memory file and can be sniffed safely; bytes from a
// bufferView are NOT touched here because tinygltf has not range-checked that bufferView yet
// (MeshBuilder does it afterwards).
bool noteImage(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
               const unsigned char* bytes, int size, void* user) {
    auto* state = static_cast<ImageState*>(user);
    if (index >= 0) {
        if (state->delivered.size() <= size_t(index)) state->delivered.resize(size_t(index) + 1, 0);
        state->delivered[size_t(index)] = 1;
    }
    if (image->bufferView < 0) {
        int w = 0, h = 0, c = 0;
        if (size <= 0 || !stbi_info_from_memory(bytes, size, &w, &h, &c)) {
            state->bad.emplace_back(index,
                                    stbi_failure_reason() ? stbi_failure_reason() : "unknown");
        }
    }
    return true;
}

// tinygltf puts these into `err` only for *required* external loads, i.e. buffers (images go to
// `warn`), and for embedded buffer data it cannot decode.
bool isBufferFailure(const std::string& err) {
    for (const char* s :
         {"File not found :", "File read error :", "File size mismatch :", "File is empty :",
          "in Buffer", "GLB with empty BIN chunk", "Must be equal or less than binary size"}) {
        if (err.find(s) != std::string::npos) return true;
    }
    return false;
}

// Checks the GLB container before tinygltf sees it: tinygltf 2.7.0 forgets the 8-byte BIN chunk
// header in its bounds check and could read past the end of a crafted file.
bool checkGlbLayout(const std::vector<unsigned char>& bytes, std::string* why, uint32_t* length) {
    if (bytes.size() < 20) {
        *why = "truncated: " + std::to_string(bytes.size()) + " bytes, a GLB header needs 20";
        return false;
    }
    *length = readLE32(&bytes[8]);
    const uint64_t json = readLE32(&bytes[12]);
    if (readLE32(&bytes[4]) != 2) {
        *why = "GLB version " + std::to_string(readLE32(&bytes[4])) + ", expected 2";
        return false;
    }
    if (*length > bytes.size()) {
        *why = "GLB header says " + std::to_string(*length) + " bytes but the file has " +
               std::to_string(bytes.size()) + " (truncated?)";
        return false;
    }
    if (20 + json > *length) {
        *why = "JSON chunk of " + std::to_string(json) + " bytes runs past the GLB length " +
               std::to_string(*length) + " (truncated?)";
        return false;
    }
    const uint64_t binHeader = 20 + json;
    if (binHeader < *length) {
        if (binHeader + 8 > *length ||
            binHeader + 8 + readLE32(&bytes[size_t(binHeader)]) > *length) {
            *why =
                "BIN chunk runs past the GLB length " + std::to_string(*length) + " (truncated?)";
            return false;
        }
    }
    return true;
}


}  // namespace

bool readGltfFile(const std::string& path, GltfFile* file, SceneError* error) {
    textio::FileError code = textio::FileError::None;
    std::string why;
    if (!textio::readFileBounded(path, size_t(kMaxFileBytes), &file->bytes, &code, &why)) {
        if (code == textio::FileError::TooLarge)
            return fail(path, error, SceneErrorCode::TooLarge, "file is " + why);
        if (why == "no such file")
            return fail(path, error, SceneErrorCode::FileNotFound,
                        "file not found, expected a .gltf or .glb file at this path");
        return fail(path, error, SceneErrorCode::FileNotFound,
                    "cannot be read: " + why + "; expected a .gltf or .glb file");
    }
    const std::vector<unsigned char>& bytes = file->bytes;
    file->binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    const std::string ext = fs::path(path).extension().string();
    if (!file->binary && (ext == ".glb" || ext == ".GLB")) {
        return fail(path, error, SceneErrorCode::ParseError,
                    "expected binary glTF (a .glb starting with 'glTF'), found " +
                        std::to_string(bytes.size()) + " bytes without that magic");
    }
    if (file->binary) {
        if (!checkGlbLayout(bytes, &why, &file->glbLength))
            return fail(path, error, SceneErrorCode::ParseError, "invalid GLB: " + why);
        file->json = reinterpret_cast<const char*>(bytes.data()) + 20;
        file->jsonSize = readLE32(&bytes[12]);
    } else {
        file->json = reinterpret_cast<const char*>(bytes.data());
        file->jsonSize = bytes.size();
    }
    return true;
}

bool parseGltf(const std::string& path, const GltfFile& file, tinygltf::Model* model,
               ImageState* images, std::string* tinygltfWarnings, SceneError* error) {
    std::error_code ec;
    FsState fsState;
    fsState.baseDir = fs::weakly_canonical(fs::absolute(fs::path(path), ec).parent_path(), ec);
    std::string baseDir = fsState.baseDir.string();
    if (baseDir.empty() || baseDir.back() != '/') baseDir += '/';

    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(tinygltf::FsCallbacks{&fsFileExists, &fsExpandFilePath, &fsReadWholeFile,
                                                &fsWriteWholeFile, &fsState});
    loader.SetImageLoader(&noteImage, images);

    std::string err;
    bool parsed = false;
    try {
        parsed = file.binary
                     ? loader.LoadBinaryFromMemory(model, &err, tinygltfWarnings, file.bytes.data(),
                                                   file.glbLength, baseDir)
                     : loader.LoadASCIIFromString(model, &err, tinygltfWarnings, file.json,
                                                  static_cast<unsigned int>(file.jsonSize), baseDir);
    } catch (const std::exception& e) {
        err += std::string(err.empty() ? "" : "; ") + "exception: " + e.what();
        parsed = false;
    }
    if (parsed) return true;
    if (isBufferFailure(err)) {
        return fail(path, error, SceneErrorCode::MissingBuffer,
                    "buffer data could not be loaded (tinygltf: " + trimmed(err) + ")");
    }
    return fail(path, error, SceneErrorCode::ParseError,
                std::string("not valid ") + (file.binary ? "binary glTF" : "glTF JSON") +
                    " (tinygltf: " + (err.empty() ? "no details" : trimmed(err)) + ")");
}

}  // namespace cube::gltf
