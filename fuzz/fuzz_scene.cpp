// libFuzzer target: the glTF scene loader on arbitrary bytes, as .gltf (JSON) or .glb (binary,
// chosen by the "glTF" magic). The input is written next to a copy of data/race.bin so that
// mutated JSON still finds a real external buffer and exercises the accessor checks.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include <unistd.h>

#include "scene/SceneLoader.h"

namespace {
std::string workDir() {
    static std::string dir;
    if (dir.empty()) {
        char tmpl[] = "/tmp/cube_fuzz_scene_XXXXXX";
        const char* made = mkdtemp(tmpl);
        dir = made ? made : "/tmp";
        std::ifstream in(std::string(CUBE_SOURCE_DIR) + "/data/race.bin", std::ios::binary);
        std::ofstream out(dir + "/race.bin", std::ios::binary);
        out << in.rdbuf();
    }
    return dir;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const bool binary = size >= 4 && data[0] == 'g' && data[1] == 'l' && data[2] == 'T' && data[3] == 'F';
    const std::string path = workDir() + (binary ? "/input.glb" : "/input.gltf");
    {
        std::ofstream f(path, std::ios::binary | std::ios::trunc);
        f.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    cube::SceneData scene;
    cube::SceneError error;
    if (cube::loadScene(path, &scene, &error)) {
        // A scene that loads must be internally consistent.
        for (const cube::SceneMesh& m : scene.meshes)
            for (uint32_t i : m.indices)
                if (i >= m.vertices.size()) __builtin_trap();
        for (const cube::SceneNode& n : scene.nodes)
            for (int mi : n.meshes)
                if (mi < 0 || size_t(mi) >= scene.meshes.size()) __builtin_trap();
    } else if (error.str().empty()) {
        __builtin_trap();
    }
    return 0;
}
