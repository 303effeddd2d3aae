#!/usr/bin/env python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Speed of Marching Cubes on hexahedra (`isovdb reservoir`), in cells per second of its
`marching_cubes` stage (grid building and reading excluded), median of several runs:
on a synthetic corner-point grid (default 150 x 100 x 100 = 1.5 M cells: undulating,
dipping layers, a fault throw across the middle pillars, a porosity field with many
folds of its iso-surface) and on any GRDECL decks given with --deck (e.g. ResInsight's
Reek: TestModels/reek/reek_box_grid_w_props.grdecl, PORO 0.2). Target (#23): 10 M cells/s.
Two figures per grid: the stage as `isovdb reservoir` runs it (once per process, on fresh
memory), and the median of --repeats runs in one process (build/bench/isovdb-reservoir-mc,
where the stage's memory is warm: a small deck's milliseconds are below the noise of
whole runs).

Run on demand, never in CI:
    /usr/bin/python3 bench/reservoir_speed.py [--nx 150 --ny 100 --nz 100] [--runs 5]
                                              [--deck FILE... --property PORO --iso 0.2]
It builds nothing: run scripts/build.sh first (build/isovdb).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def write_values(out, keyword, values, fmt):
    out.write(f"{keyword}\n")
    text = np.char.mod(fmt, values.ravel())
    for start in range(0, text.size, 8):
        out.write(" ".join(text[start:start + 8]) + "\n")
    out.write("/\n\n")


def synthetic_deck(path, nx, ny, nz):
    """A corner-point grid of undulating, dipping layers with a fault and a PORO field."""
    dx, dy, dz = 50.0, 50.0, 2.0
    x = np.arange(nx + 1) * dx
    y = np.arange(ny + 1) * dy
    xx, yy = np.meshgrid(x, y)  # [j, i]
    top = 1500.0 + 0.02 * xx + 15.0 * np.sin(xx / 700.0) * np.cos(yy / 900.0)
    coord = np.stack([xx, yy, top - 50.0, xx, yy, top + nz * dz + 100.0], axis=-1)
    # ZCORN order: k, top/bottom, j, south/north, i, west/east.
    zc = np.empty((nz, 2, ny, 2, nx, 2))
    for dj in (0, 1):
        for di in (0, 1):
            surface = top[dj:dj + ny, di:di + nx]  # [j, i] node (i + di, j + dj)
            throw = np.where(np.arange(nx) >= nx // 2, 12.0, 0.0)[None, :]
            for dk in (0, 1):
                layers = (np.arange(nz) + dk)[:, None, None] * dz
                zc[:, dk, :, dj, :, di] = surface[None] + throw[None] + layers
    i, j, k = np.meshgrid(np.arange(nx), np.arange(ny), np.arange(nz), indexing="ij")
    cx, cy, cz = (i + 0.5) * dx, (j + 0.5) * dy, (k + 0.5) * dz
    poro = 0.2 + 0.08 * np.sin(cx / 400.0) * np.sin(cy / 350.0) + 0.06 * np.cos(cz / 9.0 + cx / 900.0)
    poro = np.transpose(poro, (2, 1, 0))  # i fastest
    with open(path, "w") as out:
        out.write(f"SPECGRID\n{nx} {ny} {nz} 1 F /\n\n")
        write_values(out, "COORD", coord, "%.2f")
        write_values(out, "ZCORN", zc, "%.3f")
        write_values(out, "PORO", poro, "%.4f")


def marching_cubes_rate(isovdb, deck_files, prop, iso, runs, work):
    seconds, cells = [], 0
    for run in range(runs):
        stats = os.path.join(work, "reservoir_stats.json")
        cmd = [isovdb, "reservoir", *deck_files, "--property", prop, "--iso", str(iso), "-o",
               os.path.join(work, "reservoir.ply"), "--stats", stats, "-q"]
        subprocess.run(cmd, check=True, capture_output=True)
        with open(stats) as f:
            s = json.load(f)
        seconds.append(s["timings_s"]["marching_cubes"])
        cells = s["reservoir"]["usable_cells"]
        triangles = s["reservoir"]["mc_triangles"]
    median = statistics.median(seconds)
    return cells, triangles, median, cells / median if median > 0 else float("inf")


def in_process_rate(tool, deck_files, prop, iso, repeats):
    out = subprocess.run([tool, *deck_files, "--property", prop, "--iso", str(iso), "--repeats", str(repeats)],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--nx", type=int, default=150)
    parser.add_argument("--ny", type=int, default=100)
    parser.add_argument("--nz", type=int, default=100)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--repeats", type=int, default=50, help="in-process runs (isovdb-reservoir-mc)")
    parser.add_argument("--deck", nargs="+", action="append", default=[], help="GRDECL deck (+ property files)")
    parser.add_argument("--property", default="PORO")
    parser.add_argument("--iso", type=float, default=0.2)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--work", default=tempfile.gettempdir())
    args = parser.parse_args()
    isovdb = os.path.join(args.build, "isovdb")
    if not os.access(isovdb, os.X_OK):
        sys.exit(f"reservoir_speed: no {isovdb}: run scripts/build.sh first")
    rows = []
    synthetic = os.path.join(args.work, f"synthetic_{args.nx}x{args.ny}x{args.nz}.grdecl")
    if not os.path.exists(synthetic):
        print(f"writing {synthetic} ...", flush=True)
        synthetic_deck(synthetic, args.nx, args.ny, args.nz)
    rows.append((f"synthetic {args.nx}x{args.ny}x{args.nz}", [synthetic], "PORO", 0.2))
    for files in args.deck:
        rows.append((os.path.basename(files[0]), files, args.property, args.iso))
    tool = os.path.join(args.build, "bench", "isovdb-reservoir-mc")
    print(f"{'grid':<36} {'cells':>10} {'triangles':>10} {'MC s (median)':>14} {'M cells/s':>10}"
          f" {'in-process s':>13} {'M cells/s':>10}")
    for name, files, prop, iso in rows:
        cells, triangles, median, rate = marching_cubes_rate(isovdb, files, prop, iso, args.runs, args.work)
        warm = in_process_rate(tool, files, prop, iso, args.repeats) if os.access(tool, os.X_OK) else None
        warm_cols = f" {warm['median_s']:>13.4f} {warm['m_cells_per_s']:>10.2f}" if warm else ""
        print(f"{name:<36} {cells:>10,} {triangles:>10,} {median:>14.4f} {rate / 1e6:>10.2f}{warm_cols}", flush=True)


if __name__ == "__main__":
    main()
