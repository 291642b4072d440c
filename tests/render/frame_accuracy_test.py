#!/usr/bin/env python3
"""FrameAccuracy: the real-time frame against the engine's path-traced reference on six of
scripts/accuracy.py's scenes, small and at draft quality so that it fits ctest (about 35 s on
2 cores). The rooms and the normal-mapped floor under its sky alone are held to issue 37's goal
of a 5% mean relative 8x8-block error, the flat floor, whose two sides share every term, to 1%;
the normal-mapped floor under its sun, not yet at the goal on the full-size table, to bounds its
frame failed before the whole tile's facets (docs/materials.md, "The whole tile's facets") and
passes with a margin for the reference's noise.

  frame_accuracy_test.py SOURCE_DIR BIN_DIR WORK_DIR

Bounds against measurements at these settings (192x108, 128 paths a pixel, draft bake;
2026-12-07): textured room 1.7% (its reference's own noise 1.1%), glossy room 3.7% (1.4%), the
flat floor 0.3% (0.2%); the normal-mapped floor under its sky and sun 4.9% (3.4%; 10.4% before
the whole tile's facets, 15.6% before the slopes' kurtosis, 29.5% before the footprint), under
its sun alone 8.7% (4.4%; 15.1%, 21.9% and 54.6%), under its sky alone 0.9% (0.4%; 1.9% before the kurtosis, 6.2% before the surface's
plane cut the texels' lobes, specularShareAboveSurface; 4.0% before the footprint, two errors
cancelling: docs/materials.md, "A footprint's bumps"; 18.5% before the frame and the reference
bent the same normals, normal_withValidReflection). A
failing scene names its sheet (reference | frame) and its heat map of block errors.
"""
import json
import os
import subprocess
import sys

BOUNDS = {"textured_room": 0.05, "glossy_room": 0.05, "flat_floor": 0.01, "normal_floor": 0.08,
          "normal_floor_sun": 0.12, "normal_floor_sky": 0.05}


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    source, binaries, work = sys.argv[1:]
    os.makedirs(work, exist_ok=True)
    rows_path = os.path.join(work, "rows.json")
    result = subprocess.run(
        [sys.executable, os.path.join(source, "scripts", "accuracy.py"),
         os.path.join(work, "accuracy.md"), "--bin", binaries, "--work", work,
         "--size", "192x108", "--spp", "128", "--quality", "draft",
         "--scenes", ",".join(BOUNDS), "--json", rows_path],
        capture_output=True, text=True)
    sys.stderr.write(result.stderr)
    if result.returncode != 0:
        sys.exit(f"FrameAccuracy: scripts/accuracy.py failed (exit {result.returncode})")
    with open(rows_path) as f:
        rows = {r["name"]: r for r in json.load(f)}
    failed = []
    for name, bound in BOUNDS.items():
        r = rows.get(name)
        if r is None:
            failed.append(f"{name}: no row")
            continue
        print(f"[ accuracy ] {name}: frame error {r['error'] * 100:.2f}% (bound "
              f"{bound * 100:.0f}%), level {r['level']:.3f}, reference noise "
              f"{r['noise'] * 100:.2f}%")
        if not r["error"] <= bound:
            failed.append(f"{name}: frame error {r['error'] * 100:.2f}% over {bound * 100:.0f}%; "
                          f"see {r['sheet']} and {r['heat_map']}")
    if failed:
        sys.exit("FrameAccuracy failed:\n  " + "\n  ".join(failed))


if __name__ == "__main__":
    main()
