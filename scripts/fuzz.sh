#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang, ASan and UBSan in build-fuzz/, makes a
# seed corpus of real files for each, and runs each target for a bounded time or count:
#   scripts/fuzz.sh                 60 s per target (CI runs --seconds 45)
#   scripts/fuzz.sh --seconds S     S seconds per target
#   scripts/fuzz.sh --runs N        N executions per target (the benchmark: 10000000)
#   scripts/fuzz.sh ... --only T,U  only the targets named (fuzz_gltf, fuzz_q3, fuzz_q3_text,
#                                   fuzz_md3, fuzz_image, fuzz_zip, fuzz_package, fuzz_replay,
#                                   fuzz_command_line)
#   scripts/fuzz.sh ... --timeout S one input running longer than S wall seconds is a finding
#                                   (20; raise it on a loaded machine, where a starved process
#                                   can take that long over an input that needs 0.05 s)
#   scripts/fuzz.sh ... --jobs J    J targets side by side (1; each target is one process on
#                                   one core, so CI gives its 2 cores 2 targets at a time)
# Prints, per target, its executions and the result; exits non-zero on any finding (the
# reproducer is left in build-fuzz/findings/TARGET/).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$root/build-fuzz
limit=(-max_total_time=60)
all="fuzz_gltf fuzz_q3 fuzz_q3_text fuzz_md3 fuzz_image fuzz_zip fuzz_package fuzz_replay fuzz_command_line"
targets=$all
timeout=20
jobs=1
usage="usage: scripts/fuzz.sh [--seconds S | --runs N] [--only TARGET,...] [--timeout S] [--jobs J]"
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) limit=(-max_total_time="$2"); shift 2 ;;
    --runs) limit=(-runs="$2"); shift 2 ;;
    --only) targets=${2//,/ }; shift 2 ;;
    --timeout) timeout=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    *) echo "$usage" >&2; exit 2 ;;
  esac
done
case "$jobs" in
  '' | *[!0-9]* | 0) echo "scripts/fuzz.sh: --jobs wants a count of 1 or more, not '$jobs'" >&2; exit 2 ;;
esac
for target in $targets; do
  case " $all " in
    *" $target "*) ;;
    *) echo "scripts/fuzz.sh: unknown target '$target'; $usage" >&2; exit 2 ;;
  esac
done
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DONELIGHT_FUZZ=ON >/dev/null
fi
cmake --build "$build" -j2 --target onelight_fuzzers

# Seed corpora: real files of each kind.
# (one folder per run, so that runs of different targets can go side by side)
corpus=$(mktemp -d "$build/corpus.XXXXXX")
trap 'rm -rf "$corpus"' EXIT
for target in $all; do mkdir -p "$corpus/$target"; done
cp "$root"/tests/render/levels/*.gltf "$root"/tests/fuzz/seeds/gltf/* "$corpus/fuzz_gltf/"
cp "$root"/game/replays/*.replay "$corpus/fuzz_replay/"
cp "$root"/tests/fuzz/seeds/command_line/* "$corpus/fuzz_command_line/"
maps=/usr/share/games/openarena/baseoa
if [ -d "$maps" ]; then
  python3 - "$maps" "$corpus/fuzz_q3" <<'PY'
import sys, zipfile, glob, os
folder, out = sys.argv[1], sys.argv[2]
taken = 0
for pk3 in sorted(glob.glob(os.path.join(folder, "*.pk3"))):
    with zipfile.ZipFile(pk3) as z:
        for name in z.namelist():
            small_map = name.endswith(".bsp") and z.getinfo(name).file_size < 2_000_000
            if (small_map and taken < 4) or (name.endswith(".shader") and taken < 12):
                open(os.path.join(out, os.path.basename(name)), "wb").write(z.read(name))
                taken += 1
PY
  # Images (TGA, JPEG, PNG, small ones), shader scripts, excerpts of .map sources, small pk3s.
  python3 - "$maps" "$corpus" <<'PY'
import sys, zipfile, glob, os, io
folder, corpus = sys.argv[1], sys.argv[2]

def map_excerpt(text, budget=32768):
    """Whole blocks of a .map source within about budget bytes: worldspawn's keys and its first
    brushes and patches, then point entities, so that each execution parses kilobytes (the real
    sources are 0.3-0.8 MB, which held fuzz_q3_text to 100 executions a second)."""
    entities, brushes, depth, start, quoted = [], [], 0, 0, False
    for i, c in enumerate(text):
        if c == '"':
            quoted = not quoted
        elif not quoted and c == "{":
            if depth <= 1:
                start = i
            depth += 1
        elif not quoted and c == "}":
            depth -= 1
            if depth == 0:
                entities.append((start_entity, i + 1))
            elif depth == 1 and not entities:  # a brush or patch of worldspawn
                brushes.append((start, i + 1))
        if not quoted and c == "{" and depth == 1:
            start_entity = i
    if not entities:
        return text[:budget]
    keys_end = brushes[0][0] if brushes else entities[0][1] - 1
    out = [text[entities[0][0]:keys_end]]
    size = len(out[0])
    for begin, end in brushes:
        if size + end - begin > budget // 2:
            break
        out.append(text[begin:end] + "\n")
        size += end - begin
    out.append("}\n")
    for begin, end in entities[1:]:
        if size + end - begin > budget:
            break
        out.append(text[begin:end] + "\n")
        size += end - begin
    return "".join(out)

counts = {".tga": 0, ".jpg": 0, ".png": 0, ".shader": 0, ".map": 0, ".md3": 0}
limits = {".tga": (8, 65536), ".jpg": (8, 65536), ".png": (4, 65536), ".shader": (8, 16384),
          ".map": (3, 1 << 20), ".md3": (12, 16384)}
for pk3 in sorted(glob.glob(os.path.join(folder, "*.pk3"))):
    with zipfile.ZipFile(pk3) as z:
        for info in z.infolist():
            ext = os.path.splitext(info.filename)[1].lower()
            if ext not in counts or counts[ext] >= limits[ext][0] or info.file_size > limits[ext][1]:
                continue
            target = ("fuzz_image" if ext in (".tga", ".jpg", ".png")
                      else "fuzz_md3" if ext == ".md3" else "fuzz_q3_text")
            name = f"{counts[ext]}{ext}"
            data = z.read(info)
            if ext == ".map":
                data = map_excerpt(data.decode("latin-1")).encode("latin-1")
            open(os.path.join(corpus, target, name), "wb").write(data)
            counts[ext] += 1
# Small pk3s: deflated, stored, and one with a folder entry.
for n, method in enumerate((zipfile.ZIP_DEFLATED, zipfile.ZIP_STORED)):
    data = io.BytesIO()
    with zipfile.ZipFile(data, "w", method) as z:
        z.writestr("scripts/a.shader", "textures/a\n{\n\tsurfaceparm nolightmap\n}\n")
        z.writestr("textures/a.tga", bytes([0, 0, 10, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 2, 0, 24, 0x20,
                                            0x81, 1, 2, 3, 0x81, 4, 5, 6]))
        if n:
            z.writestr("maps/", "")
    open(os.path.join(corpus, "fuzz_zip", f"{n}.pk3"), "wb").write(data.getvalue())
PY
fi
printf '%s' "-meta; -vis; -light -fast -gamma 1.5 -exposure 200 -compensate 2 -bounce 8 -dirty -scale 1.25" \
  >"$corpus/fuzz_q3_text/cmdline.txt"
cp "$root"/tests/fuzz/seeds/q3/* "$corpus/fuzz_q3/"
# Packages: compiled and baked by the main build's onelight-bake, when there is one.
bake=$root/build/bin/onelight-bake
if [ -x "$bake" ]; then
  for level in "$root"/tests/fuzz/seeds/gltf/triangle.gltf; do
    name=$(basename "$level" .gltf)
    # A coarse lightmap keeps the packages small, so that each execution is fast.
    "$bake" compile "$level" --texels-per-metre 4 -o "$corpus/fuzz_package/$name.compiled.olpak" >/dev/null
    "$bake" "$level" --quality draft --quiet --texels-per-metre 4 \
      -o "$corpus/fuzz_package/$name.baked.olpak" >/dev/null
  done
fi

# One target's run: its summary line goes to $build/$target.result, and its exit code says
# whether it found something.
run_target() {
  local target=$1 findings=$build/findings/$1 log=$build/$1.log extra=() max_len=4000000
  rm -rf "$findings" && mkdir -p "$findings" "$build/work/$target"
  [ "$target" = fuzz_package ] && extra=(-use_value_profile=1)
  # Text parsers are linear: 16 KB inputs reach every path a megabyte would, far more often.
  [ "$target" = fuzz_q3_text ] && max_len=16384
  local seeds started=$SECONDS result code=0
  seeds=$(ls "$corpus/$target" | wc -l)
  if (cd "$findings" && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
      UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      "$build/bin/$target" "${limit[@]}" "${extra[@]}" -rss_limit_mb=4096 -timeout="$timeout" \
      -max_len=$max_len -print_final_stats=1 "$build/work/$target" "$corpus/$target" >"$log" 2>&1); then
    result="no finding"
  else
    result="FINDING (see $log and $findings)"
    code=1
  fi
  # (a run that ends in a finding prints its statistics twice: the last count is the run's)
  local runs
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  echo "fuzz: $target: ${runs:-?} executions in $((SECONDS - started)) s from $seeds seeds: $result" \
    | tee "$build/$target.result"
  return $code
}

status=0
running=0
for target in $targets; do
  if [ "$running" -ge "$jobs" ]; then
    wait -n || status=1
    running=$((running - 1))
  fi
  run_target "$target" &
  running=$((running + 1))
done
while [ "$running" -gt 0 ]; do
  wait -n || status=1
  running=$((running - 1))
done
exit $status
