#!/usr/bin/env bash
# The Slurm bake on one node: a Quake 3 map baked locally, then with --slurm 2 and --slurm 8 on a
# single-node Slurm started on localhost (tests/slurm/local_slurm.sh), each shard given the whole
# node (--cpus-per-task = every core), so the shards run one after another and each shard's time
# is what a dedicated node of this size would take. Checks that every package equals the local
# one, prints the wall times, each shard's and the merge's, and the wall time on paper for 64
# nodes (and for 2 and 8 nodes: the slowest shard, the merge and the overhead), the model stated
# at its end. Times are noisy under load: run it on a quiet machine, and read /proc/loadavg.
#
#   scripts/slurm-benchmark.sh [MAP] [QUALITY]     (default: aggressor draft; needs a build,
#                                                   OpenArena's maps and the Slurm packages)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
map=${1:-aggressor}
quality=${2:-draft}
bake=$root/build/bin/onelight-bake
[ -x "$bake" ] || { echo "slurm-benchmark: $bake is missing; build first (scripts/setup.sh)" >&2; exit 1; }
out=$(mktemp -d /tmp/onelight-slurm-bench.XXXXXX)
chmod 755 "$out"  # munged's socket folder must be reachable by all
cluster=$out/cluster
trap '"$root/tests/slurm/local_slurm.sh" stop "$cluster"' EXIT
conf=$("$root/tests/slurm/local_slurm.sh" start "$cluster")
export SLURM_CONF=$conf
cores=$(nproc)
now() { date +%s.%N; }
calc() { awk "BEGIN { printf \"%.6f\", $1 }"; }

start=$(now)
"$bake" "$map" -o "$out/local.olpak" --quality "$quality" --quiet > "$out/local.txt"
local_s=$(calc "$(now) - $start")
printf 'local bake: %.1f s (%s, %s, %s cores; load %s)\n' "$local_s" "$map" "$quality" "$cores" \
  "$(cut -d' ' -f1-3 /proc/loadavg)"

for n in 2 8; do
  start=$(now)
  "$bake" "$map" -o "$out/slurm$n.olpak" --quality "$quality" --quiet --slurm "$n" \
    --cpus-per-task "$cores" --work "$out/work$n" > "$out/slurm$n.txt"
  wall=$(calc "$(now) - $start")
  cmp -s "$out/local.olpak" "$out/slurm$n.olpak" || { echo "slurm-benchmark: --slurm $n differs from the local bake" >&2; exit 1; }
  printf -- '--slurm %s: %.1f s wall, identical to the local bake\n' "$n" "$wall"
  grep -E '^  (compile|shard|balance|gathers|merge) ' "$out/slurm$n.txt"
  # The shards' median time (every shard bakes its share of each stage, the visibility set too).
  median=$(awk '$1 == "shard" { print $4 }' "$out/slurm$n.txt" | sort -n |
    awk '{ v[NR] = $1 } END { printf "%.3f", NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
  sum=$(awk '$1 == "shard" { s += $4 } END { printf "%.3f", s }' "$out/slurm$n.txt")
  slowest=$(awk '$1 == "shard" && $4 > m { m = $4 } END { printf "%.3f", m }' "$out/slurm$n.txt")
  merge=$(awk '$1 == "merge" { print $3 }' "$out/slurm$n.txt")
  compile=$(awk '$1 == "compile" && $4 == "s," { print $3 }' "$out/slurm$n.txt")
  eval "median$n=$median sum$n=$sum slowest$n=$slowest merge$n=$merge wall$n=$wall compile$n=${compile:-0}"
done

# On paper, 64 nodes run every shard at once: the compile (once, before the shards), then a
# shard takes F + W/N (F: what every shard runs whole, W: the divided work), fitted through the
# median shard at N = 2 and 8, times the slowest-to-median spread measured at N = 8; then the
# merge, and the scheduling overhead measured at N = 8 (its wall time less the compile, the
# shards, run one after another, and the merge).
w=$(calc "($median2 - $median8) / (1/2 - 1/8)")
f=$(calc "$median8 - $w / 8")
spread=$(calc "$slowest8 / $median8")
overhead=$(calc "$wall8 - $compile8 - $sum8 - $merge8")
printf 'model: compile %.2f s; shard = %.2f s + %.2f s / N, slowest %.2f x the median; merge %.2f s; overhead %.2f s\n' \
  "$compile8" "$f" "$w" "$spread" "$merge8" "$overhead"
printf '64 nodes, on paper: %.1f s (local %.1f s; 2 nodes on paper %.1f s, 8 nodes %.1f s)\n' \
  "$(calc "$compile8 + ($f + $w / 64) * $spread + $merge8 + $overhead")" "$local_s" \
  "$(calc "$compile2 + $slowest2 + $merge2 + $overhead")" \
  "$(calc "$compile8 + $slowest8 + $merge8 + $overhead")"
rm -rf "$out/work2" "$out/work8"
echo "slurm-benchmark: outputs in $out"
