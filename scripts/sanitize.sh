#!/usr/bin/env bash
# Builds everything with -fsanitize=address,undefined in build-asan/ and runs the whole ctest
# suite there: unit, numerics, lab, cli, then gpu (lavapipe). Every test is checked for memory
# errors and undefined behaviour; all but the gpu ones for leaks too. The Vulkan loader unloads
# the driver (lavapipe, LLVM, the validation layer) at vkDestroyInstance, so the blocks it
# leaves behind show as "<unknown module>" and cannot be attributed or suppressed: the gpu
# label runs with leak detection off (our code's leaks are caught by the rest of the suite).
# The slurm label is left out: it starts Debian's Slurm and munge daemons and runs our bake
# inside their jobs, the same bake, merge and shard code the rest of the suite runs under the
# sanitizers (the Slurm library's own code is in the unit label, which runs here); under ASan
# its bakes would only cost CI minutes, and a sanitizer report from inside a job would land in
# the job's log rather than in ctest's output.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build-asan
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DONELIGHT_SANITIZE=ON >/dev/null
fi
cmake --build "$build" -j2
mkdir -p "$build/xdg" && chmod 700 "$build/xdg"
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
status=0
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:detect_odr_violation=0 \
  ctest --test-dir "$build" --output-on-failure -j2 -LE "gpu|slurm" "$@" || status=1
ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:detect_odr_violation=0 \
  ctest --test-dir "$build" --output-on-failure -j2 -L gpu "$@" || status=1
exit $status
