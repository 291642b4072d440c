#!/usr/bin/env bash
# Builds the baker's tests with -fsanitize=thread in build-tsan/ and runs those that bake with
# several threads (determinism across thread counts and shards, the grid, probes, visibility).
# TBB itself is not instrumented: its task hand-offs are invisible to ThreadSanitizer, so races
# reported inside libtbb are suppressed (tests/sanitizers/tsan.supp); a race in our code fails.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build-tsan
# -O1 -g1: line tables are all a sanitizer's stack trace needs, and the build takes half the
# time of -O2 -g (measured on bake_level.cpp and q3_import_test.cpp with ASan: 18 s and 35 s
# against 9 s and 16 s), which CI's time limit wants.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DONELIGHT_TESTS=ON -DONELIGHT_TSAN=ON >/dev/null
cmake --build "$build" -j2 --target onelight_bake_tests
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$root/tests/sanitizers/tsan.supp"
ctest --test-dir "$build" --output-on-failure -R "BakeDeterminism|LightGrid|DominantPrimary|Visibility" "$@"
