#!/usr/bin/env bash
# The tiled path before and after a change to its shaders, and its list limit, in one device call
# (about a minute and a half of device time on an H200, start included). Each run is its own
# fxbench process (pass times are GPU timer queries, so the variants need not share a run):
#   old   the shaders of an earlier commit (CUBE_SHADER_DIR=.gpu/old/shaders)
#   new   this tree's shaders
# in the fill scene at 1080p, the standard one at 4K and at 1080p, with the lists always written on
# the GPU (CUBEFX_TILED_CPU_LISTS=0); then the limit below which the CPU writes the lists
# (TiledPath::kCpuListEntries) at 0, 16,384 and 131,072 entries in the standard and fill scenes and
# a sweep of small particle counts; lit smoke's image error against the raster path in the fill and
# standard scenes (PNGs of the fill one). Set OLD_ROWS=16 where the old shaders predate
# TileSort::rowsFor (their blocks are 16 rows).
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
        old) echo "CUBE_SHADER_DIR=$old CUBEFX_TILE_SORT_ROWS=${OLD_ROWS:-0}" ;;
        *) echo "CUBEFX_TILE_SORT_ROWS=0" ;;
    esac
}
for sc in "fill 1920x1080" "standard 3840x2160" "standard 1920x1080"; do
    set -- $sc
    for v in old new; do
        run "${1}_${2}_gpu_$v" env CUBEFX_TILED_CPU_LISTS=0 $(variant $v) $F --scenario "$1" --size "$2" \
            --frames 10 --error-frames 0 --modes $modes
    done
done
for lim in 0 16384 131072; do
    for sc in standard fill; do
        run "limit_${sc}_$lim" env CUBEFX_TILED_CPU_LISTS=$lim $F --scenario $sc --size 1920x1080 --frames 10 \
            --error-frames 0 --modes hard,soft+tiled,spherical+tiled
    done
    run "limit_sweep_$lim" env CUBEFX_TILED_CPU_LISTS=$lim $F --size 1920x1080 --sweep particles=1000,4000,16000 \
        --frames 8 --error-frames 0 --modes hard,soft+tiled,spherical+tiled
done
lit=soft-lit,soft-lit+tiled,spherical-lit,spherical-lit+tiled
run lit_fill $F --scenario fill --size 1920x1080 --frames 4 --error-frames 1 --modes $lit --images "$R/img-fill"
run lit_standard $F --scenario standard --size 1920x1080 --frames 4 --error-frames 2 --modes $lit
tar czf "$out/ab.tgz" -C "$R" --exclude=img-fill .
[ -d "$R/img-fill" ] && tar cf - -C "$R" img-fill | gzip -1 | split -b 15m - "$out/abimg.tgz."
ls -la "$out"
