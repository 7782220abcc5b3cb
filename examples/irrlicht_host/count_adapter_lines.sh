#!/usr/bin/env bash
# Counts an example's host-side adapter lines: the non-blank, non-comment lines between a
# "// fx-adapter begin: <part>" line and the next "// fx-adapter end" line, per part and in all.
# The parts are named after what they hold: callbacks, setup, per-frame, teardown.
#   count_adapter_lines.sh main.cpp
set -euo pipefail
awk '/^[[:space:]]*\/\/ fx-adapter begin: / { part = $4; inside = 1; next }
     /^[[:space:]]*\/\/ fx-adapter end/      { inside = 0; next }
     inside && $0 !~ /^[[:space:]]*$/ && $0 !~ /^[[:space:]]*\/\// { n[part]++; total++ }
     END { for (p in n) printf "%s %d\n", p, n[p]; printf "total %d\n", total }' "$1" | sort
