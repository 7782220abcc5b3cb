#!/usr/bin/env bash
# How far the particle shapes are from perfect (README, "How far the shapes are from perfect").
# Runs fxbench three times over the same frames: with the shaders as they are, then with copies
# of the soft and spherical fragment shaders that also discard what a perfect shape would never
# draw (atlas alpha 0; for spheres also a chord wholly behind the scene). `particle_fragments`
# counts what is not discarded, so the second and third runs count the ideal. A measurement aid
# only: the copies live in a temporary folder read through CUBE_SHADER_DIR.
#   scripts/ideal_fragments.sh [fxbench options...]   (default: the standard scene, 1 round)
set -euo pipefail
cd "$(dirname "$0")/.."
fxbench=./build/bin/fxbench
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
    "alpha": [
        ("fs_particles_soft.glsl", "    float fade = softFade(",
         "    if (texel.a <= 0.0) discard;\n    float fade = softFade("),
        ("fs_particles_spherical.glsl", "if (d2 >= r * r) discard;",
         "if (d2 >= r * r || texel.a <= 0.0) discard;"),
    ],
}
edits["visible"] = edits["alpha"] + [
    ("fs_particles_spherical.glsl", "    float coverage = texel.a * visible",
     "    if (visible <= 0.0) discard;\n    float coverage = texel.a * visible"),
]
write_copies(sys.argv[1], edits, "ideal_fragments.sh")
EOF

args=("$@")
[ ${#args[@]} -gt 0 ] || args=(--rounds 1)
for variant in now alpha visible; do
    # An empty CUBE_SHADER_DIR means the shaders built into fxbench (engine_stub/gl/Paths.cpp).
    shaderDir=""
    [ "$variant" = now ] || shaderDir="$work/$variant"
    CUBE_SHADER_DIR="$shaderDir" "$fxbench" --modes soft,soft-quads,spherical,spherical-quads "${args[@]}" \
        --json "$work/$variant.json" >/dev/null
done

python3 - "$work" <<'EOF'
import json, sys
work = sys.argv[1]
runs = {v: {m["name"]: m["particle_fragments"] for m in json.load(open(f"{work}/{v}.json"))["modes"]}
        for v in ("now", "alpha", "visible")}
print("| mode | drawn now | atlas alpha > 0 (spheres: inside the outline) | spheres: and a visible chord |")
print("|---|---:|---:|---:|")
for mode in runs["now"]:
    visible = f"{runs['visible'][mode]:,.0f}" if mode.startswith("spherical") else "-"
    print(f"| {mode} | {runs['now'][mode]:,.0f} | {runs['alpha'][mode]:,.0f} | {visible} |")
EOF
