#!/usr/bin/env bash
# Renders the pictures in docs/: the same simulated frame (1.5 s into the burnout, seed 1, fixed
# dt) in every mode, and close-ups where the smoke meets the track and the barrier.
# usage: scripts/make_docs_images.sh [build dir]   (writes docs/images/*.png)
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${1:-build}/bin/cube_game"
out=docs/images
mkdir -p "$out"
common="--frames 240 --fixed-dt 0.0166667 --seed 1 --start 4.5 --size 960x768"
"$bin" $common --fx legacy --screenshot "$out/mode_legacy.png" >/dev/null
"$bin" $common --mode hard --screenshot "$out/mode_hard.png" >/dev/null
"$bin" $common --mode soft --screenshot "$out/mode_soft.png" >/dev/null
"$bin" $common --mode soft --prepass-equal --screenshot "$out/mode_soft_equal.png" >/dev/null
"$bin" $common --mode soft --quarter-res --screenshot "$out/mode_soft_quarter.png" >/dev/null
"$bin" $common --mode soft --bilinear-upsample --screenshot "$out/mode_soft_quarter_bilinear.png" >/dev/null
"$bin" $common --mode spherical --screenshot "$out/mode_spherical.png" >/dev/null
"$bin" $common --mode spherical --quarter-res --screenshot "$out/mode_spherical_quarter.png" >/dev/null
# Close-up: a fixed camera by the track looking across the donut at the barrier (z = 8.5).
close="--frames 240 --fixed-dt 0.0166667 --seed 1 --start 4.5 --size 960x768 --no-hud --no-mirror --camera -19,1.5,1,-6,0.5,8"
for m in hard soft spherical; do
  "$bin" $close --mode $m --screenshot "$out/closeup_$m.png" >/dev/null
done
echo "make_docs_images: wrote $(ls "$out" | wc -l) images to $out"
