#!/usr/bin/env python3
"""Every installed Quake 3 (IBSP v46) map through the engine, one at a time.

For each map of the installed games' pk3s (OpenArena's baseoa, Nexuiz's data; the version the
game loads when several pk3s hold one): compile, bake at draft, draw one frame from spawn 0
headless, and draw the same view with the map's own q3map2 lightmaps (--view q3map2) at the same
exposure. Reports per map: OK, approximated (the import or bake warned: what it approximated or
left out) or refused (with the reason), compile and bake seconds, the bake's peak memory, the
package's size, the frame's GPU time, how the two frames' mean linear colours differ (luminance
ratio of the means and of the median 8x8 block, chromaticity distance in CIE xy), and what the map's recorded q3map2 -light stage did. Writes a markdown table per game and a summary to OUT
(atomically: a temporary file renamed over it, after every map, so that an interrupted run keeps
what it measured), with a progress line per map on stderr. A map
that fails is reported and the run carries on.

  scripts/corpus.py OUT.md [--games openarena,nexuiz] [--maps REGEX] [--limit N]
                    [--bin build/bin] [--work DIR] [--rows FILE] [--resume] [--size WxH]
                    [--timeout S] [--no-bake]

Every finished map's row is appended to a rows file (default WORK/rows.jsonl), with the commit
of the binaries that made it (BIN/COMMIT when a copy of the binaries holds one, else the
checkout's HEAD); --resume keeps the rows already there and runs only the rest. A rows file
kept in the repository (--rows) lets a run that takes longer than one sitting go on in the
next, on another machine.

A run shares the machine by being held (scripts/hold PID WORK/holds -- COMMAND): the held time
is left out of its step times.

--no-bake compiles each map and draws spawn 0 unbaked (its primaries alone): whether every map
loads, compiles and draws, in minutes for the whole corpus.
"""
import argparse
import json
import os
import re
import resource
import struct
import subprocess
import sys
import tempfile
import time
import zipfile

GAMES = {
    "openarena": ("OpenArena", "/usr/share/games/openarena/baseoa"),
    "nexuiz": ("Nexuiz", "/usr/share/games/nexuiz/data"),
}


def maps_of(folder):
    """(name, pk3, inner) of each IBSP v46 map, the last pk3 in load order winning; and how
    many map files other pk3s hold that the game does not load."""
    if not os.path.isdir(folder):
        return [], 0
    pk3s = sorted((f for f in os.listdir(folder) if f.lower().endswith(".pk3")),
                  key=lambda f: (f.lower(), f))
    found, shadowed = {}, 0
    for pk3 in pk3s:
        path = os.path.join(folder, pk3)
        try:
            archive = zipfile.ZipFile(path)
        except (zipfile.BadZipFile, OSError) as e:
            print(f"corpus: {path}: not a readable pk3 ({e}); skipped", file=sys.stderr)
            continue
        for inner in archive.namelist():
            m = re.fullmatch(r"maps/(.+)\.bsp", inner, re.IGNORECASE)
            if not m:
                continue
            with archive.open(inner) as f:
                head = f.read(8)
            if len(head) < 8 or head[:4] != b"IBSP" or struct.unpack("<i", head[4:])[0] != 46:
                continue
            key = m.group(1).lower()
            shadowed += key in found
            found[key] = (m.group(1), path, inner)
    return [found[k] for k in sorted(found)], shadowed


def held_seconds(holds, start, end):
    """Seconds of [start, end] (epoch) during which the run was held: stopped by scripts/hold,
    which appends "START END" (epoch seconds) to the file `holds` (the work folder's). A held
    step's wall time less these is what it took, so that a run can share the machine with a
    build. Overlapping holds count once."""
    if not holds or not os.path.exists(holds):
        return 0.0
    spans = []
    for line in open(holds):
        parts = line.split()
        if len(parts) == 2:
            a, b = max(float(parts[0]), start), min(float(parts[1]), end)
            if b > a:
                spans.append((a, b))
    total, reached = 0.0, start
    for a, b in sorted(spans):
        a = max(a, reached)
        if b > a:
            total += b - a
            reached = b
    return total


def cpu_seconds(pid):
    """CPU seconds (user and system, every thread) process `pid` has used so far; 0 once it is
    gone."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    except (OSError, IndexError, ValueError):
        return 0.0


def run(argv, args):
    """(exit code, output, seconds) of argv; exit code None when it ran past args.timeout. The
    seconds leave out the time the run was held (held_seconds of args.holds). The timeout counts
    the step's work, not the machine's: its CPU seconds over the cores (a step slowed down by
    other work beside it is not cut short), and, for a step that hangs without working, four
    timeouts of wall time (held time left out)."""
    start, wall = time.monotonic(), time.time()
    cores = os.cpu_count() or 1
    with tempfile.TemporaryFile(mode="w+", errors="replace") as out:
        p = subprocess.Popen(argv, stdout=out, stderr=subprocess.STDOUT, text=True)
        code = None
        while True:
            try:
                code = p.wait(timeout=1.0)
                break
            except subprocess.TimeoutExpired:
                ran = time.monotonic() - start - held_seconds(args.holds, wall, time.time())
                if cpu_seconds(p.pid) / cores > args.timeout or ran > 4 * args.timeout:
                    p.kill()
                    p.wait()
                    break
        out.seek(0)
        text = out.read()
    return code, text, time.monotonic() - start - held_seconds(args.holds, wall, time.time())


def reason(output, fallback):
    for line in output.splitlines():
        if ": error: " in line:
            return line.split(": error: ", 1)[1]
    lines = [l for l in output.splitlines() if l.strip()]
    return lines[-1] if lines else fallback


def frame_radiance(capture_json):
    """The capture's mean linear radiance before exposure (its sidecar's "radiance"): RGB cd/m^2
    (a tonemapped PNG's mean would compress the ratios)."""
    return json.load(open(capture_json))["radiance"]["mean_rgb"]


def median_ratio(args, own_exr, q3_exr):
    """The median 8x8 block's luminance in our frame over q3map2's view (onelight-lab
    frame-error's median_level): the level of a typical surface, which the lamps' own pixels
    (emission in ours, lightmapped texture in q3map2's) do not move; None without the lab or the
    captures."""
    if not args.lab or not (os.path.exists(own_exr) and os.path.exists(q3_exr)):
        return None
    code, out, _ = run([args.lab, "frame-error", own_exr, q3_exr], args)
    m = re.search(r"median_level=([0-9.eE+-]+)", out) if code == 0 else None
    return float(m.group(1)) if m else None


def light_from(compile_output):
    """Where the map's baked light came from, from the import's light-source lines: the BSP's
    light entities, its source .map's, or q3map2's own lightmaps (then the luminance ratio is 1
    by construction), or only its sky and surface lights."""
    text = compile_output
    if "lightmaps: recovered from q3map2's own" in text:
        return "q3map2's lightmaps"
    m = re.search(r"light entities: (\d+) from the source \.map", text)
    if m:
        return f"source .map ({m.group(1)} lights)"
    m = re.search(r"light entities: (\d+) from the BSP", text)
    if m:
        return f"BSP ({m.group(1)} lights)"
    return "sky and surface lights"


def q3map2_options(compile_output):
    """The import's "q3map2 options" line, short: what the map's recorded -light stage did."""
    for line in compile_output.splitlines():
        if "q3map2 options: " in line:
            text = line.split("q3map2 options: ", 1)[1]
            return "not recorded" if text.startswith("not recorded") else text.split("': ", 1)[-1]
    return ""


def luminance(rgb):
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]


def chromaticity(rgb):
    """CIE xy of a linear sRGB colour; None when black."""
    x = 0.4124 * rgb[0] + 0.3576 * rgb[1] + 0.1805 * rgb[2]
    y = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]
    z = 0.0193 * rgb[0] + 0.1192 * rgb[1] + 0.9505 * rgb[2]
    s = x + y + z
    return None if s <= 1e-9 else (x / s, y / s)


def one_map(name, pk3, inner, args, work, stem):
    """One map through compile, draft bake and the two frames. Its files in `work` are named
    `stem` (the game's key and the map's name: two games may ship maps of one name)."""
    spec = f"{pk3}:{inner}"
    package = os.path.join(work, stem + ".olpak")
    report = package[:-6] + ".json"
    row = {"map": name, "pk3": os.path.basename(pk3), "status": "refused", "why": ""}
    code, out, row["compile_s"] = run([args.bake, "compile", spec, "-o", package], args)
    if code != 0:
        row["why"] = "compile: " + (reason(out, "failed") if code is not None else "timed out")
        return row
    row["q3map2"] = q3map2_options(out)
    row["light_from"] = light_from(out)
    if args.no_bake:
        return compiled_map(row, out, package, stem, args, work)
    code, out, row["bake_s"] = run([args.bake, spec, "-o", package, "--quality", "draft",
                                    "--quiet", "--report", report], args)
    if code != 0:
        row["why"] = "bake: " + (reason(out, "failed") if code is not None else "timed out")
        return row
    warnings = []
    try:
        r = json.load(open(report))
        row["peak_mib"] = r.get("peak_memory_bytes", 0) / 2**20
        warnings = r.get("warnings", [])
    except (OSError, ValueError):
        pass
    if "peak_mib" not in row:  # the largest child so far, an upper bound
        row["peak_mib"] = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    row["package_mib"] = os.path.getsize(package) / 2**20
    captures = os.path.join(work, "captures")
    base = [args.game_exe, package, "--headless", "--frames", "1", "--size", args.size]
    own = os.path.join(captures, stem + "-onelight")
    code, out, _ = run(base + ["--capture", own], args)
    if code != 0:
        row["why"] = "draw: " + (reason(out, "failed") if code is not None else "timed out")
        return row
    try:
        capture = json.load(open(own + ".json"))
        row["frame_ms"] = capture["timings_ms"]["gpu"]
        ev100 = capture["camera"]["ev100"]
        mean = frame_radiance(own + ".json")
        row["luminance"] = luminance(mean)
        q3 = os.path.join(captures, stem + "-q3map2")
        code, out, _ = run(base + ["--view", "q3map2", "--ev100", f"{ev100:.4f}", "--capture", q3],
                           args)
        if code == 0:
            theirs = frame_radiance(q3 + ".json")
            if luminance(theirs) > 1e-6:
                row["lum_ratio"] = luminance(mean) / luminance(theirs)
                median = median_ratio(args, own + ".exr", q3 + ".exr")
                if median is not None:
                    row["median_ratio"] = median
            a, b = chromaticity(mean), chromaticity(theirs)
            if a and b:
                row["dxy"] = ((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) ** 0.5
        else:
            warnings.append("q3map2 view: " + reason(out, "failed"))
    except (OSError, ValueError, KeyError) as e:
        warnings.append(f"capture unread: {e}")
    row["status"] = "approximated" if warnings else "OK"
    row["why"] = "; ".join(w.split(": ", 1)[-1] if w.startswith(("/", spec)) else w
                           for w in warnings)
    return row


def compiled_map(row, compile_output, package, stem, args, work):
    """--no-bake: the compiled, unbaked package drawn from spawn 0 (the primaries alone: the
    q3map2 lightmaps come with the bake); reports the compile's warnings and the frame."""
    row["package_mib"] = os.path.getsize(package) / 2**20
    row["peak_mib"] = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    own = os.path.join(work, "captures", stem + "-compiled")
    code, out, _ = run([args.game_exe, package, "--headless", "--frames", "1", "--size",
                        args.size, "--capture", own], args)
    if code != 0:
        row["why"] = "draw: " + (reason(out, "failed") if code is not None else "timed out")
        return row
    capture = json.load(open(own + ".json"))
    row["frame_ms"] = capture["timings_ms"]["gpu"]
    notes = [l.split("warning: ", 1)[1] for l in compile_output.splitlines() if "warning: " in l]
    row["status"] = "approximated" if notes else "OK"
    if luminance(frame_radiance(own + ".json")) <= 1e-6:
        notes.append("unbaked, spawn 0 sees no primary light")
    row["why"] = "; ".join(notes)
    return row


def cell(row, key, fmt):
    return fmt.format(row[key]) if key in row else "–"


def table(game, rows, shadowed):
    lines = [f"## {game}", "",
             f"{len(rows)} maps" + (f" ({shadowed} older copies in earlier pk3s not run)"
                                   if shadowed else ""), "",
             "| map | pk3 | result | compile s | draft bake s | peak MiB | package MiB | "
             "frame ms | light from | lum. ratio | median block | Δxy | q3map2 -light | binaries "
             "| notes |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        why = r["why"].replace("|", "\\|").replace("\n", " ")
        if len(why) > 300:
            why = why[:297] + "..."
        lines.append("| " + " | ".join([
            r["map"], r["pk3"], r["status"], cell(r, "compile_s", "{:.1f}"),
            cell(r, "bake_s", "{:.1f}"), cell(r, "peak_mib", "{:.0f}"),
            cell(r, "package_mib", "{:.1f}"), cell(r, "frame_ms", "{:.1f}"),
            r.get("light_from", ""),
            cell(r, "lum_ratio", "{:.2f}"), cell(r, "median_ratio", "{:.2f}"),
            cell(r, "dxy", "{:.3f}"),
            r.get("q3map2", "").replace("|", "\\|"), r.get("commit", "–"), why]) + " |")
    return lines + [""]


def write_atomically(path, text):
    folder = os.path.dirname(os.path.abspath(path))
    fd, temporary = tempfile.mkstemp(prefix=".corpus-", dir=folder)
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        mask = os.umask(0)
        os.umask(mask)
        os.chmod(temporary, 0o666 & ~mask)  # as open() would make it, not mkstemp's 0600
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("out", help="the markdown file to write")
    p.add_argument("--games", default="openarena,nexuiz", help="comma-separated: " +
                   ", ".join(GAMES))
    p.add_argument("--maps", default="", help="only maps whose name matches this regex")
    p.add_argument("--limit", type=int, default=0, help="at most N maps per game (0: all)")
    p.add_argument("--bin", default=os.path.join(here, "..", "build", "bin"))
    p.add_argument("--work", default="", help="where packages and captures go (default: temp)")
    p.add_argument("--size", default="320x180", help="the frames' size")
    p.add_argument("--timeout", type=float, default=1800, help="seconds per step (of its "
                   "CPU time over the cores; a step that hangs: four times this, wall)")
    p.add_argument("--no-bake", action="store_true", help="compile and draw unbaked only: "
                   "every map checked in minutes, without the bake's columns")
    p.add_argument("--rows", default="", help="the rows file (default: WORK/rows.jsonl)")
    p.add_argument("--resume", action="store_true", help="keep the rows of maps an earlier run "
                   "finished (the rows file), run only the rest")
    args = p.parse_args()
    args.bake = os.path.join(args.bin, "onelight-bake")
    args.game_exe = os.path.join(args.bin, "onelight")
    # The lab measures the median block's ratio; a copy of the binaries may not hold it.
    args.lab = next((exe for exe in (os.path.join(args.bin, "onelight-lab"),
                                     os.path.join(here, "..", "build", "bin", "onelight-lab"))
                     if os.access(exe, os.X_OK)), None)
    for exe in (args.bake, args.game_exe):
        if not os.access(exe, os.X_OK):
            sys.exit(f"corpus: {exe}: missing; build onelight and onelight-bake first")
    if args.resume and not (args.work or args.rows):
        sys.exit("corpus: --resume needs --rows FILE or --work DIR, the earlier run's rows")
    commit_file = os.path.join(args.bin, "COMMIT")
    if os.path.exists(commit_file):
        args.commit = open(commit_file).read().strip()
    else:
        args.commit = subprocess.run(["git", "-C", here, "rev-parse", "--short", "HEAD"],
                                     capture_output=True, text=True).stdout.strip() or "?"

    work = args.work or tempfile.mkdtemp(prefix="onelight-corpus-")
    args.holds = os.path.join(work, "holds")  # scripts/hold's record (held_seconds)
    os.makedirs(os.path.join(work, "captures"), exist_ok=True)
    # Every finished row, one JSON object a line (the mode and map identify it): --resume
    # reuses them.
    done_path = args.rows or os.path.join(work, "rows.jsonl")
    done = {}
    if args.resume and os.path.exists(done_path):
        for line in open(done_path):
            try:
                r = json.loads(line)
                done[(r["mode"], r["map"], r["pk3"])] = r["row"]
            except (ValueError, KeyError):
                continue  # a line cut by an interrupted write
    mode = "no-bake" if args.no_bake else "draft"
    pattern = re.compile(args.maps) if args.maps else None
    sections, counts, started = [], {"OK": 0, "approximated": 0, "refused": 0}, time.monotonic()
    every = []  # every row so far, for the bound's summary
    for game_key in args.games.split(","):
        if game_key not in GAMES:
            sys.exit(f"corpus: --games {game_key}: expected one of {', '.join(GAMES)}")
        game, folder = GAMES[game_key]
        maps, shadowed = maps_of(folder)
        if pattern:
            maps = [m for m in maps if pattern.search(m[0])]
        if args.limit:
            maps = maps[:args.limit]
        rows = []
        for i, (name, pk3, inner) in enumerate(maps):
            key = (mode, name, os.path.basename(pk3))
            # Its files in WORK (two games may ship maps of one name).
            stem = game_key + "-" + re.sub(r"[^A-Za-z0-9_.-]", "_", name)
            if key in done:
                row = done[key]
                if "light_from" not in row and row["status"] != "refused":
                    # A row from before the column: the compile alone tells (seconds).
                    package = os.path.join(work, "light-from.olpak")
                    code, out, _ = run([args.bake, "compile", f"{pk3}:{inner}", "-o", package],
                                       args)
                    if code == 0:
                        row["light_from"] = light_from(out)
                        row["q3map2"] = q3map2_options(out)
                if "lum_ratio" in row and "median_ratio" not in row:
                    # A row from before the column: its captures in WORK tell (a second).
                    frames = os.path.join(work, "captures", stem)
                    median = median_ratio(args, frames + "-onelight.exr", frames + "-q3map2.exr")
                    if median is not None:
                        row["median_ratio"] = median
            else:
                try:
                    row = one_map(name, pk3, inner, args, work, stem)
                except Exception as e:  # a map must never stop the run
                    row = {"map": name, "pk3": os.path.basename(pk3), "status": "refused",
                           "why": f"corpus script: {e}"}
                row["commit"] = args.commit
                with open(done_path, "a") as f:
                    f.write(json.dumps({"mode": mode, "map": name, "pk3": key[2], "row": row})
                            + "\n")
            rows.append(row)
            every.append(row)
            counts[row["status"]] += 1
            write_report(args, counts, sections + table(game, rows, shadowed), started, every,
                         final=False)  # an interrupted run keeps what it measured
            print(f"corpus: {game} {i + 1}/{len(maps)} {name}: {row['status']}"
                  f" (compile {row.get('compile_s', 0):.1f} s, bake {row.get('bake_s', 0):.1f} s)"
                  + (f": {row['why'][:160]}" if row["why"] else ""), file=sys.stderr, flush=True)
        if maps or not os.path.isdir(folder):
            sections += table(game, rows, shadowed) if maps else [f"## {game}", "",
                                                                   f"{folder}: not installed", ""]
    write_report(args, counts, sections, started, every, final=True)


# The bound on the engine's own light against q3map2's (docs/corpus.md): the median 8x8 block's
# luminance within these times q3map2's view of the same spawn, and the mean colours' CIE xy
# within this distance.
BOUND_MEDIAN = (0.75, 1.45)
BOUND_DXY = 0.02


def bound_summary(rows):
    """One paragraph: how many of the maps the engine's own bake lights are within the bound,
    and which are not (q3map2's own lightmaps are 1 by construction)."""
    own = [r for r in rows if r.get("light_from", "q3map2's lightmaps") != "q3map2's lightmaps"
           and "median_ratio" in r and "dxy" in r]
    if not own:
        return []
    lo, hi = BOUND_MEDIAN
    outside = [r for r in own if not (lo <= r["median_ratio"] <= hi and r["dxy"] <= BOUND_DXY)]
    text = (f"Lit by the engine's own bake: {len(own)} maps; the median block within {lo} to "
            f"{hi} times q3map2's view and Δxy ≤ {BOUND_DXY} on {len(own) - len(outside)}")
    if outside:
        text += "; outside: " + ", ".join(
            f"{r['map']} ({r['median_ratio']:.2f}, Δxy {r['dxy']:.3f})" for r in outside)
    return [text + ".", ""]


def write_report(args, counts, sections, started, every, final):
    total = sum(counts.values())
    head = ["# Quake 3 map corpus", "",
            f"`{' '.join(sys.argv)}`, {time.strftime('%Y-%m-%d')}, "
            f"{time.monotonic() - started:.0f} s" + ("" if final else " (still running)"), "",
            f"**{total} maps: {counts['OK']} OK, {counts['approximated']} approximated, "
            f"{counts['refused']} refused.**", ""] + ([] if args.no_bake else bound_summary(every)) + [
            ("Columns (--no-bake): the compile's wall seconds; the largest child process's "
             "peak memory so far; the compiled package's size; the GPU time of one unbaked "
             f"frame from spawn 0 (headless, lavapipe, {args.size}). No bake, so no bake or "
             "luminance columns. Approximated: the import warned (notes)." if args.no_bake else
             "Columns: compile and draft-bake wall seconds; the bake report's peak memory; the "
             "package's size; the GPU time of one frame from spawn 0 (headless, lavapipe, "
             f"{args.size}); the frame's mean linear luminance (before exposure) over that of "
             "the q3map2 view of the same camera (1 by construction where the light is q3map2's "
             "own lightmaps), the same for the median 8x8 block (a typical surface: the lamps' "
             "own pixels, emission in ours and lightmapped texture in q3map2's, do not move it), "
             "and the distance of their mean colours' CIE "
             "xy chromaticities; what the map's recorded q3map2 -light stage did (bounces, dirt, "
             "scales, the lightmap encoding the q3map2 view decodes). Approximated: the import or "
             "bake warned (notes)."), ""]
    write_atomically(args.out, "\n".join(head + sections))
    if final:
        print(f"corpus: {total} maps: {counts['OK']} OK, {counts['approximated']} approximated, "
              f"{counts['refused']} refused; {args.out}", file=sys.stderr)

if __name__ == "__main__":
    main()
