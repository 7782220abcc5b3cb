#!/usr/bin/env bash
# The whole test suite built with AddressSanitizer + UndefinedBehaviorSanitizer (gcc), run
# through ctest (the soak is left to the normal build: 20,000 frames under ASan adds nothing the
# shorter GL tests don't already cover; so are the package tests, which build the plugin their
# own way, and the measurement scripts' tests, label "scripts": tests/CMakeLists.txt). Mesa's own
# allocations (llvmpipe's JIT and driver caches) are outside our code: LeakSanitizer suppressions
# for them live in scripts/lsan.supp.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
build=build-asan
# Debug (asserts on, no optimization) with -g1: line tables give reports their file:line at less
# compile time than full debug info. Measured, five of the heaviest files instrumented: -O0 -g
# 17.3 s, -O0 -g1 14.9 s, -O1 -g1 31.5 s; -O1 ran the 470 tests in 261 s instead of about 320 s,
# which does not pay for a build twice as long.
# A unity build (CMake's batches of the engine's, the plugin's and fxbench's files): the normal
# build in build/ compiles every file on its own, which proves each includes what it uses; here
# that was a third of the build (on two cores 258 s -> 177 s).
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCUBE_SANITIZE=ON -DCUBE_BENCH=OFF -DCMAKE_UNITY_BUILD=ON \
      "-DCMAKE_CXX_FLAGS_DEBUG=-g1" "-DCMAKE_C_FLAGS_DEBUG=-g1" >/dev/null
cmake --build "$build" -j"$(nproc)"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The poisoned-host tests take one poison in four alone per technique, every poison still alone
# through one of them (tests/fx_host/PoisonedHostTest.cpp, poisonStride); the suite takes them all.
export CUBE_FX_HOST_POISON_STRIDE=4
cd "$build"
ctest --output-on-failure -j"$(nproc)" -LE "soak|package|scripts" "$@"
