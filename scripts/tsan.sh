#!/usr/bin/env bash
# Builds the baker's tests with -fsanitize=thread in build-tsan/ and runs those that bake with
# several threads (determinism across thread counts and shards, the grid, probes, visibility).
# TBB itself is not instrumented: its task hand-offs are invisible to ThreadSanitizer, so races
# reported inside libtbb are suppressed (tests/sanitizers/tsan.supp); a race in our code fails.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build-tsan
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DONELIGHT_TESTS=ON \
    -DONELIGHT_TSAN=ON >/dev/null
fi
cmake --build "$build" -j2 --target onelight_bake_tests
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$root/tests/sanitizers/tsan.supp"
ctest --test-dir "$build" --output-on-failure -R "BakeDeterminism|LightGrid|DominantPrimary|Visibility" "$@"
