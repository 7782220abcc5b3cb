#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test:
#   1. the unit, GL and tool tests (ctest, optimized build in build/: scripts/configure.sh)
#   2. the same suite under AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/)
#   3. the soak (ctest label "soak": 20,000 frames with reaction files rewritten under --watch)
#   4. libFuzzer on the reaction and scene loaders, about a minute each, and on the C table's
#      descriptors and numbers, 30 s, plus the kept crashers
# CUBE_TEST_STAGES (default "unit sanitize soak fuzz") picks stages, e.g. CUBE_TEST_STAGES=unit.
# The soak keeps about one core busy and each fuzzer one, so the soak runs in the background
# while the stages after it run; its log is printed and counted at the end.
set -uo pipefail
cd "$(dirname "$0")"
stages="${CUBE_TEST_STAGES:-unit sanitize soak fuzz}"
passed=0; failed=0
count() {  # reads a ctest log, adds its totals
  local line
  line=$(grep -E "tests passed, [0-9]+ tests failed out of [0-9]+" "$1" | tail -1)
  if [ -n "$line" ]; then
    local total f
    total=$(echo "$line" | sed -E 's/.*out of ([0-9]+).*/\1/')
    f=$(echo "$line" | sed -E 's/.*passed, ([0-9]+) tests failed.*/\1/')
    passed=$((passed + total - f)); failed=$((failed + f))
  else
    failed=$((failed + 1))
  fi
}
bash scripts/deps.sh || exit 1
bash scripts/configure.sh || exit 1
cmake --build build -j"$(nproc)" || exit 1
log=$(mktemp)
soak_log=$(mktemp)
soak_pid=""
for stage in $stages; do
  echo "=== test.sh: $stage"
  case $stage in
    unit) (cd build && ctest --output-on-failure -j"$(nproc)" -LE soak) 2>&1 | tee "$log"; count "$log" ;;
    soak) (cd build && ctest -V -L soak) >"$soak_log" 2>&1 &
          soak_pid=$!
          echo "test.sh: soak running in the background (pid $soak_pid)" ;;
    sanitize) bash scripts/sanitize.sh 2>&1 | tee "$log"; count "$log" ;;
    fuzz) if bash scripts/fuzz.sh; then passed=$((passed + 1)); else failed=$((failed + 1)); fi ;;
    *) echo "test.sh: unknown stage '$stage'"; failed=$((failed + 1)) ;;
  esac
done
if [ -n "$soak_pid" ]; then
  wait "$soak_pid"
  echo "=== test.sh: soak (log)"
  grep -E "soak:|tests passed|Passed|Failed" "$soak_log" || tail -40 "$soak_log"
  count "$soak_log"
fi
rm -f "$log" "$soak_log"
echo "test.sh: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
