#!/usr/bin/env bash
# The tiled path's back-to-front order sorted on the GPU (TileSort::DepthOrder) against the CPU's
# sort, in one device call (about four minutes of device time on an H200). Each run is its own
# fxbench process, the two variants alternating (the host's CPU time has varied by up to 2 x
# between processes on the H200: compare the rounds, and within each run the passes):
#   cpu   CUBEFX_TILED_GPU_ORDER=4294967295 (never: the draw list sorts on the CPU, as before)
#   gpu   CUBEFX_TILED_GPU_ORDER=0 (every tiled view: the list is built unsorted, the GPU sorts)
# a sweep of 16,000 to 256,000 particles (two rounds), 1,000,000 particles (one round), and the
# standard and fill scenes at 1080p (a few hundred particles: what the GPU's order costs where the
# default, TileSort::kOrderParticles, leaves it to the CPU).
# Here, after a build:
#   ../shared/gpu/pack.sh
# The device call, with .gpu carried along:
#   bash scripts/gpu_order_ab.sh
# Into $OUT: order.tgz (each run's JSON and table, the log).
set -u
cd "$(dirname "$0")/.."
out=${OUT:-/tmp/gpu-out}
R=/tmp/gpu-order
rm -rf "$R"
mkdir -p "$out" "$R"
if [ ! -f .gpu/run-egl.sh ]; then
    echo "gpu_order_ab.sh: pack first (see the header)" >&2
    exit 1
fi
F="bash .gpu/run-egl.sh fxbench --backend egl --size 1920x1080"
run() {
    local name=$1 limit=$2 s
    shift 2
    s=$(date +%s)
    CUBEFX_TILED_GPU_ORDER=$limit timeout 90 "$@" --json "$R/$name.json" > "$R/$name.txt" 2>&1
    echo "$name rc=$? $(( $(date +%s) - s ))s" | tee -a "$R/log"
}
never=4294967295
for round in 1 2; do
    for v in cpu gpu; do
        limit=$never
        [ $v = gpu ] && limit=0
        run "sweep_${v}_$round" $limit $F --sweep particles=16000,64000,256000 --frames 6 --error-frames 0 \
            --modes hard,soft+tiled,spherical+tiled
    done
done
for v in cpu gpu; do
    limit=$never
    [ $v = gpu ] && limit=0
    run "million_$v" $limit $F --sweep particles=1000000 --frames 4 --error-frames 0 --modes soft+tiled
    for sc in standard fill; do
        run "${sc}_$v" $limit $F --scenario $sc --frames 10 --error-frames 1 --modes hard,soft+tiled,spherical+tiled
    done
done
tar czf "$out/order.tgz" -C "$R" .
ls -la "$out"
