#!/usr/bin/env bash
# Regenerates tests/golden/golden.txt (hashes of frames in every mode, the CUBE trace and the
# deterministic stats) after an intended change to what the engine draws. Say why in the commit.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build -j"$(nproc)" --target test_golden
CUBE_GOLDEN_UPDATE=1 ./build/bin/test_golden
git diff --stat tests/golden/golden.txt
