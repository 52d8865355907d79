#!/usr/bin/env bash
# Mutation testing: applies each mutation of scripts/mutations.txt to the source, rebuilds,
# runs the suite and restores the file. A mutant the suite fails on is KILLED; one it passes
# SURVIVED (a gap in the tests, unless the entry says why it is equivalent). A pattern that no
# longer occurs exactly once is STALE or AMBIGUOUS, never skipped silently. Slow: not in CI.
#
#   scripts/mutate.sh [ID...]        # all mutations, or only the ones named
#   scripts/mutate.sh --check [ID...]  # only checks that every pattern occurs exactly once
#   MUTATE_BUILD=dir MUTATE_JOBS=n MUTATE_TIMEOUT=s scripts/mutate.sh
set -u -o pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
list=${MUTATIONS:-scripts/mutations.txt}
build=${MUTATE_BUILD:-build-mutate}
jobs=${MUTATE_JOBS:-2}
limit=${MUTATE_TIMEOUT:-180} # seconds for one suite run; a hang counts as killed
log=$build/mutate-logs

# ---- read the list: records of `key: value` lines separated by blank lines
ids=() files=() finds=() replaces=() whys=() equivs=()
add_record() {
  [[ -z ${r_id:-} ]] && return
  if [[ -z ${r_file:-} || -z ${r_find:-} || -z ${r_why:-} || ! -v r_replace ]]; then
    echo "mutations: record $r_id lacks file, find, replace or why" >&2
    exit 2
  fi
  ids+=("$r_id") files+=("$r_file") finds+=("$r_find") replaces+=("$r_replace")
  whys+=("$r_why") equivs+=("${r_equivalent:-}")
}
clear_record() { unset r_id r_file r_find r_replace r_why r_equivalent; }
clear_record
while IFS= read -r line || [[ -n $line ]]; do
  [[ $line == \#* ]] && continue
  if [[ -z ${line//[[:space:]]/} ]]; then
    add_record
    clear_record
    continue
  fi
  key=${line%%:*}
  value=${line#*: }
  [[ $line == *:* ]] || { echo "mutations: cannot read line: $line" >&2; exit 2; }
  [[ $value == "$line" ]] && value=${line#*:} # `replace:` with an empty value
  case $key in
  id | file | find | replace | why | equivalent) printf -v "r_$key" '%s' "$value" ;;
  *) echo "mutations: unknown key '$key' in: $line" >&2; exit 2 ;;
  esac
done <"$list"
add_record

declare -A seen
for id in "${ids[@]}"; do
  [[ -n ${seen[$id]:-} ]] && { echo "mutations: duplicate id $id" >&2; exit 2; }
  seen[$id]=1
done
check_only=0
if [[ ${1:-} == --check ]]; then
  check_only=1
  shift
fi
selected=("$@")
for id in "${selected[@]}"; do
  [[ -n ${seen[$id]:-} ]] || { echo "mutations: no mutation $id in $list" >&2; exit 2; }
done
wanted() {
  ((${#selected[@]} == 0)) && return 0
  local s
  for s in "${selected[@]}"; do [[ $s == "$1" ]] && return 0; done
  return 1
}

# ---- the working tree must come back exactly as it was
state_before=$(git status --porcelain=v1 && git diff | sha1sum)
backup=""
target=""
restore() {
  if [[ -n $backup && -f $backup ]]; then
    cp "$backup" "$target" # a new mtime: the next build recompiles it
    rm -f "$backup"
    backup=""
  fi
}
trap 'restore' EXIT
trap 'restore; echo "interrupted" >&2; exit 130' INT TERM

# In `find` and `replace`, \n stands for a line break and \\ for a backslash.
unescape='sub unesc { my $s = shift; $s =~ s/\\(n|\\)/$1 eq "n" ? "\n" : "\\"/ge; $s }'
occurrences() { # occurrences of the exact text $2 in file $1
  PAT=$2 perl -0777 -ne "$unescape"' my $p = unesc($ENV{PAT}); $n = () = /\Q$p\E/g; print $n' "$1"
}
apply() { # replaces the one occurrence of $2 in file $1 by $3
  PAT=$2 REP=$3 perl -0777 -pi -e "$unescape"' my $p = unesc($ENV{PAT}); my $r = unesc($ENV{REP});
    s/\Q$p\E/$r/' "$1"
}

if ((check_only)); then
  status=0
  for i in "${!ids[@]}"; do
    wanted "${ids[$i]}" || continue
    count=0
    [[ -f ${files[$i]} ]] && count=$(occurrences "${files[$i]}" "${finds[$i]}")
    result=OK
    [[ $count == 0 ]] && result=STALE
    [[ $count -gt 1 ]] && result=AMBIGUOUS
    [[ $result != OK ]] && status=1
    printf '%-6s %-10s %s\n' "${ids[$i]}" "$result" "${files[$i]}"
  done
  exit $status
fi

if [[ ! -f $build/CMakeCache.txt ]]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
    >/dev/null || exit 2
fi
mkdir -p "$log"
echo "building the unmutated tree in $build"
if ! cmake --build "$build" -j "$jobs" --target gcx gcx_tests >"$log/baseline.txt" 2>&1; then
  echo "the unmutated tree does not build: $log/baseline.txt" >&2
  exit 2
fi

run_suite() { # 0 when every test passes
  timeout "$limit" "$build/tests/gcx_tests" --gtest_fail_fast --gtest_brief=1 &&
    (cd "$build" && timeout "$limit" ctest -R '^cli\.' --stop-on-failure --output-on-failure)
}

killer() { # the first test that failed, from a mutation's log
  local t
  t=$(grep -m1 -oE '^\[  FAILED  \] [A-Za-z0-9_./]+' "$1" | cut -c14-)
  [[ -z $t ]] && t=$(grep -m1 -oE 'cli\.[A-Za-z0-9_]+ \.+\**(Failed|Timeout)' "$1" | cut -d' ' -f1)
  [[ -z $t ]] && grep -q '^suite timed out' "$1" && t="a timeout (${limit}s)"
  echo "${t:-a crash}"
}

start=$(date +%s)
killed=0 survived=0 equivalent=0 stale=0 broken=0 total=0
for i in "${!ids[@]}"; do
  id=${ids[$i]}
  wanted "$id" || continue
  total=$((total + 1))
  file=${files[$i]}
  t0=$(date +%s)
  count=0
  [[ -f $file ]] && count=$(occurrences "$file" "${finds[$i]}")
  if [[ $count != 1 ]]; then
    result=$([[ $count == 0 ]] && echo STALE || echo AMBIGUOUS)
    stale=$((stale + 1))
  else
    target=$file
    backup=$(mktemp)
    cp -p "$file" "$backup"
    apply "$file" "${finds[$i]}" "${replaces[$i]}"
    if cmake --build "$build" -j "$jobs" --target gcx gcx_tests >"$log/$id.txt" 2>&1; then
      run_suite >>"$log/$id.txt" 2>&1
      rc=$?
      ((rc == 124)) && echo "suite timed out" >>"$log/$id.txt"
      if ((rc != 0)); then
        result=KILLED
        killed=$((killed + 1))
      elif [[ -n ${equivs[$i]} ]]; then
        result=EQUIVALENT
        equivalent=$((equivalent + 1))
      else
        result=SURVIVED
        survived=$((survived + 1))
      fi
    else
      result=BUILD-FAILED
      broken=$((broken + 1))
    fi
    restore
  fi
  note=${whys[$i]}
  [[ $result == KILLED ]] && note="by $(killer "$log/$id.txt")"
  [[ $result == EQUIVALENT ]] && note="equivalent: ${equivs[$i]}"
  [[ $result == KILLED && -n ${equivs[$i]} ]] && note="KILLED but listed as equivalent: fix the list"
  printf '%-6s %-12s %4ss  %s  %s\n' "$id" "$result" $(($(date +%s) - t0)) "$file" "$note"
done

elapsed=$(($(date +%s) - start))
scored=$((killed + survived))
score=0
((scored > 0)) && score=$((100 * killed / scored))
echo "mutations: $total run, $killed killed, $survived survived, $equivalent equivalent," \
  "$stale stale or ambiguous, $broken failed to build"
echo "score: $killed/$scored killed ($score%), time ${elapsed}s (logs in $log)"

state_after=$(git status --porcelain=v1 && git diff | sha1sum)
if [[ $state_before != "$state_after" ]]; then
  echo "the working tree changed during the run: check git status" >&2
  exit 2
fi
((survived + stale + broken == 0))
