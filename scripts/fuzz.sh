#!/usr/bin/env bash
# Runs the libFuzzer targets of a GCX_FUZZ build (docs/testing.md, "Fuzzing and sanitizers").
# usage: fuzz.sh run   BUILD WORK SECONDS JOBS   every target for SECONDS, JOBS targets at a time
#        fuzz.sh merge BUILD WORK                 minimise the found corpus into tests/fuzz/corpus
#        fuzz.sh seeds WORK                       (re)build the seed folders only
# WORK keeps, per target: seeds/ (from the test corpus and examples), corpus/ (what the fuzzer
# found), crashes (artifacts: crash-*, timeout-*, oom-*) and the log.
set -euo pipefail
cd "$(dirname "$0")/.."
TARGETS=(check_nct expand_nct fmt_nct setup_json)
COMMITTED=tests/fuzz/corpus

# The seeds are the project's own programs and setups, copied (not committed twice).
seeds() {
  local work=$1 t
  for t in "${TARGETS[@]}"; do
    rm -rf "$work/$t/seeds"
    mkdir -p "$work/$t/seeds" "$work/$t/corpus" "$work/$t/artifacts"
    case $t in
    *_nct) find tests examples -type f -name '*.nct' -size -64k ;;
    *_json) find tests examples -type f -name '*.json' -size -64k ;;
    esac | while read -r f; do cp "$f" "$work/$t/seeds/$(echo "$f" | tr / _)"; done
  done
}

options() { # the options every libFuzzer run of target $1 shares
  local opts=(-timeout=10 -rss_limit_mb=2048 -print_final_stats=1)
  case $1 in *_nct) opts+=(-dict=fuzz/nct.dict) ;; esac
  echo "${opts[@]}"
}

run_one() {
  local build=$1 work=$2 seconds=$3 t=$4 dirs=()
  dirs=("$work/$t/corpus" "$work/$t/seeds")
  [ -d "$COMMITTED/$t" ] && dirs+=("$COMMITTED/$t")
  # a crash stops the run; its input is in artifacts/
  "$build/fuzz/fuzz_$t" $(options "$t") -max_total_time="$seconds" \
    -artifact_prefix="$work/$t/artifacts/" "${dirs[@]}" >"$work/$t/log" 2>&1 || true
}

summary() { # one line per target from its log: execs, coverage, corpus, findings
  local work=$1 t log last execs findings status=0
  printf '%-12s %12s %8s %8s %14s %s\n' target execs cov ft corpus findings
  for t in "${TARGETS[@]}"; do
    log=$work/$t/log
    last=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    findings=$(ls "$work/$t/artifacts" | wc -l)
    printf '%-12s %12s %8s %8s %14s %s\n' "$t" "${execs:-?}" \
      "$(echo "$last" | sed -n 's/.* cov: \([0-9]*\).*/\1/p')" \
      "$(echo "$last" | sed -n 's/.* ft: \([0-9]*\).*/\1/p')" \
      "$(echo "$last" | sed -n 's/.* corp: \([^ ]*\).*/\1/p')" \
      "$findings$( [ "$findings" = 0 ] || echo " in $work/$t/artifacts")"
    [ "$findings" = 0 ] || status=1
    grep -q 'ERROR: libFuzzer\|SUMMARY: .*Sanitizer\|property violated' "$log" && status=1
  done
  return $status
}

cmd=${1:-}
case $cmd in
seeds) seeds "$2" ;;
run)
  build=$2 work=$3 seconds=$4 jobs=$5
  seeds "$work"
  export -f run_one options
  export COMMITTED
  printf '%s\n' "${TARGETS[@]}" | xargs -P "$jobs" -I{} bash -c "run_one '$build' '$work' '$seconds' {}"
  summary "$work"
  ;;
merge)
  build=$2 work=$3
  seeds "$work"
  for t in "${TARGETS[@]}"; do
    # -merge=1 adds to the seeds the fewest inputs that reach code (edges; -use_counters=0
    # ignores hit counts) the seeds do not; those, up to 2 KB each, are the committed corpus
    mkdir -p "$COMMITTED/$t"
    rm -rf "$work/$t/merged"
    cp -r "$work/$t/seeds" "$work/$t/merged"
    "$build/fuzz/fuzz_$t" $(options "$t") -merge=1 -use_counters=0 -max_len=2048 \
      "$work/$t/merged" "$COMMITTED/$t" "$work/$t/corpus" >"$work/$t/merge.log" 2>&1
    rm -f "$work/$t/merged"/*.nct "$work/$t/merged"/*.json # the seeds (found inputs: hashes)
    # found inputs are named by their hash; a named file is a regression input kept by hand
    find "$COMMITTED/$t" -type f -regextype posix-extended -regex '.*/[0-9a-f]{40}' -delete
    find "$work/$t/merged" -type f -exec cp {} "$COMMITTED/$t"/ \;
    echo "$t: $(ls "$COMMITTED/$t" | wc -l) files, $(cat "$COMMITTED/$t"/* 2>/dev/null | wc -c) bytes"
  done
  ;;
*)
  sed -n '2,7p' "$0" >&2
  exit 2
  ;;
esac
