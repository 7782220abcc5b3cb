#!/usr/bin/env bash
# Installs what the build needs from Debian's archive, only if something is missing.
# Sourced by run.sh and test.sh; safe to run again (idempotent), works as root with no stdin.
set -euo pipefail
CUBE_PACKAGES=(build-essential cmake pkg-config python3-glad
  libglfw3-dev libglm-dev libtinygltf-dev nlohmann-json3-dev libyaml-cpp-dev libosmesa6-dev libegl-dev
  libstb-dev libimgui-dev libgtest-dev libbenchmark-dev xvfb xauth python3
  libirrlicht-dev  # examples/irrlicht_host: a legacy engine as host (Irrlicht 1.8, OpenGL driver)
  glslang-tools spirv-tools  # scripts/shader_ops.py: the particle shaders' operations per fragment
  # What runs need: the engine links no back end but dlopens the one --backend names, so the
  # runtime libraries are listed themselves rather than left to the -dev packages' Depends.
  # osmesa: libosmesa6. egl: libegl1 + Mesa's vendor driver and its DRI drivers (llvmpipe's
  # swrast_dri here; a GPU machine may use its vendor's instead). glfw: libglfw3.
  libosmesa6 libegl1 libegl-mesa0 libgl1-mesa-dri libglfw3)
# Extra tools for the robustness jobs (sanitizers, fuzzing), only when asked for.
if [ "${CUBE_WITH_CLANG:-0}" = 1 ]; then CUBE_PACKAGES+=(clang libclang-rt-14-dev); fi

missing=()
for p in "${CUBE_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "deps: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO=sudo
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq </dev/null
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" </dev/null
fi
