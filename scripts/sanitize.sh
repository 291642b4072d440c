#!/usr/bin/env bash
# Builds the unit tests with -fsanitize=address,undefined in build-asan/ and runs them.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build-asan
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DONELIGHT_SANITIZE=ON >/dev/null
fi
cmake --build "$build" -j2 --target onelight_unit_tests
mkdir -p "$build/xdg" && chmod 700 "$build/xdg"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir "$build" --output-on-failure -L unit
