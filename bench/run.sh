#!/usr/bin/env bash
# make bench: throughput (lines/s) and peak memory of gcx on generated programs, and the same
# program through LinuxCNC's rs274 when it is installed (the ratio is gcx / rs274 speed).
# The macro section runs a WHILE loop of LINES iterations (one G1 block each) through gcx's
# macro expansion pass, and the equivalent o-word loop through rs274; there lines/s counts the
# blocks emitted, not the source lines.
# The drilling section expands a G83 peck cycle at HOLES (default 100000) positions to canonical
# G0/G1 (lines/s counts source blocks, and separately canonical lines emitted), and runs the
# equivalent RS274 program (without NCT's E word) through rs274.
#   usage: bench/run.sh BUILD_DIR [LINES]   (environment: HOLES=100000, RSS_LINES=10000000)
set -euo pipefail
build=${1:-build}
lines=${2:-1000000}
gcx=$build/gcx
gen=$build/bench/gcx-bench-gen
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

rs274_measure() {  # rs274_measure LABEL N PROGRAM CANON: rs274 with a private HOME and var file
  mkdir -p "$work/home"
  : > "$work/$(basename "$3").var"  # rs274 writes both
  measure "$1" "$2" env HOME="$work/home" \
    rs274 -g -v "$work/$(basename "$3").var" "$3" "$4" < /dev/null
}

measure() {  # measure LABEL LINES COMMAND... -> prints lines/s and peak RSS
  local label=$1 n=$2
  shift 2
  /usr/bin/time -f "%e %M" -o "$work/time" "$@" > /dev/null 2> "$work/err" || {
    echo "$label: FAILED"; cat "$work/err"; return 1; }
  read -r secs kb < "$work/time"
  awk -v l="$label" -v n="$n" -v s="$secs" -v k="$kb" \
    'BEGIN { printf "%-50s %9.2f s %12.0f lines/s %8.1f MB peak RSS\n", l, s, (s > 0 ? n / s : 0), k / 1024 }'
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
measure "gcx expand --to canonical ($lines lines, --jobs 1)" "$lines" \
  "$gcx" expand "$work/lines.nct" --to canonical --jobs 1 -o "$work/out1.ngc"
cmp -s "$work/out.ngc" "$work/out1.ngc" || { echo "--jobs 1 and --jobs 2 wrote different files"; exit 1; }
measure "gcx run --stats ($lines lines)" "$lines" "$gcx" run "$work/lines.nct" --stats

echo "== memory: peak RSS must not grow with the program (RSS_LINES=${RSS_LINES:=10000000})"
for n in 100000 "$RSS_LINES"; do
  "$gen" lines "$n" > "$work/rss.nct"
  measure "gcx expand --to canonical ($n lines)" "$n" \
    "$gcx" expand "$work/rss.nct" --to canonical -o "$work/rss.ngc"
  rm -f "$work/rss.nct" "$work/rss.ngc"
done

echo "== the grammar path: $lines blocks of macro expressions (none fit for the fast path)"
"$gen" exprs "$lines" > "$work/exprs.nct"
measure "gcx check (expressions, $lines lines)" "$lines" "$gcx" check "$work/exprs.nct"
rm -f "$work/exprs.nct"

echo "== equivalence: the program against its canonical output, each run in its own thread"
# the canonical output under an .nct name: gcx reads it itself, streaming (as .ngc it would go
# through rs274, which writes its whole output to a file first)
cp "$work/out.ngc" "$work/out_canonical.nct"
measure "gcx equiv (program vs canonical, $lines lines)" "$lines" \
  "$gcx" equiv "$work/lines.nct" "$work/out_canonical.nct"
equiv_secs=$(cat "$work/last")
awk -v e="$equiv_secs" -v g="$gcx_secs" 'BEGIN { printf "ratio: gcx equiv takes %.2fx the time of gcx expand of one program\n", (g > 0 ? e / g : 0) }'

if command -v rs274 > /dev/null; then
  echo "== LinuxCNC rs274 on the same program (output-file argument, its fastest mode)"
  rs274_measure "rs274 ($lines lines)" "$lines" "$work/lines.ngc" "$work/out.canon"
  rs_secs=$(cat "$work/last")
  awk -v g="$gcx_secs" -v r="$rs_secs" 'BEGIN { printf "ratio: gcx expand is %.1fx the speed of rs274\n", (g > 0 ? r / g : 0) }'
else
  echo "rs274 not installed: no ratio"
fi

echo "== macro expansion: a WHILE loop emitting $lines G1 blocks (lines/s = blocks emitted/s)"
"$gen" macro "$lines" > "$work/macro.nct"
# the loop makes one backward jump and runs three blocks per iteration: at the default
# 1,000,000 lines it runs within the default runaway limits (docs/limits.md); longer runs raise them
limits=()
if [ "$lines" -gt 1000000 ]; then
  limits=(--max-jumps $((lines + 1000)) --max-blocks $((lines * 4 + 1000)) --max-moves $((lines * 2)))
fi
measure "gcx expand --to canonical (macro, $lines blocks)" "$lines" \
  "$gcx" expand "$work/macro.nct" --to canonical "${limits[@]}" -o "$work/macro.ngc"
macro_secs=$(cat "$work/last")
feeds=$(grep -c '^G1 ' "$work/macro.ngc" || true)
if [ "$feeds" -ne $((lines + 1)) ]; then  # the loop's blocks plus the plunge
  echo "gcx expand wrote $feeds G1 blocks, expected $((lines + 1))"; exit 1
fi
measure "gcx run --stats (macro, $lines blocks)" "$lines" \
  "$gcx" run "$work/macro.nct" --stats "${limits[@]}"

if command -v rs274 > /dev/null; then
  echo "== LinuxCNC rs274 on the same loop written with o-words"
  "$gen" oword "$lines" > "$work/oword.ngc"
  rs274_measure "rs274 (o-word loop, $lines blocks)" "$lines" "$work/oword.ngc" "$work/oword.canon"
  rs_macro_secs=$(cat "$work/last")
  feeds=$(grep -c 'STRAIGHT_FEED' "$work/oword.canon" || true)
  if [ "$feeds" -ne $((lines + 1)) ]; then
    echo "rs274 wrote $feeds feed moves, expected $((lines + 1))"; exit 1
  fi
  awk -v g="$macro_secs" -v r="$rs_macro_secs" 'BEGIN { printf "ratio: gcx expand (macro loop) is %.1fx the speed of rs274 (o-word loop)\n", (g > 0 ? r / g : 0) }'
else
  echo "rs274 not installed: no macro ratio"
fi

echo "== drilling cycles: G83 at ${HOLES:=100000} holes (Q5, 5 pecks each, E0.254 = rs274's 0.254 mm)"
"$gen" g83 "$HOLES" > "$work/g83.nct"
"$gen" g83ngc "$HOLES" > "$work/g83.ngc"
blocks=$(wc -l < "$work/g83.nct")
measure "gcx expand --to canonical (G83 $HOLES holes)" "$blocks" \
  "$gcx" expand "$work/g83.nct" --to canonical -o "$work/g83.out.ngc"
g83_secs=$(cat "$work/last")
emitted=$(wc -l < "$work/g83.out.ngc")
gfeeds=$(grep -c '^G1 ' "$work/g83.out.ngc" || true)
awk -v n="$emitted" -v s="$g83_secs" \
  'BEGIN { printf "%-50s %9s   %12.0f lines/s (%d canonical lines)\n", "  emitted canonical lines", "", (s > 0 ? n / s : 0), n }'
if [ "$gfeeds" -ne $((HOLES * 5)) ]; then
  echo "gcx expand wrote $gfeeds G1 blocks, expected $((HOLES * 5))"; exit 1
fi
if command -v rs274 > /dev/null; then
  rs274_measure "rs274 (G83 $HOLES holes)" "$blocks" "$work/g83.ngc" "$work/g83.canon"
  rs_g83_secs=$(cat "$work/last")
  rfeeds=$(grep -c 'STRAIGHT_FEED' "$work/g83.canon" || true)
  if [ "$rfeeds" -ne "$gfeeds" ]; then
    echo "rs274 wrote $rfeeds feed moves, gcx $gfeeds"; exit 1
  fi
  awk -v g="$g83_secs" -v r="$rs_g83_secs" 'BEGIN { printf "ratio: gcx expand (G83) is %.1fx the speed of rs274\n", (g > 0 ? r / g : 0) }'
else
  echo "rs274 not installed: no G83 ratio"
fi
