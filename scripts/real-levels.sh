#!/usr/bin/env bash
# The real-level table: four OpenArena maps compiled, baked at draft and default quality, and
# drawn at 1280x720 from three spawns each, ours beside q3map2's own lightmaps.
#
#   scripts/real-levels.sh [OUT_DIR]     (default build/real-levels; needs a build and the
#                                         packages of scripts/test-packages.txt)
#
# Writes OUT_DIR/real-levels.md (the table), OUT_DIR/real-levels.json (every figure),
# docs/images/real-levels.png (the contact sheet: each spawn, ours | q3map2, at our metered
# exposure) and rewrites the README's table between its real-levels markers. Run it on a quiet
# machine: frame times rise several-fold when another process uses the cores. It takes about
# half an hour on two cores.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-build/real-levels}"
bin=build/bin
mkdir -p "$out" docs/images
for tool in onelight onelight-bake onelight-lab; do
    [[ -x "$bin/$tool" ]] || { echo "real-levels: $bin/$tool is missing; build first (./test)" >&2; exit 1; }
done
command -v python3 > /dev/null || { echo "real-levels: python3 is needed for the table" >&2; exit 1; }

# name|level argument
maps=("aggressor|pak1-maps.pk3:maps/aggressor.bsp" "q3dm6ish|q3dm6ish" "kaos|kaos" "oa_bases3|oa_bases3")
spawns=(spawn0 spawn1 spawn2)

now() { date +%s.%N; }
sheet_images=() sheet_ev=()
for entry in "${maps[@]}"; do
    name="${entry%%|*}" level="${entry#*|}"
    dir="$out/$name"
    mkdir -p "$dir"
    echo "real-levels: $name: compile" >&2
    start=$(now)
    "$bin/onelight-bake" compile "$level" -o "$dir/compiled.olpak" > "$dir/compile.txt"
    python3 -c "import sys; print(float(sys.argv[2]) - float(sys.argv[1]))" "$start" "$(now)" \
        > "$dir/compile.seconds"
    for quality in draft default; do
        echo "real-levels: $name: bake at $quality quality" >&2
        "$bin/onelight-bake" "$level" -o "$dir/$quality.olpak" --quality "$quality" \
            --report "$dir/$quality.json" > "$dir/$quality.txt"
    done
    for spawn in "${spawns[@]}"; do
        echo "real-levels: $name: frame from $spawn" >&2
        "$bin/onelight" "$dir/default.olpak" --headless --size 1280x720 --camera "$spawn" \
            --capture "$dir/$spawn" > /dev/null
        ev=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['camera']['ev100'])" "$dir/$spawn.json")
        for view in onelight q3map2; do
            "$bin/onelight" "$dir/default.olpak" --headless --size 256x144 --camera "$spawn" \
                --view "$view" --ev100 "$ev" --capture "$dir/${spawn}_small_$view" > /dev/null
            sheet_images+=("$dir/${spawn}_small_$view.exr")
        done
        sheet_ev+=("$ev")
    done
done

# The captures' EXRs hold radiance before exposure: the sheet exposes each row as it was drawn.
images=$(IFS=,; echo "${sheet_images[*]}")
evs=$(IFS=,; echo "${sheet_ev[*]}")
"$bin/onelight-lab" sheet -o docs/images/real-levels.png --columns 2 --ev100 "$evs" --images "$images" > /dev/null

python3 - "$out" "${maps[@]}" <<'PY'
import json, os, re, sys
out, maps = sys.argv[1], [m.split("|")[0] for m in sys.argv[2:]]
spawns = ["spawn0", "spawn1", "spawn2"]
rows, figures = [], {}
for name in maps:
    d = os.path.join(out, name)
    draft = json.load(open(os.path.join(d, "draft.json")))
    default = json.load(open(os.path.join(d, "default.json")))
    compile_text = open(os.path.join(d, "compile.txt")).read()
    static = int(re.search(r"triangles\s+(\d+) static \((\d+) imported", compile_text).group(1))
    imported = int(re.search(r"\((\d+) imported", compile_text).group(1))
    frames = []
    for s in spawns:
        j = json.load(open(os.path.join(d, s + ".json")))
        frames.append({"spawn": s, "gpu_ms": j["timings_ms"]["gpu"], "cpu_ms": j["timings_ms"]["cpu"],
                       "draws": j["frame"]["surfaces_drawn"], "triangles": j["frame"]["triangles"],
                       "ev100": j["camera"]["ev100"]})
    f = {"map": name, "triangles_imported": imported, "triangles_compiled": static,
         "lights": default["lights"], "compile_seconds": float(open(os.path.join(d, "compile.seconds")).read()),
         "bake_seconds": {"draft": draft["seconds_total"], "default": default["seconds_total"]},
         "noise": {"draft": draft["lightmap"]["estimated_relative_noise"],
                   "default": default["lightmap"]["estimated_relative_noise"]},
         "peak_memory_mib": {"draft": draft["peak_memory_bytes"] / 2**20,
                             "default": default["peak_memory_bytes"] / 2**20},
         "package_mib": default["package_bytes"] / 2**20, "frames": frames,
         "warnings": default["warnings"]}
    figures[name] = f
    l = f["lights"]
    ms = " / ".join("%.0f" % x["gpu_ms"] for x in frames)
    draws = " / ".join(str(x["draws"]) for x in frames)
    tris = " / ".join("%.1fk" % (x["triangles"] / 1000) for x in frames)
    rows.append("| %s | %d (%d) | %d + %d%s | %.1f | %.0f (%.1f%%) | %.0f (%.1f%%) | %.0f | %.1f | %s | %s | %s |" % (
        name, imported, static, l["primary"], l["baked"],
        " + %d emissive tris" % l["emissive_triangles"] if l["emissive_triangles"] else "",
        f["compile_seconds"], f["bake_seconds"]["draft"], 100 * f["noise"]["draft"],
        f["bake_seconds"]["default"], 100 * f["noise"]["default"],
        max(f["peak_memory_mib"].values()), f["package_mib"], ms, draws, tris))
table = "\n".join([
    "| map | triangles: map (compiled) | lights: primary + baked | compile s | bake draft s (noise) | bake default s (noise) | peak MiB | package MiB | frame GPU ms, 3 spawns | draws | triangles drawn |",
    "|---|---|---|---|---|---|---|---|---|---|---|"] + rows)
json.dump(figures, open(os.path.join(out, "real-levels.json"), "w"), indent=2)
open(os.path.join(out, "real-levels.md"), "w").write(table + "\n")
readme = open("README.md").read()
begin, end = "<!-- real-levels:begin -->", "<!-- real-levels:end -->"
if begin in readme and end in readme:
    a, b = readme.index(begin) + len(begin), readme.index(end)
    readme = readme[:a] + "\n" + table + "\n" + readme[b:]
    tmp = "README.md.tmp"
    open(tmp, "w").write(readme)
    os.replace(tmp, "README.md")
print(table)
PY
echo "real-levels: wrote $out/real-levels.md, $out/real-levels.json, docs/images/real-levels.png and the README's table" >&2
