#!/usr/bin/env bash
# Builds the libFuzzer targets with clang and runs each for a bounded time (FUZZ_SECONDS, default
# 60; the C table's target FUZZ_CAPI_SECONDS, default 30) on a seed corpus from reactions/, data/
# and fuzz/seeds/. Any crash, leak or sanitizer report fails the
# script; the crashing input is copied into fuzz/regressions/<target>/ so it becomes a test.
# Then every file in fuzz/regressions/ is replayed once (the regression tests).
set -euo pipefail
cd "$(dirname "$0")/.."
CUBE_WITH_CLANG=1 bash scripts/deps.sh
seconds="${FUZZ_SECONDS:-60}"
build=build-fuzz
# Line tables only (-g1: a report's file:line) and a unity build: on two cores 175 s -> 80 s.
CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCUBE_FUZZ=ON -DCMAKE_UNITY_BUILD=ON \
      "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" >/dev/null
cmake --build "$build" -j"$(nproc)" --target fuzz_reactions fuzz_scene fuzz_legacy fuzz_capi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/corpus_reactions" "$work/corpus_scene" "$work/corpus_legacy" "$work/corpus_capi"
cp reactions/*.yaml data/legacy_smoke.yaml "$work/corpus_reactions/"
cp data/legacy_smoke.yaml "$work/corpus_legacy/"
cp data/race.gltf data/race.glb "$work/corpus_scene/"
# Hand-made seeds for the classes of bad input each loader must refuse (alias bombs,
# recipes with a bad layer): fuzz/seeds/<target>/.
for target in reactions legacy; do
  [ -d "fuzz/seeds/$target" ] && cp fuzz/seeds/$target/* "$work/corpus_$target/"
done
# Seeds for the limits: JSON nested past the pre-scan's depth (in extras) and a long node chain.
python3 - "$work/corpus_scene" <<'PY'
import json, sys
d = sys.argv[1]
race = open("data/race.gltf").read().rstrip()
open(d + "/deep_extras.gltf", "w").write(race[:-1] + ', "extras": ' + "[" * 3000 + "]" * 3000 + "}")
m = json.loads(race)
n = len(m["nodes"])
m["nodes"] += [{"children": [n + i + 1]} for i in range(199)] + [{"name": "leaf"}]
m["scenes"][0]["nodes"].append(n)
open(d + "/chain.gltf", "w").write(json.dumps(m))
PY

# The C table: a good descriptor (byte 40 has bit 7 set) followed by one of each call, and a
# descriptor of 0xAB bytes.
python3 - "$work/corpus_capi" <<'PY'
import struct, sys
d = sys.argv[1]
good = bytes(40) + b"\x81" + struct.pack("<I", 64)
calls = b"".join(bytes([k]) + struct.pack("<ifff", 0, 1.0 / 60, 0.5, 0.0) for k in range(14))
open(d + "/good_calls", "wb").write(good + calls)
open(d + "/garbage_desc", "wb").write(b"\xab" * 48)
PY

status=0
for target in reactions scene legacy capi; do
  target_seconds="$seconds"
  [ "$target" = capi ] && target_seconds="${FUZZ_CAPI_SECONDS:-30}"
  echo "fuzz: $target for ${target_seconds}s"
  mkdir -p "fuzz/regressions/$target"
  if ! ASAN_OPTIONS=detect_leaks=1 "$build/bin/fuzz_$target" -max_total_time="$target_seconds" -timeout=10 \
       -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix="$work/crash_${target}_" \
       "$work/corpus_$target" >"$work/log_$target" 2>&1; then
    tail -40 "$work/log_$target"
    for f in "$work"/crash_${target}_*; do
      [ -e "$f" ] && cp "$f" "fuzz/regressions/$target/" && echo "fuzz: kept $(basename "$f") as a regression input"
    done
    status=1
  else
    grep -E "^(stat::number_of_executed_units|stat::new_units_added|Done)" "$work/log_$target" || true
  fi
  # Regression inputs: each must run clean.
  shopt -s nullglob
  inputs=(fuzz/regressions/$target/*)
  if [ ${#inputs[@]} -gt 0 ]; then
    "$build/bin/fuzz_$target" "${inputs[@]}" >"$work/replay_$target" 2>&1 || { tail -20 "$work/replay_$target"; status=1; }
    echo "fuzz: replayed ${#inputs[@]} regression input(s) for $target"
  fi
done
exit $status
