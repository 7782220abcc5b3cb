#!/usr/bin/env bash
# What each part of the particle shaders costs: fxbench over the same frames with the shaders as
# they are, then with copies that each leave one part out (read through CUBE_SHADER_DIR), and the
# per-pass times side by side. The pictures of the copies are wrong on purpose (but for
# the same_picture variants below, which only try a cheaper way to the same one); only their times
# mean something.
# A measurement aid, made for a GPU session's few minutes: one command answers where soft's and
# spherical's extra time per fragment and the composite's time go.
#   scripts/shader_parts.sh [fxbench options...]      the three steps below, here (llvmpipe)
#   scripts/shader_parts.sh --check                   only checks that every part is still found
#   scripts/shader_parts.sh --same-pictures [options] checks that the variants meant to draw the
#                                                     same picture (same_picture below) do, byte
#                                                     for byte (fxbench --images, one frame)
# In steps, for a machine that may have no python3 (the GPU machine: scripts/gpu_check.sh):
#   scripts/shader_parts.sh --prepare DIR             1. the copies, into DIR (python3)
#   scripts/shader_parts.sh --run DIR OUT [options]   2. fxbench over them, JSON into OUT (bash)
#   scripts/shader_parts.sh --table OUT               3. the table (python3)
# fxbench is $FXBENCH (default ./build/bin/fxbench; on the GPU machine
# FXBENCH="bash .gpu/run-egl.sh fxbench", with --backend egl --size 1920x1080). Default options:
# the standard scene, 8 frames, 2 rounds, no error frames. Runs alternate variant by variant,
# twice; the table gives each pass's two medians.
set -euo pipefail
cd "$(dirname "$0")/.."

# Step 1: each variant a copy of shaders/ in $1/<variant>; their names in $1/variants.
# Each variant: (file, text that must be there exactly once, replacement).
prepare() {
    python3 - "$1" <<'PY'
import pathlib, sys
sys.dont_write_bytecode = True
sys.path.insert(0, "scripts")
from shader_copies import write_copies
work = pathlib.Path(sys.argv[1])
variants = {
    # Soft without its fade: the scene-depth fetch, its decode and the contrast curve gone.
    "soft-no-fade": [("fs_particles_soft.glsl", "fade = softFade(sceneDepthTexelAt(gl_FragCoord.xy), vFadeLine);",
                      "fade = 1.0;")],
    # The full-res particle shaders' scene depth read without its decode (the division: soft's
    # in its fade, spherical's in sceneDepthAt; the quarter-res builds read theirs without one
    # already: FX_HALF_RES_DEPTH).
    "no-depth-decode": [("particles_common.glsl", "float v = (line.x + line.y * d) / (uDepthCoeffs.z + uDepthCoeffs.w * d);",
                         "float v = line.x + line.y * d;"),
                        ("particles_common.glsl", "float t = decodedSceneDepth(sceneDepthTexelAt(fragCoord));",
                         "float t = sceneDepthTexelAt(fragCoord) * 1000.0;")],
    # Spherical without the scene depth: the chord clipped by the near plane only.
    "sphere-no-depth": [("fs_particles_spherical.glsl", "float sceneZ = sceneDepthAt(gl_FragCoord.xy);",
                         "float sceneZ = 3.0e38;")],
    # Spherical without the chord: the atlas alpha at the closest approach alone.
    "sphere-no-chord": [("fs_particles_spherical.glsl",
                         "float coverage = texel.a * visible * nearFadeFactor(0.5 * (z0 + z1));",
                         "float coverage = texel.a;")],
    # The composite as before FX_GATHER_FARTHEST: every smoky pixel reads its full-resolution
    # depth, not only those whose footprint's gathered depths span an edge. The same picture.
    "composite-full-depth": [("fs_particles_composite.glsl", "#if defined(FX_GATHER_FARTHEST)", "#if 0")],
    # The composite without its edge test: plain bilinear (one fetch a pixel).
    "composite-no-edges": [("fs_particles_composite.glsl", "#if defined(FX_COMPOSITE_BILINEAR)", "#if 1")],
    # The scene depth read with texelFetch instead of textureLod through the nearest sampler: the
    # same texel (the picture is the same bit for bit), a load instead of a filtered sample. The
    # shaders take textureLod because llvmpipe bounds-checks every texelFetch lane; a GPU may
    # prefer the load. The texel's offset is worked out per fragment here (a division of two
    # uniforms), which only counts against the load.
    "depth-texelfetch": [("particles_common.glsl",
                          "return textureLod(uSceneDepth, fragCoord * uDepthUv.zw + uDepthUv.xy, 0.0).r;",
                          "return texelFetch(uSceneDepth, ivec2(fragCoord + uDepthUv.xy / uDepthUv.zw), 0).r;")],
    # One part added, not left out: as the spherical shader does, a fragment whose coverage is 0
    # (output exactly 0: the atlas's empty rim inside a trimmed polygon) is discarded, so it costs
    # no blend. The picture is the same bit for bit; fxbench's standard frames at 1920x1080 discard
    # 11 % of hard's and soft's samples. Hard and soft have no discard otherwise.
    "discard-empty": [(f, "    oColor = shadeOutput(vTint, vFogAdd, texel.rgb, coverage);",
                       "    if (coverage == 0.0) discard;\n"
                       "    oColor = shadeOutput(vTint, vFogAdd, texel.rgb, coverage);")
                      for f in ("fs_particles_hard.glsl", "fs_particles_soft.glsl")],
}
# What one operation costs a fragment: hard with 16 dependent multiply-adds more, which the
# compiler cannot fold (they go through a uniform it does not know, left at its default 0) and
# which add exactly 0 to the coverage, so the picture is the same bit for bit. Its pass time over
# hard's, divided by 16, is the slope to read the counts of scripts/shader_ops.py by.
chain = "".join("    ops = ops * uShaderPartsZero + vAtlasUV.y;\n" for _ in range(16))
variants["hard-16-ops"] = [
    ("fs_particles_hard.glsl", "    float coverage = texel.a;",
     "    float ops = vAtlasUV.x;\n" + chain + "    float coverage = texel.a + ops * uShaderPartsZero;"),
    ("fs_particles_hard.glsl", "layout(location = 0) out vec4 oColor;",
     "layout(location = 0) out vec4 oColor;\nuniform float uShaderPartsZero;")]
# Soft without the discard before its scene-depth fetch (where the atlas alone says the output
# is 0): what that early out saves (H200, session 21: 1.690 against 1.622 ms).
variants["soft-fetch-empty"] = [
    ("fs_particles_soft.glsl", "    if (texel.a == 0.0) discard;\n", "")]
# Spherical's discards (off the outline, an empty atlas texel at the closest approach) before
# its scene-depth fetch instead of after it: fewer fetches, but the fetch then waits for the
# atlas's. Soft gained from the same order on the H200 (session 21); the sphere's order was
# chosen for the two fetches' overlap and has not been timed against it.
variants["sphere-empty-before-fetch"] = [
    ("fs_particles_spherical.glsl",
     "    float sceneZ = sceneDepthAt(gl_FragCoord.xy);\n    if (d2 >= r2) discard;\n",
     "    if (d2 >= r2 || texel.a == 0.0) discard;\n    float sceneZ = sceneDepthAt(gl_FragCoord.xy);\n")]
# The fragment shader reduced to one blended write of nearly nothing: what is left of a pass is
# its vertices, rasterisation, varyings and blending. Against the pass as it is: the fragment
# shader's own cost (spherical's pass is 3.681 ms against hard's 1.205 on the H200, with 1.34
# times the samples; its depth fetch is 0.36 ms of it and its chord nothing).
for name, file in (("hard-fs-trivial", "fs_particles_hard.glsl"), ("sphere-fs-trivial", "fs_particles_spherical.glsl")):
    variants[name] = [(file, "void main() {\n", "void main() {\n    oColor = vec4(0.0, 0.0, 0.0, 1.0 / 255.0);\n    return;\n")]
write_copies(work, variants, "shader_parts.sh")
(work / "variants").write_text("\n".join(variants) + "\n")
PY
}

# The variants that only try a cheaper way to the same picture.
same_picture=(depth-texelfetch discard-empty soft-fetch-empty hard-16-ops sphere-empty-before-fetch composite-full-depth)

# fxbench over the modes the variants touch, with the shaders of variant $2 of the copies in $1
# ("now": the shaders built into fxbench); the rest: fxbench options.
fxbench_with() {
    local parts=$1 variant=$2
    shift 2
    local fxbench shaderDir=""
    read -r -a fxbench <<< "${FXBENCH:-./build/bin/fxbench}"
    [ "${fxbench[0]}" != ./build/bin/fxbench ] || [ -x ./build/bin/fxbench ] ||
        { echo "shader_parts.sh: build first (./run.sh or cmake --build build)" >&2; exit 1; }
    # An empty CUBE_SHADER_DIR means the shaders built into fxbench (engine_stub/gl/Paths.cpp).
    [ "$variant" = now ] || shaderDir=$(cd "$parts/$variant" && pwd)
    CUBE_SHADER_DIR="$shaderDir" "${fxbench[@]}" --modes hard,soft,spherical,soft+quarter-always "$@"
}

# Step 2 (bash only): fxbench with its built-in shaders ("now") and with each copy in $1, twice,
# alternating; into $2/<variant>.<round>.json. The rest: fxbench options.
run() {
    local parts=$1 out=$2
    shift 2
    [ -f "$parts/variants" ] || { echo "shader_parts.sh: no $parts/variants (--prepare first)" >&2; exit 1; }
    local args=("$@")
    [ ${#args[@]} -gt 0 ] || args=(--frames 8 --rounds 2)
    mkdir -p "$out"
    cp "$parts/variants" "$out/variants"
    local variants round variant
    mapfile -t variants < "$parts/variants"
    for round in 1 2; do
        for variant in now "${variants[@]}"; do
            fxbench_with "$parts" "$variant" --error-frames 0 "${args[@]}" --json "$out/$variant.$round.json" >/dev/null
        done
    done
}

# Whether the same_picture variants draw what the shaders as they are draw, byte for byte: one
# frame's PNGs (fxbench --images) of each. The rest: fxbench options.
same_pictures() {
    local work
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
    prepare "$work/parts"
    local variant mode status=0
    for variant in now "${same_picture[@]}"; do
        fxbench_with "$work/parts" "$variant" --frames 1 --rounds 1 --warmup 1 --error-frames 1 "$@" \
            --images "$work/$variant" >"$work/$variant.log" 2>&1 || { cat "$work/$variant.log" >&2; exit 1; }
    done
    for mode in hard soft spherical soft-quarter-always; do
        for variant in "${same_picture[@]}"; do
            if ! cmp -s "$work/now/standard_$mode.png" "$work/$variant/standard_$mode.png"; then
                echo "shader_parts.sh: $variant draws $mode differently (or not at all)" >&2
                status=1
            fi
        done
    done
    [ "$status" -eq 0 ] && echo "shader_parts.sh: ${same_picture[*]}: the same pictures of hard, soft, spherical and soft+quarter-always"
    exit "$status"
}

# Step 3: the table of the runs in $1.
table() {
    local variants
    mapfile -t variants < "$1/variants"
    python3 - "$1" now "${variants[@]}" <<'PY'
import json, sys
work, variants = sys.argv[1], sys.argv[2:]
import os
def passes(variant, round):  # a run cut short (a device call's time limit) is left out: "-"
    path = f"{work}/{variant}.{round}.json"
    if not os.path.exists(path):
        return {}
    run = json.load(open(path))
    return {(m["name"], p): ms for m in run["modes"] for p, ms in m["passes_ms"].items() if "particles" in p}
runs = {v: [passes(v, 1), passes(v, 2)] for v in variants}
rows = list(runs["now"][0])
print("Per-pass median ms, two runs each (" + json.load(open(f"{work}/now.1.json"))["timing_method"] + ")\n")
print("| mode | pass | " + " | ".join(variants) + " |")
print("|---|---|" + "---:|" * len(variants))
for mode, p in rows:
    cells = []
    for v in variants:
        a, b = (r.get((mode, p)) for r in runs[v])
        cells.append("-" if a is None or b is None else f"{a:.3f}, {b:.3f}")
    print(f"| {mode} | {p} | " + " | ".join(cells) + " |")
PY
}

case "${1:-}" in
    --check)
        work=$(mktemp -d)
        trap 'rm -rf "$work"' EXIT
        prepare "$work"
        echo "shader_parts.sh: every part found ($(tr '\n' ' ' < "$work/variants"))" ;;
    --same-pictures) same_pictures "${@:2}" ;;
    --prepare) prepare "${2:?--prepare DIR}" ;;
    --run) run "${2:?--run DIR OUT}" "${3:?--run DIR OUT}" "${@:4}" ;;
    --table) table "${2:?--table OUT}" ;;
    *)
        work=$(mktemp -d)
        trap 'rm -rf "$work"' EXIT
        prepare "$work/parts"
        run "$work/parts" "$work/out" "$@"
        table "$work/out" ;;
esac
