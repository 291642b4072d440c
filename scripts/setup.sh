#!/usr/bin/env bash
# Shared by ./play and ./test: install missing Debian packages, configure (Ninja, Release, ccache),
# build with -j2. Idempotent: a second run installs nothing, configures nothing and builds only
# what changed.
# Usage: scripts/setup.sh [BUILD_DIR [extra cmake args...]]
#   ONELIGHT_TEST_PACKAGES=1   adds the packages of scripts/test-packages.txt and configures the
#                              tests, benchmarks and lab (./test sets it)
#   ONELIGHT_TARGETS="a b"     builds only those targets (./play: the game, the baker, the demo
#                              level); the default is everything
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

cache=$build/CMakeCache.txt
# A build folder made by another generator (the Makefiles of older checkouts) is configured anew.
if [ -f "$cache" ] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' "$cache"; then
  echo "onelight: $build was not configured for Ninja; configuring it again" >&2
  rm -rf "$cache" "$build/CMakeFiles"
fi
tests=OFF
[ "${ONELIGHT_TEST_PACKAGES:-0}" = 1 ] && tests=ON
if [ ! -f "$cache" ]; then
  args=(-G Ninja -DCMAKE_BUILD_TYPE=Release)
  [ "$tests" = ON ] && args+=(-DONELIGHT_TESTS=ON)
  cmake -S "$root" -B "$build" "${args[@]}" "$@" >/dev/null
elif [ "$tests" = ON ] && grep -q '^ONELIGHT_TESTS:BOOL=OFF$' "$cache"; then
  cmake -S "$root" -B "$build" -DONELIGHT_TESTS=ON "$@" >/dev/null
fi
read -r -a targets <<< "${ONELIGHT_TARGETS:-all}"
cmake --build "$build" -j2 --target "${targets[@]}"
