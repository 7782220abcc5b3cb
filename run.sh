#!/usr/bin/env bash
# One command for a newcomer: installs what is missing, builds, and runs the main job headless:
# the scripted race drive with the soft-particle plugin, written to out/.
set -euo pipefail
cd "$(dirname "$0")"
bash scripts/deps.sh
bash scripts/configure.sh
cmake --build build -j"$(nproc)"
mkdir -p out
./build/bin/cube_game --frames 420 --fixed-dt 0.0166667 --seed 1 \
  --screenshot out/cube_game.png --stats-json out/cube_game_stats.json "$@"
echo "run.sh: frame in out/cube_game.png, statistics in out/cube_game_stats.json"
