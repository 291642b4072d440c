#!/usr/bin/env bash
# The Slurm bake on one node: a Quake 3 map baked locally, then with --slurm 2 and --slurm 8 on a
# single-node Slurm started on localhost (tests/slurm/local_slurm.sh), each shard given the whole
# node (--cpus-per-task = every core), so the shards run one after another and each shard's time
# is what a dedicated node of this size would take. Checks that every package equals the local
# one, prints the wall times, each shard's and the merge's, and the wall time on paper for 64
# nodes: each shard's time modelled as F + W/N (F: what every shard runs whole, W: the split
# work), F and W fitted from the mean shard times at N = 2 and 8, plus the merge and the
# scheduling overhead measured at N = 8.
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
  grep -E '^  (shard|balance|merge) ' "$out/slurm$n.txt"
  mean=$(awk '$1 == "shard" { s += $4; k++ } END { printf "%.3f", s / k }' "$out/slurm$n.txt")
  slowest=$(awk '$1 == "shard" && $4 > m { m = $4 } END { printf "%.3f", m }' "$out/slurm$n.txt")
  merge=$(awk '$1 == "merge" { print $3 }' "$out/slurm$n.txt")
  eval "mean$n=$mean slowest$n=$slowest merge$n=$merge wall$n=$wall"
done

# Shard time F + W/N through the means at N = 2 and 8; 64 nodes run every shard at once.
w=$(calc "($mean2 - $mean8) / (1/2 - 1/8)")
f=$(calc "$mean8 - $w / 8")
shard64=$(calc "$f + $w / 64")
# Overhead at N = 8: the wall time less the shards (one after another) and the merge.
sum8=$(awk '$1 == "shard" { s += $4 } END { printf "%.3f", s }' "$out/slurm8.txt")
overhead=$(calc "$wall8 - $sum8 - $merge8")
spread=$(calc "$slowest8 / $mean8")
printf 'model: shard = %.2f s + %.2f s / N (fixed part every shard runs + split work)\n' "$f" "$w"
printf '64 nodes, on paper: shard %.2f s x %.2f (spread at N = 8) + merge %.2f s + overhead %.2f s = %.1f s (local %.1f s)\n' \
  "$shard64" "$spread" "$merge8" "$overhead" \
  "$(calc "$shard64 * $spread + $merge8 + $overhead")" "$local_s"
rm -rf "$out/work2" "$out/work8"
echo "slurm-benchmark: outputs in $out"
