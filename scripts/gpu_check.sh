#!/usr/bin/env bash
# A session's whole GPU check in one device call (../shared/gpu/run-all.sh's tables, then the
# blocks below, most wanted first, each started only while the call has time left: at most about
# ten minutes of device time, so a lent machine's fifteen hold it). It needs no python3 there.
# Here, after a build:
#   ../shared/gpu/pack.sh && scripts/shader_parts.sh --prepare .gpu/parts
# The device call, with .gpu carried along:
#   bash scripts/gpu_check.sh
# Into $OUT: run-all.sh's data.tgz and img.tgz.* (standard, fill, overdraw, 4K, the particle sweep,
# the drive through both depth paths) and parts.tgz (shader_parts.sh's runs and their log, a
# particle sweep of the tiled modes: parts/tiled_sweep.json, and the tiled path's list limit in
# three settings: parts/lists_*.json; lit smoke rasterised and tiled: parts/lit_*.json; the tiled
# path's bins while declared, in its pass on the host's threads or by the GPU, the last with the
# particles written while declared or in the pass: parts/bins_{declared,cpu,list,gpu}_*.json;
# the tiled pass's GPU time by stage at 64,000 and 256,000 particles: parts/stages.txt;
# quarter res's choice in its pass or
# while declared: parts/choice_*.json; where
# bench_draw was packed too, its bins, cull, bound and the tiled pass's gather and copy on the host's
# threads: parts/bench_draw.json).
# Back here: tar xzf parts.tgz -C /tmp && scripts/shader_parts.sh --table /tmp/parts
# (With bench_draw: ../shared/gpu/pack.sh build fxbench cube_game bench_sim bench_draw.)
set -u
cd "$(dirname "$0")/.."
out=${OUT:-/tmp/gpu-out}
mkdir -p "$out"
if [ ! -f .gpu/run-all.sh ] || [ ! -f .gpu/parts/variants ]; then
    echo "gpu_check.sh: pack first: ../shared/gpu/pack.sh && scripts/shader_parts.sh --prepare .gpu/parts" >&2
    exit 1
fi
# The blocks run in the order below, most wanted first, each only while the call has time left:
# the run tool stops a command at 600 s, and what is not packed by then does not come back (the
# tables of run-all.sh are packed by it). A block starts only before kBudget seconds.
start=$(date +%s)
kBudget=${GPU_CHECK_BUDGET:-470}
mkdir -p "$out/parts"
: > "$out/parts.log"
pack() {
    [ -d "$out/parts" ] || return 0
    tar czf "$out/parts.tgz" -C "$out" parts parts.log && rm -rf "$out/parts" "$out/parts.log"
}
trap pack EXIT
block() {
    local elapsed=$(( $(date +%s) - start ))
    if [ "$elapsed" -ge "$kBudget" ]; then
        echo "skipped $1: ${elapsed}s of ${kBudget}s gone" | tee -a "$out/parts.log"
        return 0
    fi
    "$1"
}
# One fxbench run into parts/NAME.json and parts/NAME.txt under `timeout LIMIT`, then its rc and the
# block's seconds so far into parts.log. Environment settings (VAR=value) go before the options.
fx_part() {
    local name=$1 limit=$2
    shift 2
    local vars=()
    while [ $# -gt 0 ] && [[ $1 != -* ]]; do vars+=("$1"); shift; done
    env ${vars[@]+"${vars[@]}"} timeout "$limit" bash .gpu/run-egl.sh fxbench --backend egl "$@" \
        --json "$out/parts/$name.json" > "$out/parts/$name.txt" 2>&1
    echo "$name rc=$? $(( $(date +%s) - s ))s" | tee -a "$out/parts.log"
}
shader_parts_runs() {
    s=$(date +%s)
    local limit=$(( 570 - ($(date +%s) - start) ))
    [ "$limit" -le 300 ] || limit=300
    FXBENCH="bash .gpu/run-egl.sh fxbench" timeout "$limit" bash scripts/shader_parts.sh --run .gpu/parts "$out/parts" \
        --backend egl --size 1920x1080 >> "$out/parts.log" 2>&1
    echo "shader_parts rc=$? $(( $(date +%s) - s ))s" | tee -a "$out/parts.log"
}
tiled_sweep() {
    # The tiled compute path (TiledPath.h) against the raster one as the particle count grows: run-all's
    # tables have the tiled modes at their scenes' counts, its sweep not. 256,000: where session 24's
    # CPU binning (37 ms outside the passes) bounded it; since session 25 the GPU writes the lists.
    s=$(date +%s)
    fx_part tiled_sweep 150 --size 1920x1080 --sweep particles=1000,16000,64000,256000 \
        --frames 6 --error-frames 0 --modes hard,soft,soft+tiled,spherical,spherical+tiled
}
bins_ab() {
    # Where a view the GPU orders is binned (sessions 32-35): while declared on the host's threads
    # (CUBEFX_TILED_DEFER_BINS=0), in its second pass on the host's threads (CUBEFX_TILED_GPU_BINS=0),
    # or by the GPU, queued in its first pass behind the order and the records and read back in the
    # second (the default since session 35, TiledPath::gpuBins), in alternating processes. Compare the
    # frames first; since session 33 the time the GPU idles while the CPU bins falls between the two
    # passes (outside), so "outside" is comparable too; the GPU's read-back wait falls there as well.
    # With the GPU's bins, the particles written while declared and copied in the first pass
    # (CUBEFX_TILED_GATHER_IN_PASS=0, way "list") or written by that pass from the pools (the
    # default since session 36): compare cpu_declare_ms and the frames of "list" and "gpu".
    s=$(date +%s)
    for round in 1 2; do
      for way in declared cpu list gpu; do
        case $way in
          declared) env="CUBEFX_TILED_DEFER_BINS=0" ;;
          cpu) env="CUBEFX_TILED_GPU_BINS=0" ;;
          list) env="CUBEFX_TILED_GATHER_IN_PASS=0" ;;
          gpu) env="CUBEFX_TILED_GPU_BINS=1" ;;
        esac
        fx_part "bins_${way}_${round}" 90 "$env" --size 1920x1080 \
            --sweep particles=16000,64000,256000 --frames 8 --error-frames 0 --modes hard,soft+tiled
      done
    done
}
stage_times() {
    # Where the tiled pass's GPU time goes at scale (TiledStageTimes, session 35): each stage of a view
    # binned in its pass timed with GL_TIMESTAMP queries, the medians of 64 views in the log line
    # "fx: tiled stages, GPU ms": order, records, bins, wait, emit, pair sort, shade, composite.
    s=$(date +%s)
    fx_part stages 90 CUBEFX_TILED_STAGE_TIMES=1 --size 1920x1080 \
        --sweep particles=64000,256000 --frames 66 --rounds 1 --warmup 2 --error-frames 0 --modes soft+tiled
    grep "tiled stages" "$out/parts/stages.txt" | tee -a "$out/parts.log"
}
choice_ab() {
    # Quarter res's choice in the view's first pass (session 34, QuarterResPath::choiceInPass), after the
    # scene went to the GPU, against chosen while declared (CUBEFX_QUARTER_CHOICE_IN_PASS=0), in
    # alternating processes: #36's soft+quarter / soft at 1,000 particles (1.058 in session 29, the
    # bound's 65 us of CPU before any GPU work) and a point where quarter res pays.
    s=$(date +%s)
    for round in 1 2; do
      for c in 0 1; do
        fx_part "choice_${c}_${round}" 60 "CUBEFX_QUARTER_CHOICE_IN_PASS=$c" --size 1920x1080 \
            --sweep particles=1000,64000 --frames 20 --error-frames 0 --modes hard,soft,soft+quarter
      done
    done
}
list_limits() {
    # Where the tiled path's lists stop being the CPU's (TiledPath::kCpuListEntries, 0 by default since
    # session 28): the GPU sort always (0), the old default, and the CPU's up to 4 M entries, in the scenes
    # whose lists are long (fill at 1080p: about 520,000 entries; standard at 4K: about 277,000).
    s=$(date +%s)
    for lim in 0 131072 4194304; do
      for sc in "fill 1920x1080" "standard 3840x2160"; do
        set -- $sc
        fx_part "lists_${1}_${lim}" 60 "CUBEFX_TILED_CPU_LISTS=$lim" --scenario "$1" --size "$2" \
            --frames 10 --error-frames 0 --modes hard,soft+tiled,spherical+tiled
      done
    done
}
lit_smoke() {
    # Lit smoke, rasterised and tiled (the game's drive lights its smoke, and Tiling::Auto now tiles it
    # on a GPU): the standard scene at 1080p and 4K.
    s=$(date +%s)
    for size in 1920x1080 3840x2160; do
      fx_part "lit_${size}" 60 --scenario standard --size "$size" --frames 10 \
          --error-frames 0 --modes hard,soft-lit,soft-lit+tiled,spherical-lit,spherical-lit+tiled
    done
}
bench_draw_rows() {
    # The view's CPU work on the GPU host's threads (session 31: the cull and bins of 16,000 particles
    # in seven pieces, not one; the bound in three): bench_draw's job-system rows, 1 thread to all.
    if [ -x .gpu/bin/bench_draw ]; then
      s=$(date +%s)
      timeout 120 bash .gpu/run-egl.sh bench_draw \
          --benchmark_filter='BM_TileBins/(16000|256000)/|BM_DrawListBuildJobs/(16000|256000)/|BM_ScreenRectJobs/(16000|256000)/|BM_(Gather|Copy)Jobs/(16000|256000)/' \
          --benchmark_min_time=0.1 --benchmark_out="$out/parts/bench_draw.json" --benchmark_out_format=json \
          > "$out/parts/bench_draw.txt" 2>&1
      echo "bench_draw rc=$? $(( $(date +%s) - s ))s" | tee -a "$out/parts.log"
    fi
}

bash .gpu/run-all.sh
block bins_ab
block stage_times
block choice_ab
block tiled_sweep
block shader_parts_runs
block list_limits
block lit_smoke
block bench_draw_rows
pack
trap - EXIT
ls -la "$out"
