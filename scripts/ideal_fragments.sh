#!/usr/bin/env bash
# How far the particle shapes are from perfect (README, "How far the shapes are from perfect").
# Runs fxbench over the same frames, each time with copies of the shaders read through
# CUBE_SHADER_DIR (a measurement aid only; the copies live in a temporary folder):
# `particle_fragments` counts what is not discarded, so
#   drawn:   soft without its early out on an empty atlas texel: what its shape rasterises
#            (spheres as shipped: they discard outside the outline and any coverage of 0);
#   alpha:   the same, soft with its early out, spheres also discarding atlas alpha 0: the ideal;
#   visible: spheres also discarding a chord wholly behind the scene; soft also discarding a
#            fade of 1 (no geometry within its softness): what soft needs the scene depth for
#            (soft fetches it at every fragment with smoke: the alpha column);
# and, for spheres, whose fetch comes before their discards (so those are taken out of these copies):
#   sphere-all:  spherical: every fragment its shape rasterises fetches;
#   sphere-need: spherical as shipped, also discarding a chord the scene does not clip: what
#                needs the fetch.
# (Fade classification, API 2.2-2.3, skipped some of the fetches the two columns apart; it was
# removed in 2.4: on the GPU it cost more than it saved.)
#   scripts/ideal_fragments.sh [fxbench options...]   (default: the standard scene, 1 round;
#                                                      fxbench is $FXBENCH, default ./build/bin/fxbench)
set -euo pipefail
cd "$(dirname "$0")/.."
fxbench=${FXBENCH:-./build/bin/fxbench}
[ -x "$fxbench" ] || { echo "ideal_fragments.sh: build first (./run.sh or cmake --build build)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 - "$work" <<'EOF'
import sys
sys.dont_write_bytecode = True
sys.path.insert(0, "scripts")
from shader_copies import write_copies
# (file, text that must be there, replacement): stop loudly when a shader no longer matches.
edits = {
    "drawn": [("fs_particles_soft.glsl", "    if (texel.a == 0.0) discard;\n", "")],
    "alpha": [
        ("fs_particles_spherical.glsl", "if (d2 >= r2) discard;",
         "if (d2 >= r2 || texel.a <= 0.0) discard;"),
    ],
}
edits["sphere-all"] = [("fs_particles_spherical.glsl", "    if (d2 >= r2) discard;\n", ""),
                       ("fs_particles_spherical.glsl", "    if (coverage == 0.0) discard;\n", "")]
edits["sphere-need"] = [("fs_particles_spherical.glsl", "    float visible = clamp(",
                         "    if (sceneZ >= tMid + halfDepth) discard;\n    float visible = clamp(")]
edits["visible"] = edits["alpha"] + [
    ("fs_particles_spherical.glsl", "    float coverage = texel.a * visible",
     "    if (visible <= 0.0) discard;\n    float coverage = texel.a * visible"),
    ("fs_particles_soft.glsl", "    float coverage = texel.a * fade;",
     "    if (fade >= 1.0) discard;\n    float coverage = texel.a * fade;"),
]
write_copies(sys.argv[1], edits, "ideal_fragments.sh")
EOF

args=("$@")
[ ${#args[@]} -gt 0 ] || args=(--rounds 1)
for variant in drawn alpha visible; do
    CUBE_SHADER_DIR="$work/$variant" "$fxbench" --modes soft,soft-quads,spherical,spherical-quads "${args[@]}" \
        --json "$work/$variant.json" >/dev/null
done
for variant in sphere-all sphere-need; do
    CUBE_SHADER_DIR="$work/$variant" "$fxbench" --modes spherical "${args[@]}" --json "$work/$variant.json" >/dev/null
done

python3 - "$work" <<'EOF'
import json, sys
work = sys.argv[1]
runs = {v: {m["name"]: m["particle_fragments"] for m in json.load(open(f"{work}/{v}.json"))["modes"]}
        for v in ("drawn", "alpha", "visible")}
print("| mode | drawn (soft: rasterised; spheres: written, their own discards leave out alpha 0 "
      "and a hidden chord already) | atlas alpha > 0 "
      "| and a visible chord (spheres) or a fade below 1 (soft) |")
print("|---|---:|---:|---:|")
for mode in runs["drawn"]:
    print(f"| {mode} | {runs['drawn'][mode]:,.0f} | {runs['alpha'][mode]:,.0f} | {runs['visible'][mode]:,.0f} |")
# Each copy only discards more than the one before it.
bad = [m for m in runs["drawn"] if not runs["drawn"][m] >= runs["alpha"][m] >= runs["visible"][m]]
if bad or not any(runs["drawn"].values()):
    sys.exit(f"ideal_fragments.sh: counts not falling from column to column (or all 0): {bad}")

soft = runs["alpha"]["soft"], runs["visible"]["soft"]
print(f"\nsoft: {soft[0]:,.0f} fragments with smoke fetch the scene depth ({soft[1]:,.0f} need it: a fade below 1)")
sphere = {v: json.load(open(f"{work}/sphere-{v}.json"))["modes"][0]["particle_fragments"] for v in ("all", "need")}
print(f"spherical: {sphere['all']:,.0f} fragments fetch the scene depth ({sphere['need']:,.0f} need it: a chord the "
      f"scene clips)")
if not sphere["need"] <= sphere["all"] or not sphere["all"]:
    sys.exit("ideal_fragments.sh: spheres' fragments that need the fetch outnumber those that fetch (or none fetch)")
EOF
