#!/usr/bin/env bash
# Architecture checks, run by ctest (tests/CMakeLists.txt):
#
#   scripts/check_architecture.sh layering ROOT [ALLOWED_LIST]
#       every #include "..." under ROOT/src, ROOT/passes and ROOT/dialects, as an edge between
#       top-level folders (src/machine, src/cycles, passes/macro, dialects/nct, ...); fails on
#       any cycle among them and on src/machine including anything under passes/. ALLOWED_LIST
#       names edges "FROM TO" left out of the cycle check (known debts, each with its reason).
#   scripts/check_architecture.sh forbidden ROOT FORBIDDEN_LIST EXEMPT_LIST
#       fails when a file under ROOT/src or ROOT/passes (except the exempt paths) matches one of
#       the extended regexes of FORBIDDEN_LIST: dialect numbers the core must not spell.
#
# The lists hold one entry a line; lines starting with `#` are comments, blank lines are ignored.
set -euo pipefail

usage() {
  echo "usage: $0 layering ROOT [ALLOWED_LIST] | forbidden ROOT FORBIDDEN_LIST EXEMPT_LIST" >&2
  exit 2
}

# The top-level folder of a path relative to ROOT: src/machine/x.h -> src/machine,
# dialects/registry.cpp -> dialects.
folder() {
  local p=$1
  case "$p" in
  */*/*) echo "${p%%/*}/$(echo "${p#*/}" | cut -d/ -f1)" ;;
  *) echo "${p%%/*}" ;;
  esac
}

# Entries of a list file without comment lines and blank lines.
entries() {
  sed -e '/^[[:space:]]*#/d' -e '/^[[:space:]]*$/d' -e 's/[[:space:]]*$//' "$1"
}

layering() {
  local root=$1 allowed=${2:-} edges status=0
  edges=$(mktemp)
  trap 'rm -f "$edges"' RETURN
  # One awk pass over every source file (a fork per include took minutes on a loaded machine).
  # The first input lists the files that exist; an include names a file under src/ (the include
  # root) or under ROOT itself, anything else is a system header or a generated file.
  local files
  files=$(cd "$root" && find src passes dialects -type f \( -name '*.h' -o -name '*.cpp' \) 2>/dev/null | sort || true)
  [ -n "$files" ] || return 0
  (cd "$root" && awk '
    function folder(p, parts, n) {
      n = split(p, parts, "/")
      return n >= 3 ? parts[1] "/" parts[2] : parts[1]
    }
    NR == FNR { exists[$0] = 1; next }
    FNR == 1 { from = folder(FILENAME) }
    /^[ \t]*#[ \t]*include[ \t]*"/ {
      inc = $0
      sub(/^[^"]*"/, "", inc); sub(/".*$/, "", inc)
      if (("src/" inc) in exists) target = "src/" inc
      else if (inc in exists) target = inc
      else next
      to = folder(target)
      if (from == "src/machine" && to ~ /^passes/) {
        printf "%s: src/machine includes %s (passes/ lie above the machine)\n", FILENAME, inc > "/dev/stderr"
        bad = 1
      }
      if (from != to) print from, to
    }
    END { exit bad }
  ' <(echo "$files") $files) | sort -u >"$edges" || status=1
  if [ -n "$allowed" ]; then
    local kept
    kept=$(grep -vxF -f <(entries "$allowed" | tr -s ' \t' ' ') "$edges" || true)
    echo "$kept" >"$edges"
  fi
  # tsort names the folders of a cycle on stderr ("input contains a loop:", then one a line)
  local loops
  loops=$(tsort <"$edges" 2>&1 >/dev/null || true)
  if [ -n "$loops" ]; then
    echo "include cycle between folders:" >&2
    echo "$loops" | sed -n 's/^tsort: //p' | grep -v 'input contains a loop' | sed 's/^/  /' >&2
    echo "folder edges:" >&2
    sed 's/^/  /' "$edges" >&2
    status=1
  fi
  return $status
}

forbidden() {
  local root=$1 list=$2 exempt=$3 regex hits status=0
  local -a excludes=()
  while IFS= read -r path; do excludes+=("$root/$path"); done < <(entries "$exempt")
  while IFS= read -r regex; do
    local rc=0
    grep -qE -e "$regex" /dev/null || rc=$?
    if [ $rc -gt 1 ]; then
      echo "$(basename "$list"): not an extended regex: $regex" >&2
      return 2
    fi
    hits=$(grep -rnE --include='*.h' --include='*.cpp' -e "$regex" "$root/src" "$root/passes" |
      while IFS= read -r hit; do
        local skip=0
        for e in "${excludes[@]}"; do [[ $hit == "$e"* ]] && skip=1; done
        [ $skip = 0 ] && echo "${hit#"$root"/}"
      done || true)
    if [ -n "$hits" ]; then
      echo "the core spells a dialect's number (/$regex/ in $(basename "$list")):" >&2
      echo "$hits" | sed 's/^/  /' >&2
      status=1
    fi
  done < <(entries "$list")
  return $status
}

case "${1:-}" in
layering)
  [ $# = 2 ] || [ $# = 3 ] || usage
  layering "$(cd "$2" && pwd)" "${3:-}"
  ;;
forbidden)
  [ $# = 4 ] || usage
  forbidden "$(cd "$2" && pwd)" "$3" "$4"
  ;;
*) usage ;;
esac
