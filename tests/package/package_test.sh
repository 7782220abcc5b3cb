#!/usr/bin/env bash
# The plugin as a foreign engine gets it (ctest label "package"):
#   1. copy the plugin's sources (fx_plugin/, textio/, its shaders, the atlas) to a scratch folder and
#      build them ALONE: cmake -S fx_plugin (no top-level project, no GTest/GLFW/TinyGLTF/EGL);
#   2. install into a prefix, then delete the copied sources and the build tree;
#   3. check that no installed file names a path of the source or build tree;
#   4. move the prefix elsewhere;
#   5. configure examples/minimal_host with only CMAKE_PREFIX_PATH pointing at the moved prefix
#      (find_package(CubeFx 1.0 CONFIG REQUIRED)), build it with its own global glad, and run it:
#      it renders hard and soft smoke to PNG and checks smoke, soft != hard at the ground, GL
#      state and GL errors (--verify);
#   6. a non-CMake host: compile against the moved prefix with pkg-config only (cubefx-cxx.pc:
#      the C++ layer, cubefx and glm);
#   7. the C side needs no glm: cubefx.pc requires nothing, and find_package(CubeFx COMPONENTS C)
#      configures with glm made unfindable (CMAKE_DISABLE_FIND_PACKAGE_glm), which the default
#      (C and CXX) does not; CubeFx_REACTIONS_DIR and the .pc's reactionsdir name the installed
#      example reactions (examples_test.sh builds and runs the C host that way);
#   8. find_package with a newer major (3.0) must fail; 1.0 (a 1.x host's request) is accepted.
#   package_test.sh <source root> <scratch folder>
set -euo pipefail
src=$(cd "$1" && pwd)
work=$2
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
log() { echo "package_test: $*"; }

copy=$work/src
mkdir -p "$copy/data"
cp -r "$src/fx_plugin" "$src/textio" "$src/shaders" "$src/reactions" "$copy/"
cp "$src/data/smoke_atlas.png" "$src/data/smoke_normals.png" "$copy/data/"

log "add_subdirectory(fx_plugin) from a foreign project that has a 'glad' target of its own"
mkdir -p "$work/foreign"
cat >"$work/foreign/CMakeLists.txt" <<CM
cmake_minimum_required(VERSION 3.20)
project(foreign LANGUAGES C CXX)
set(CMAKE_CXX_STANDARD 17)
add_library(glad INTERFACE)  # most engines have one; the plugin's own is named apart
add_subdirectory($copy/fx_plugin cubefx)
add_executable(foreign_host host.cpp)
target_link_libraries(foreign_host PRIVATE CubeFx::fx_plugin glad)
CM
cat >"$work/foreign/host.cpp" <<'CPP'
#include <fx/Plugin.h>
int main() { return fxApiVersion() == fx::kApiVersion ? 0 : 1; }
CPP
# This build only has to configure, compile and link: -O0 without debug info, the cheapest compile
# (the standalone build below is the optimized one that renders), and as a unity build, as large
# engines compile their own and their plugins' sources (on two cores 15 s, against 39 s file by file).
cmake -S "$work/foreign" -B "$work/foreign/b" -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O0" \
      "-DCMAKE_C_FLAGS_DEBUG=-O0" -DCMAKE_UNITY_BUILD=ON >"$work/foreign-configure.log"
cmake --build "$work/foreign/b" -j"$(nproc)" --target foreign_host >"$work/foreign-build.log"
"$work/foreign/b/foreign_host"
rm -rf "$work/foreign"

log "CUBE_PLUGIN_ONLY: the top level configures the plugin without the engine's dependencies"
cmake -S "$src" -B "$work/only" -DCUBE_PLUGIN_ONLY=ON >"$work/only.log"
for dep in GTest_DIR glfw3_DIR TinyGLTF_DIR OSMESA_FOUND; do
  if grep -q "^$dep" "$work/only/CMakeCache.txt"; then
    echo "package_test: FAIL: CUBE_PLUGIN_ONLY still looks up $dep"; exit 1
  fi
done
grep -q "fx_plugin" "$work/only/Makefile" || { echo "package_test: FAIL: no fx_plugin target"; exit 1; }
rm -rf "$work/only"

log "standalone plugin build (cmake -S fx_plugin)"
# A unity build too (on two cores 36 s, against 69 s file by file): the main build compiles every
# file of the plugin on its own, which is what proves each one includes what it uses. At -O1 with
# debug info (the source-path check below needs the debug info; what is checked here is the
# package, not the code's speed): 42 -> 33 s on two cores.
cmake -S "$copy/fx_plugin" -B "$work/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_UNITY_BUILD=ON \
      "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g -DNDEBUG" \
      >"$work/configure.log"
cmake --build "$work/build" -j"$(nproc)" >"$work/build.log"
cmake --install "$work/build" --prefix "$work/prefix" >"$work/install.log"
rm -rf "$copy" "$work/build"

log "installed files name no source or build path"
bad=$(grep -rlF -e "$copy" -e "$work/build" -e "$src" "$work/prefix" || true)
if [ -n "$bad" ]; then
  echo "package_test: FAIL: these installed files contain a source or build path:"; echo "$bad"; exit 1
fi
for f in lib/libcubefx.so include/fx/Plugin.h include/fx/Api.h lib/cmake/CubeFx/CubeFxConfig.cmake \
         lib/cmake/CubeFx/CubeFxConfigVersion.cmake lib/pkgconfig/cubefx.pc lib/pkgconfig/cubefx-cxx.pc \
         share/cubefx/reactions/README.md share/cubefx/reactions/burnout_smoke.yaml; do
  [ -e "$work/prefix/$f" ] || { echo "package_test: FAIL: $f was not installed"; exit 1; }
done
# The reaction internals stay private.
[ ! -e "$work/prefix/include/fx/Reaction.h" ] || { echo "package_test: FAIL: Reaction.h is public"; exit 1; }

mv "$work/prefix" "$work/moved"
prefix=$work/moved

log "examples/minimal_host against the moved prefix"
cmake -S "$src/examples/minimal_host" -B "$work/example" -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_BUILD_TYPE=RelWithDebInfo >"$work/example-configure.log"
cmake --build "$work/example" -j"$(nproc)" >"$work/example-build.log"
# The host carries its own, global glad next to the plugin's private one.
nm "$work/example/minimal_host" >"$work/example-symbols.txt"
grep -q " [BD] glad_glCreateShader$" "$work/example-symbols.txt" ||
  { echo "package_test: FAIL: the example has no global glad of its own"; exit 1; }
mkdir -p "$work/out"
LD_LIBRARY_PATH="$prefix/lib" "$work/example/minimal_host" "$work/example/smoke.yaml" "$work/out" --verify
[ -s "$work/out/hard.png" ] && [ -s "$work/out/soft.png" ] || { echo "package_test: FAIL: no PNG"; exit 1; }

log "pkg-config host"
cat >"$work/pc_host.cpp" <<'CPP'
#include <fx/Plugin.h>
#include <cstdio>
int main() {
    std::printf("fxApiVersion %u, headers %u\n", fxApiVersion(), fx::kApiVersion);
    fx::PluginImports imports;  // no host: refused with a named error, no crash
    fx::ErrorCode code = fx::ErrorCode::None;
    const bool refused = !fxCreatePlugin(imports, &code) && code == fx::ErrorCode::NullArgument;
    return fxApiVersion() == fx::kApiVersion && refused ? 0 : 1;
}
CPP
flags=$(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags --libs cubefx-cxx)
case "$flags" in *"$prefix"*) ;; *) echo "package_test: FAIL: pkg-config flags miss the moved prefix: $flags"; exit 1 ;; esac
# shellcheck disable=SC2086
c++ -std=c++17 "$work/pc_host.cpp" -o "$work/pc_host" $flags
LD_LIBRARY_PATH="$prefix/lib" "$work/pc_host"

log "the C side without glm: cubefx.pc and find_package(CubeFx COMPONENTS C)"
requires=$(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --print-requires cubefx)
[ -z "$requires" ] || { echo "package_test: FAIL: cubefx.pc requires '$requires' (the C API needs nothing)"; exit 1; }
reactions=$(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --variable=reactionsdir cubefx)
[ -e "$reactions/burnout_smoke.yaml" ] || { echo "package_test: FAIL: reactionsdir '$reactions' holds no reactions"; exit 1; }
mkdir -p "$work/c_only"
cat >"$work/c_only/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.20)
project(c_only LANGUAGES C)
find_package(CubeFx CONFIG REQUIRED ${CUBEFX_COMPONENTS})
if(NOT EXISTS "${CubeFx_REACTIONS_DIR}/burnout_smoke.yaml")
  message(FATAL_ERROR "CubeFx_REACTIONS_DIR='${CubeFx_REACTIONS_DIR}' holds no reactions")
endif()
file(WRITE ${CMAKE_BINARY_DIR}/host.c "#include <fx/fx.h>\nint main(void) { return fxGetApi(FX_API_VERSION) ? 0 : 1; }\n")
add_executable(c_only ${CMAKE_BINARY_DIR}/host.c)
target_link_libraries(c_only PRIVATE CubeFx::fx_c)
CM
# glm made unfindable: the C component must not look it up...
cmake -S "$work/c_only" -B "$work/c_only/b" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_DISABLE_FIND_PACKAGE_glm=ON \
      "-DCUBEFX_COMPONENTS=COMPONENTS;C" >"$work/c_only.log" 2>&1 ||
  { cat "$work/c_only.log"; echo "package_test: FAIL: find_package(CubeFx COMPONENTS C) needs glm"; exit 1; }
cmake --build "$work/c_only/b" >>"$work/c_only.log" 2>&1 || { cat "$work/c_only.log"; exit 1; }
LD_LIBRARY_PATH="$prefix/lib" "$work/c_only/b/c_only"
# ...while the default (C and CXX) does, so the line above would catch a lookup.
if cmake -S "$work/c_only" -B "$work/c_only/b2" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_DISABLE_FIND_PACKAGE_glm=ON \
         >"$work/c_only_cxx.log" 2>&1; then
  echo "package_test: FAIL: find_package(CubeFx) found the C++ layer without glm"; exit 1
fi
rm -rf "$work/c_only"

log "an incompatible version is refused by find_package"
mkdir -p "$work/v3"
cat >"$work/v3/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.20)
project(v3 LANGUAGES CXX)
find_package(CubeFx 3.0 CONFIG REQUIRED)
CM
if cmake -S "$work/v3" -B "$work/v3/b" -DCMAKE_PREFIX_PATH="$prefix" >"$work/v3.log" 2>&1; then
  echo "package_test: FAIL: find_package(CubeFx 3.0) accepted version 2.x"; exit 1
fi
log "passed"
