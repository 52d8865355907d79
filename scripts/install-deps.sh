#!/usr/bin/env bash
# Install the Debian packages gcx needs, only when some are missing.
# usage: install-deps.sh REQUIRED... -- OPTIONAL...
# OPTIONAL packages (the rs274 oracle, chromium) are tried once; their absence skips the tests
# that need them (differential tests, the report rendering test).
set -euo pipefail
required=() optional=() seen_sep=0
for p in "$@"; do
  if [ "$p" = "--" ]; then seen_sep=1; continue; fi
  if [ $seen_sep = 0 ]; then required+=("$p"); else optional+=("$p"); fi
done
missing() { for p in "$@"; do dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'ok installed' || echo "$p"; done; }
need=$(missing "${required[@]}")
want=$(missing "${optional[@]}")
[ -z "$need$want" ] && exit 0
SUDO=""; [ "$(id -u)" = 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
if [ -n "$need" ]; then
  echo "installing: $need"
  $SUDO apt-get install -y -qq --no-install-recommends $need
fi
if [ -n "$want" ]; then
  echo "installing (optional): $want"
  $SUDO apt-get install -y -qq --no-install-recommends $want || echo "warning: could not install $want; the tests that need it will be skipped"
fi
