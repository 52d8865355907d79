#!/usr/bin/env bash
# make bench: throughput (lines/s) and peak memory of gcx on generated programs, and the same
# program through LinuxCNC's rs274 when it is installed (the ratio is gcx / rs274 speed).
#   usage: bench/run.sh BUILD_DIR [LINES]
set -euo pipefail
build=${1:-build}
lines=${2:-1000000}
gcx=$build/gcx
gen=$build/bench/gcx-bench-gen
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

measure() {  # measure LABEL LINES COMMAND... -> prints lines/s and peak RSS
  local label=$1 n=$2
  shift 2
  /usr/bin/time -f "%e %M" -o "$work/time" "$@" > /dev/null 2> "$work/err" || {
    echo "$label: FAILED"; cat "$work/err"; return 1; }
  read -r secs kb < "$work/time"
  awk -v l="$label" -v n="$n" -v s="$secs" -v k="$kb" \
    'BEGIN { printf "%-44s %9.2f s %12.0f lines/s %8.1f MB peak RSS\n", l, s, (s > 0 ? n / s : 0), k / 1024 }'
  echo "$secs" > "$work/last"
}

echo "== generating $lines-line programs"
"$gen" lines "$lines" > "$work/lines.nct"
cp "$work/lines.nct" "$work/lines.ngc"
holes=$((lines / 10))
"$gen" holes "$holes" > "$work/holes.nct"

echo "== parse and static checks"
measure "gcx check ($lines lines G1/G2)" "$lines" "$gcx" check "$work/lines.nct"
echo "== canonical expansion (parse, interpret, emit)"
measure "gcx expand --to canonical ($lines lines)" "$lines" \
  "$gcx" expand "$work/lines.nct" --to canonical -o "$work/out.ngc"
gcx_secs=$(cat "$work/last")
measure "gcx run --stats ($lines lines)" "$lines" "$gcx" run "$work/lines.nct" --stats

if command -v rs274 > /dev/null; then
  echo "== LinuxCNC rs274 on the same program (output-file argument, its fastest mode)"
  mkdir -p "$work/home"
  : > "$work/p.var"  # a private HOME and parameter file: rs274 writes both
  measure "rs274 ($lines lines)" "$lines" env HOME="$work/home" \
    rs274 -g -v "$work/p.var" "$work/lines.ngc" "$work/out.canon" < /dev/null
  rs_secs=$(cat "$work/last")
  awk -v g="$gcx_secs" -v r="$rs_secs" 'BEGIN { printf "ratio: gcx expand is %.1fx the speed of rs274\n", (g > 0 ? r / g : 0) }'
else
  echo "rs274 not installed: no ratio"
fi
