#!/usr/bin/env bash
# Builds the tests with -fsanitize=address,undefined in build-asan/ and runs those that parse
# input or run the baker's threads: labels unit and cli (import, packages, replays, command lines,
# hostile input, interrupted bakes, determinism across threads and shards, the grid, probes,
# the dominant primary), with leak detection on. Extra arguments go to ctest.
#
# Left out, because they run the same code once more at sanitizer speed and find nothing the
# unit and cli tests do not: numerics (long loops of the same transport and BRDF code against
# references) and gpu (the renderer on lavapipe: the Vulkan loader unloads the driver at
# vkDestroyInstance, so its blocks show as "<unknown module>" leaks that cannot be attributed),
# lab, and slurm (Debian's daemons run our bake inside their jobs, where a sanitizer report would
# land in the job's log). They run in ./test, once.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build-asan
# -O1 -g1: line tables are all a sanitizer's stack trace needs, and the build takes half the
# time of -O2 -g (measured on bake_level.cpp and q3_import_test.cpp with ASan: 18 s and 35 s
# against 9 s and 16 s), which CI's time limit wants.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DONELIGHT_TESTS=ON -DONELIGHT_SANITIZE=ON >/dev/null
cmake --build "$build" -j2 --target onelight_sanitized_tests
mkdir -p "$build/xdg" && chmod 700 "$build/xdg"
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:detect_odr_violation=0 \
  ctest --test-dir "$build" --output-on-failure -j2 -L "unit|cli" "$@"
