#!/usr/bin/env bash
# Runs the libFuzzer targets of a GCX_FUZZ build (docs/testing.md, "Fuzzing and sanitizers").
# usage: fuzz.sh run   BUILD WORK SECONDS JOBS [TARGET...]  each target for SECONDS, JOBS at a time
#        fuzz.sh merge BUILD WORK [TARGET...]               minimise the found corpus into tests/fuzz/corpus
#        fuzz.sh list  BUILD                                the targets and the files that seed them
# The targets are those the fuzz executable names (GCX_FUZZ_TARGET=list): three per dialect of
# the registry, translate_nct and setup_json; no TARGET: all of them.
# WORK keeps, per target: seeds/ (from the test corpus and examples), corpus/ (what the fuzzer
# found), artifacts/ (crash-*, timeout-*, oom-*) and the log.
set -euo pipefail
cd "$(dirname "$0")/.."
COMMITTED=tests/fuzz/corpus

fuzzer() { echo "$1/fuzz/gcx_fuzz"; }

# "name extension" per target
list() { GCX_FUZZ_TARGET=list "$(fuzzer "$1")"; }

# the targets named on the command line, else every one but those of FUZZ_SKIP (names apart)
targets() {
  local build=$1 t; shift
  if [ $# -gt 0 ]; then printf '%s\n' "$@"; return; fi
  for t in $(list "$build" | cut -d' ' -f1); do
    case " ${FUZZ_SKIP:-} " in *" $t "*) echo "skipped: $t (FUZZ_SKIP)" >&2 ;; *) echo "$t" ;; esac
  done
}

# The seeds are the project's own programs and setups, copied (not committed twice).
seeds() {
  local build=$1 work=$2 t ext; shift 2
  while read -r t ext; do
    rm -rf "$work/$t/seeds"
    mkdir -p "$work/$t/seeds" "$work/$t/corpus" "$work/$t/artifacts"
    find tests examples -type f -name "*$ext" -size -64k |
      while read -r f; do cp "$f" "$work/$t/seeds/$(echo "$f" | tr / _)"; done
  done < <(list "$build" | grep -E "^($(targets "$build" "$@" | paste -sd'|')) ")
}

options() { # the options every libFuzzer run of target $1 shares
  local opts=(-timeout=10 -rss_limit_mb=2048 -print_final_stats=1) dialect=${1#*_}
  [ -f "fuzz/$dialect.dict" ] && opts+=("-dict=fuzz/$dialect.dict")
  echo "${opts[@]}"
}

run_one() {
  local build=$1 work=$2 seconds=$3 t=$4 dirs=()
  dirs=("$work/$t/corpus" "$work/$t/seeds")
  [ -d "$COMMITTED/$t" ] && dirs+=("$COMMITTED/$t")
  # a crash stops the run; its input is in artifacts/
  GCX_FUZZ_TARGET=$t "$(fuzzer "$build")" $(options "$t") -max_total_time="$seconds" \
    -artifact_prefix="$work/$t/artifacts/" "${dirs[@]}" >"$work/$t/log" 2>&1 || true
}

summary() { # one line per target from its log: execs, coverage, corpus, findings
  local work=$1 t log last execs findings status=0; shift
  printf '%-16s %12s %8s %8s %14s %s\n' target execs cov ft corpus findings
  for t in "$@"; do
    log=$work/$t/log
    last=$(grep -aE '^#[0-9]+' "$log" | tail -1 || true)
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    findings=$(ls "$work/$t/artifacts" | wc -l)
    printf '%-16s %12s %8s %8s %14s %s\n' "$t" "${execs:-?}" \
      "$(echo "$last" | sed -n 's/.* cov: \([0-9]*\).*/\1/p')" \
      "$(echo "$last" | sed -n 's/.* ft: \([0-9]*\).*/\1/p')" \
      "$(echo "$last" | sed -n 's/.* corp: \([^ ]*\).*/\1/p')" \
      "$findings$( [ "$findings" = 0 ] || echo " in $work/$t/artifacts")"
    [ "$findings" = 0 ] || status=1
    grep -aq 'ERROR: libFuzzer\|SUMMARY: .*Sanitizer\|property violated' "$log" && status=1
  done
  return $status
}

cmd=${1:-}
case $cmd in
list) list "$2" ;;
run)
  build=$2 work=$3 seconds=$4 jobs=$5
  shift 5
  mapfile -t names < <(targets "$build" "$@")
  seeds "$build" "$work" "${names[@]}"
  export -f run_one options fuzzer
  export COMMITTED
  printf '%s\n' "${names[@]}" | xargs -P "$jobs" -I{} bash -c "run_one '$build' '$work' '$seconds' {}"
  summary "$work" "${names[@]}"
  ;;
merge)
  build=$2 work=$3
  shift 3
  mapfile -t names < <(targets "$build" "$@")
  seeds "$build" "$work" "${names[@]}"
  for t in "${names[@]}"; do
    # -merge=1 adds to the seeds the fewest inputs that reach code (edges; -use_counters=0
    # ignores hit counts) the seeds do not; those, up to 2 KB each, are the committed corpus
    mkdir -p "$COMMITTED/$t"
    rm -rf "$work/$t/merged"
    cp -r "$work/$t/seeds" "$work/$t/merged"
    GCX_FUZZ_TARGET=$t "$(fuzzer "$build")" $(options "$t") -merge=1 -use_counters=0 -max_len=2048 \
      "$work/$t/merged" "$COMMITTED/$t" "$work/$t/corpus" >"$work/$t/merge.log" 2>&1
    # the seeds are named by their path (with a dot); found inputs by their hash
    find "$work/$t/merged" -type f -name '*.*' -delete
    # a named file is a regression input kept by hand
    find "$COMMITTED/$t" -type f -regextype posix-extended -regex '.*/[0-9a-f]{40}' -delete
    find "$work/$t/merged" -type f -exec cp {} "$COMMITTED/$t"/ \;
    echo "$t: $(ls "$COMMITTED/$t" | wc -l) files, $(cat "$COMMITTED/$t"/* 2>/dev/null | wc -c) bytes"
  done
  ;;
*)
  sed -n '2,9p' "$0" >&2
  exit 2
  ;;
esac
