#!/usr/bin/env bash
# The tiled path's GPU-written lists and lit smoke, before and after a change to their shaders, in
# one device call (about two minutes of device time on an H200, start included). Three variants of
# the same binary, each its own fxbench process (pass times are GPU timer queries, so the variants
# need not share a run):
#   old   the shaders of an earlier commit (CUBE_SHADER_DIR=.gpu/old/shaders) with the sort's blocks
#         of 16 rows that they were written for (CUBEFX_TILE_SORT_ROWS=16)
#   rows16  this tree's shaders, blocks of 16 rows
#   new   this tree's shaders, TileSort::rowsFor's rows
# in the scenes whose lists are long (fill at 1080p, standard at 4K) and the standard one at 1080p,
# with the lists always written on the GPU (CUBEFX_TILED_CPU_LISTS=0); then the standard scene's
# default (CPU-written lists below TiledPath::kCpuListEntries), a particle sweep, and lit smoke's
# image error against the raster path in the fill and standard scenes (PNGs of the fill one).
# Here, after a build:
#   ../shared/gpu/pack.sh && mkdir -p .gpu/old && git archive <commit> shaders | tar x -C .gpu/old
# The device call, with .gpu carried along:
#   bash scripts/gpu_tiled_ab.sh
# Into $OUT: ab.tgz (each run's JSON and table, the log) and abimg.tgz.* (the fill scene's PNGs).
set -u
cd "$(dirname "$0")/.."
out=${OUT:-/tmp/gpu-out}
R=/tmp/gpu-ab
rm -rf "$R"
mkdir -p "$out" "$R"
if [ ! -d .gpu/old/shaders ] || [ ! -f .gpu/run-egl.sh ]; then
    echo "gpu_tiled_ab.sh: pack first (see the header)" >&2
    exit 1
fi
old=$PWD/.gpu/old/shaders
F="bash .gpu/run-egl.sh fxbench --backend egl"
modes=hard,soft+tiled,spherical+tiled,soft-lit+tiled
run() {
    local name=$1 s
    shift
    s=$(date +%s)
    timeout 60 "$@" --json "$R/$name.json" > "$R/$name.txt" 2>&1
    echo "$name rc=$? $(( $(date +%s) - s ))s" | tee -a "$R/log"
}
variant() {
    case $1 in
        old) echo "CUBE_SHADER_DIR=$old CUBEFX_TILE_SORT_ROWS=16" ;;
        rows16) echo "CUBEFX_TILE_SORT_ROWS=16" ;;
        *) echo "CUBEFX_TILE_SORT_ROWS=0" ;;
    esac
}
for sc in "fill 1920x1080" "standard 3840x2160" "standard 1920x1080"; do
    set -- $sc
    for v in old rows16 new; do
        run "${1}_${2}_gpu_$v" env CUBEFX_TILED_CPU_LISTS=0 $(variant $v) $F --scenario "$1" --size "$2" \
            --frames 10 --error-frames 0 --modes $modes
    done
done
run standard_1920x1080_default $F --scenario standard --size 1920x1080 --frames 10 --error-frames 0 --modes $modes
for v in old new; do
    run "sweep_$v" env $(variant $v) $F --size 1920x1080 --sweep particles=16000,256000 --frames 6 --error-frames 0 \
        --modes hard,soft+tiled,spherical+tiled
done
lit=soft-lit,soft-lit+tiled,spherical-lit,spherical-lit+tiled
run lit_fill $F --scenario fill --size 1920x1080 --frames 4 --error-frames 1 --modes $lit --images "$R/img-fill"
run lit_standard $F --scenario standard --size 1920x1080 --frames 4 --error-frames 2 --modes $lit
tar czf "$out/ab.tgz" -C "$R" --exclude=img-fill .
[ -d "$R/img-fill" ] && tar cf - -C "$R" img-fill | gzip -1 | split -b 15m - "$out/abimg.tgz."
ls -la "$out"
