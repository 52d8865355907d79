#!/usr/bin/env bash
# Golden outputs of every example and test program: what the engine means today, byte for byte.
#
#   scripts/golden.sh capture OUTDIR [GCX]   run every .nct, .fms and .wl4 under examples/ and
#                                            tests/ through expand --to canonical --provenance,
#                                            run --trace, fmt and check --json; store outputs
#                                            and exit codes
#   scripts/golden.sh compare DIR_A DIR_B    list every program whose outputs differ
#
# A program's setup is the X.setup.json beside X.nct (X.fms, X.wl4), when there is one; the
# extension picks the dialect. Programs run with their own folder as the working directory, so
# the subprograms beside them are found as in the tests (NCT O0012.nct, FMS-3000 program units
# 19.fms, WL4 %-programs). An FMS-3000 program unit is also run on its own: it ends at its M99.
# Execution runs with small fixed limits, so runaway programs of the error corpus stop early and
# always at the same block, whatever the command's defaults are.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)

capture() {
  local out=$1 gcx=${2:-$top/build/gcx}
  gcx=$(cd "$(dirname "$gcx")" && pwd)/$(basename "$gcx")
  mkdir -p "$out"
  out=$(cd "$out" && pwd)
  local count=0
  while IFS= read -r rel; do
    local dir name setup=() dest
    dir=$(dirname "$rel")
    name=$(basename "$rel")
    local stem=${rel%.*}
    [ -f "$top/$stem.setup.json" ] && setup=(--setup "$(basename "$stem").setup.json")
    dest="$out/$rel"
    mkdir -p "$(dirname "$dest")"
    (
      cd "$top/$dir"
      run() { # run TAG CMD...: stdout, stderr and the exit code of one command
        local tag=$1
        shift
        local rc=0
        timeout 60 "$@" >"$dest.$tag.out" 2>"$dest.$tag.err" || rc=$?
        echo "$rc" >"$dest.$tag.rc"
      }
      local limits=(--max-jumps 20000 --max-blocks 500000)
      run expand "$gcx" expand "$name" --to canonical --provenance "${setup[@]}" "${limits[@]}"
      run trace "$gcx" run "$name" "${setup[@]}" "${limits[@]}" --stats --trace "$dest.trace.jsonl"
      run fmt "$gcx" fmt "$name"
      run check "$gcx" check --json "$name"
    )
    count=$((count + 1))
  done < <(cd "$top" && find examples tests \( -name '*.nct' -o -name '*.fms' -o -name '*.wl4' \) |
    LC_ALL=C sort)
  echo "captured $count programs into $out"
}

compare() {
  local a=$1 b=$2
  if diff -rq "$a" "$b" >/dev/null; then
    echo "identical: $(find "$a" -name '*.rc' | wc -l) outputs"
    return 0
  fi
  diff -rq "$a" "$b" | sed -e "s|$a/||g" -e "s|$b/||g"
  return 1
}

case "${1:-}" in
capture) capture "${2:?OUTDIR}" ${3:+"$3"} ;;
compare) compare "${2:?DIR_A}" "${3:?DIR_B}" ;;
*)
  sed -n '2,13p' "$0"
  exit 2
  ;;
esac
