#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test:
#   1. the unit, GL and tool tests (ctest, RelWithDebInfo build in build/)
#   2. the soak (ctest label "soak": 20,000 frames with reaction files rewritten under --watch)
#   3. the same suite under AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/)
#   4. libFuzzer on the reaction and scene loaders, about a minute each, plus the kept crashers
# CUBE_TEST_STAGES (default "unit soak sanitize fuzz") picks stages, e.g. CUBE_TEST_STAGES=unit.
set -uo pipefail
cd "$(dirname "$0")"
stages="${CUBE_TEST_STAGES:-unit soak sanitize fuzz}"
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
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null || exit 1
cmake --build build -j"$(nproc)" || exit 1
log=$(mktemp)
for stage in $stages; do
  echo "=== test.sh: $stage"
  case $stage in
    unit) (cd build && ctest --output-on-failure -j"$(nproc)" -LE soak) 2>&1 | tee "$log"; count "$log" ;;
    soak) (cd build && ctest -V -L soak) 2>&1 | tee "$log"; count "$log" ;;
    sanitize) bash scripts/sanitize.sh 2>&1 | tee "$log"; count "$log" ;;
    fuzz) if bash scripts/fuzz.sh; then passed=$((passed + 1)); else failed=$((failed + 1)); fi ;;
    *) echo "test.sh: unknown stage '$stage'"; failed=$((failed + 1)) ;;
  esac
done
rm -f "$log"
echo "test.sh: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
