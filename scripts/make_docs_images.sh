#!/usr/bin/env bash
# Renders the pictures in docs/images/ (README.md shows them):
#   - the same frame (t = 8.5 s, the end of the burnout: --start 4.5 + 240 frames at 1/60 s,
#     seed 1) in every mode, lit by the scene's sun, and the soft frame unlit for comparison;
#   - close-ups across the donut towards the barrier, one of them into a low sun;
#   - the cloud's shadow on the track (lit smoke and the same frame with --unlit-smoke);
#   - the effect recipes (sparks, lingering smoke, steam, explosion) and the tweak panel.
# usage: scripts/make_docs_images.sh [build dir]
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${1:-build}/bin/cube_game"
out=docs/images
mkdir -p "$out"
run() { "$bin" "$@" >/dev/null; }

common="--frames 240 --fixed-dt 0.0166667 --seed 1 --start 4.5 --size 960x768"
run $common --fx legacy --screenshot "$out/mode_legacy.png"
run $common --mode hard --screenshot "$out/mode_hard.png"
run $common --mode soft --screenshot "$out/mode_soft.png"
run $common --mode soft --unlit-smoke --screenshot "$out/mode_soft_unlit.png"
run $common --mode soft --prepass-equal --screenshot "$out/mode_soft_equal.png"
run $common --mode soft --quarter-res --screenshot "$out/mode_soft_quarter.png"
run $common --mode soft --bilinear-upsample --screenshot "$out/mode_soft_quarter_bilinear.png"
run $common --mode spherical --screenshot "$out/mode_spherical.png"
run $common --mode spherical --quarter-res --screenshot "$out/mode_spherical_quarter.png"
run $common --mode mega --screenshot "$out/mode_mega.png"
run $common --mode soft --panel --screenshot "$out/panel.png"

# Close-ups: a fixed camera by the track looking across the donut at the barrier (z = 8.5).
close="--frames 240 --fixed-dt 0.0166667 --seed 1 --start 4.5 --size 960x768 --no-hud --no-mirror --camera -19,1.5,1,-6,0.5,8"
for m in hard soft spherical mega; do
  run $close --mode $m --screenshot "$out/closeup_$m.png"
done
# The same view into a low sun ahead: forward scattering lights the cloud's thin edges.
run $close --mode soft --sun 28,10 --screenshot "$out/smoke_into_the_sun.png"

# The cloud's shadow: a low sun from +z throws it across the track toward the camera.
shadow="--frames 240 --fixed-dt 0.0166667 --seed 1 --start 4.5 --size 800x600 --no-hud --no-mirror --camera 8,9,-16,-6,0,0 --sun 95,18"
run $shadow --screenshot "$out/smoke_shadow_lit.png"
run $shadow --unlit-smoke --screenshot "$out/smoke_shadow_unlit.png"

# Recipes (reactions/README.md): 800x450, seed 1, 1/60 s steps.
fx="--fixed-dt 0.0166667 --seed 1 --size 800x450"
run $fx --start 12.5 --frames 120 --screenshot "$out/barrier_scrape_sparks.png"
run $fx --start 4 --frames 240 --screenshot "$out/burnout_smoke_lingers.png"
run $fx --start 8 --frames 320 --camera 14,2.5,2,20,0.8,7.5 --screenshot "$out/tyre_steam_thins.png"
run $fx --start 8 --frames 320 --camera 9,4,-13,9,1,6 --screenshot "$out/smoke_and_steam.png"
run $fx --start 1 --explode-at 1.5 --frames 54 --no-mirror --camera -35,3,-16,-37,2.5,0 --screenshot "$out/explosion.png"
echo "make_docs_images: wrote $(ls "$out"/*.png | wc -l) pictures to $out"
