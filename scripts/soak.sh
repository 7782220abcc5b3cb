#!/usr/bin/env bash
# Soak: cube_game headless for SOAK_FRAMES (default 20000) frames with --watch while another
# process keeps rewriting a reaction file: good edits, a bad edit, a missing key, then good
# again. Checks at the end (bounds stated here, asserted below):
#   - exit status 0 and no GL error;
#   - resident memory grows by less than 16 MiB between frame 300 and the last frame;
#   - the render-target pool is flat: the most textures/framebuffers alive at once over the whole
#     run equals the most in the first 18 s loop of the drive after warm-up (which passes run,
#     and so which targets live, changes with the frame; the maximum must not creep up);
#   - reloads happened and bad edits were rejected, and the final good set (3 reactions) is live.
# usage: soak.sh <cube_game binary> <source dir>
set -euo pipefail
game="$1"; src="$2"
frames="${SOAK_FRAMES:-20000}"
work=$(mktemp -d)
trap 'kill $writer 2>/dev/null || true; rm -rf "$work"' EXIT
cp "$src"/reactions/burnout_smoke.yaml "$src"/reactions/offtrack_dust.yaml "$src"/reactions/barrier_burst.yaml "$work/"
good="$work/burnout_smoke.yaml"
cp "$good" "$work/good.yaml.orig"

# The writer: alternates a good variant (rate changed), a broken one and the original.
(
  i=0
  while true; do
    case $((i % 3)) in
      0) sed -E "s/^( *rate: *)[0-9.]+/\1$((20 + i % 40))/" "$work/good.yaml.orig" > "$good.tmp" ;;
      1) printf 'reactions:\n  - name: burnout_smoke\n    type: wheel_smoke\n    emission: {rate: fast}\n' > "$good.tmp" ;;
      2) cp "$work/good.yaml.orig" "$good.tmp" ;;
    esac
    mv "$good.tmp" "$good"
    i=$((i + 1))
    sleep 0.4
  done
) &
writer=$!

"$game" --frames "$frames" --fixed-dt 0.0166667 --size 160x128 --watch --reactions "$work" \
        --no-hud --stats-json "$work/stats.json" >"$work/log" 2>&1 || { tail -20 "$work/log"; echo "soak: cube_game failed"; exit 1; }
kill $writer 2>/dev/null || true
wait $writer 2>/dev/null || true
# Leave the good file in place, give the game no more frames: check the JSON of the run.
python3 - "$work/stats.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
problems = []
grow = s["rss_kb_end"] - s["rss_kb_after_300_frames"]
if s["gl_errors"] != 0: problems.append("GL errors: %d" % s["gl_errors"])
if grow > 16 * 1024: problems.append("resident memory grew by %d KiB (bound 16384)" % grow)
if s["reloads"] < 3: problems.append("only %d reloads went live" % s["reloads"])
if s["reload_errors"] < 3: problems.append("only %d bad edits were rejected" % s["reload_errors"])
if s["reactions"] != 3: problems.append("%d reactions live at the end (expected 3)" % s["reactions"])
if (s["pool_max_live_textures"], s["pool_max_live_framebuffers"]) != (s["pool_max_live_textures_first_loop"], s["pool_max_live_framebuffers_first_loop"]):
    problems.append("render-target pool grew: most live textures %d in the first loop, %d over the run; framebuffers %d, %d" % (
        s["pool_max_live_textures_first_loop"], s["pool_max_live_textures"],
        s["pool_max_live_framebuffers_first_loop"], s["pool_max_live_framebuffers"]))
print("soak: frames %d, rss after 300 frames %d KiB, at end %d KiB (growth %d KiB), reloads %d, rejected %d, "
      "most live pool textures %d (first loop) / %d (run), framebuffers %d / %d" % (s["frames"],
      s["rss_kb_after_300_frames"], s["rss_kb_end"], grow, s["reloads"], s["reload_errors"],
      s["pool_max_live_textures_first_loop"], s["pool_max_live_textures"],
      s["pool_max_live_framebuffers_first_loop"], s["pool_max_live_framebuffers"]))
if problems:
    print("soak: FAILED: " + "; ".join(problems)); sys.exit(1)
print("soak: passed")
PY
