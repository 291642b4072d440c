#!/usr/bin/env bash
# Shared by ./play and ./test: install missing Debian packages, configure, build (Release, -j2).
# Idempotent: a second run installs nothing, configures nothing and builds only what changed.
# Usage: scripts/setup.sh [BUILD_DIR [extra cmake args...]]; ONELIGHT_TEST_PACKAGES=1 adds the
# packages of scripts/test-packages.txt (./test sets it).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$root/build}
shift || true

lists=("$root/scripts/packages.txt")
[ "${ONELIGHT_TEST_PACKAGES:-0}" = 1 ] && lists+=("$root/scripts/test-packages.txt")
mapfile -t wanted < <(cat "${lists[@]}" | grep -v '^#' | sed '/^$/d')
missing=()
for p in "${wanted[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  line="apt-get install -y --no-install-recommends ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then
    echo "onelight: missing packages; as root run: apt-get update && $line" >&2
    exit 1
  fi
  echo "onelight: installing ${#missing[@]} missing packages: ${missing[*]}" >&2
  # munge and Slurm's daemons (for the slurm tests, which start their own on localhost) must not
  # start as system services when installed: Debian's policy-rc.d denies it for the install,
  # unless the machine has a policy of its own.
  policy=/usr/sbin/policy-rc.d
  made_policy=0
  if [ ! -e "$policy" ]; then
    made_policy=1
    printf '#!/bin/sh\n# onelight setup.sh: no service starts while it installs packages\nexit 101\n' > "$policy"
    chmod 755 "$policy"
    trap 'rm -f "$policy"' EXIT
  fi
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $line >/dev/null
  if [ "$made_policy" = 1 ]; then
    rm -f "$policy"
    trap - EXIT
  fi
fi

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
fi
cmake --build "$build" -j2
