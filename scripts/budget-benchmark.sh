#!/usr/bin/env bash
# The error budget's benchmark (issue: "model only what a scene needs"): a level that is one
# 200 m quad under a sun and a black sky (tests/render/levels/open_quad.gltf), baked as it is and
# with --error-budget 5%, then drawn at 1280x720. Prints a Markdown table of package bytes, bake
# seconds and frame GPU ms, each the median of RUNS runs made in turn (default 5), and the ratios.
#   scripts/budget-benchmark.sh [--runs N] [--level LEVEL.gltf] [--budget E]
# Needs a built tree (build/bin). Intermediate files go to a temporary folder, removed at exit.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bin=$root/build/bin
level=$root/tests/render/levels/open_quad.gltf
runs=5
budget=5%
usage="usage: scripts/budget-benchmark.sh [--runs N] [--level LEVEL.gltf] [--budget E]"
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --level) level=$2; shift 2 ;;
    --budget) budget=$2; shift 2 ;;
    *) echo "$usage" >&2; exit 2 ;;
  esac
done
[ -x "$bin/onelight-bake" ] && [ -x "$bin/onelight" ] || {
  echo "scripts/budget-benchmark.sh: no build in $bin; run ./test or cmake --build build first" >&2
  exit 1
}
[ -f "$level" ] || { echo "scripts/budget-benchmark.sh: no level '$level'" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval('d'+sys.argv[2]))" "$@"; }

# Bakes, in turn: as the level is, then with the budget.
for ((i = 0; i < runs; i++)); do
  for kind in full budget; do
    args=()
    [ "$kind" = budget ] && args=(--error-budget "$budget")
    start=$(date +%s.%N)
    "$bin/onelight-bake" "$level" -o "$work/$kind.olpak" --report "$work/$kind.json" --quiet \
      "${args[@]}" >/dev/null
    echo "$(date +%s.%N) - $start" | bc >>"$work/$kind.bake_s"
  done
done
# Frames, in turn: nine frames each, their median GPU time.
for ((i = 0; i < runs; i++)); do
  for kind in full budget; do
    "$bin/onelight" "$work/$kind.olpak" --headless --frames 9 --capture "$work/${kind}_frame" >/dev/null
    json "$work/${kind}_frame.json" "['timings_ms']['gpu_median']" >>"$work/$kind.frame_ms"
  done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores"
echo
echo "| | bytes | bake s (wall, median of $runs) | frame GPU ms (median of $runs) | lightmap texels sampled | probes | grid cells |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for kind in full budget; do
  r=$work/$kind.json
  echo "| $kind | $(json "$r" "['package_bytes']") | $(median <"$work/$kind.bake_s") |" \
    "$(median <"$work/$kind.frame_ms") | $(json "$r" "['lightmap']['texels_sampled']") |" \
    "$(json "$r" "['probes']['baked']") | $(json "$r" "['light_grid']['cells']") |"
done
fb=$(json "$work/full.json" "['package_bytes']"); bb=$(json "$work/budget.json" "['package_bytes']")
fs=$(median <"$work/full.bake_s"); bs=$(median <"$work/budget.bake_s")
ff=$(median <"$work/full.frame_ms"); bf=$(median <"$work/budget.frame_ms")
echo "| full / budget | $(echo "scale=2; $fb / $bb" | bc) | $(echo "scale=2; $fs / $bs" | bc) |" \
  "$(echo "scale=2; $ff / $bf" | bc) | | | |"
echo
echo "The budget's choices:"
python3 - "$work/budget.json" <<'PY'
import json, sys
for c in json.load(open(sys.argv[1]))["error_budget"]["choices"]:
    print(f"- {c['feature']}: {c['choice']} ({c['why']})")
PY
