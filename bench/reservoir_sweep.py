#!/usr/bin/env python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Reservoir meshes over many iso-values of real decks (#23): `isovdb reservoir --check` on
each, totalled per deck: self-intersecting pairs (away from pinched and inverted cells, at
pinched cells, at inverted cells), meshes that are not manifold, degenerate triangles,
triangles. The default sweep: Reek PORO 0.10, 0.11, ..., 0.30 and Emerald PORO 0.1-0.3 and
FACIES 0.5 (from ../shared/data), regular27cell PORO 0.45 and ResInsight's Reek box PORO
0.1-0.3 (bundled). --grids adds other GRDECL files: a deck without PORO is given a smooth
one (0.2 + 0.1 sin(k/2.3 + i/7.1 + j/5.3) per cell, I, J, K from 0) and contoured at five
iso-values (e.g. xtgeo-testdata's 3dgrids/reek3/reek_sim.grdecl, ResInsight's
ApplicationLibCode/UnitTests/TestData/RifEclipseTextFileParser/GRID.GRDECL).

Run on demand, never in CI:
    /usr/bin/python3 bench/reservoir_sweep.py [--isovdb build/isovdb] [--grids FILE...]
It builds nothing: run scripts/build.sh first.
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def smooth_poro(deck, out_path):
    """A PORO keyword for a deck that has none, sized by its SPECGRID (or DIMENS)."""
    with open(deck, errors="replace") as f:
        text = f.read()
    if re.search(r"^\s*PORO\b", text, re.M):
        return None
    dims = re.search(r"^\s*(?:SPECGRID|DIMENS)\s+(\d+)\s+(\d+)\s+(\d+)", text, re.M)
    if not dims:
        return None
    nx, ny, nz = map(int, dims.groups())
    with open(out_path, "w") as out:
        out.write("PORO\n")
        for k in range(nz):
            for j in range(ny):
                for i in range(nx):
                    out.write("%.5f\n" % (0.2 + 0.1 * math.sin(k / 2.3 + i / 7.1 + j / 5.3)))
        out.write("/\n")
    return out_path


def run(isovdb, files, prop, iso, work):
    stats = os.path.join(work, "stats.json")
    subprocess.run([isovdb, "-q", "reservoir", *files, "--property", prop, "--iso", str(iso),
                    "-o", os.path.join(work, "mesh.ply"), "--check", "--stats", stats],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    with open(stats) as f:
        figures = json.load(f)
    pairs = figures["reservoir"]["self_intersecting_pairs"]
    check = figures["check"]
    return {"elsewhere": pairs["elsewhere"], "pinched": pairs["at_pinched_cells"],
            "inverted": pairs["at_inverted_cells"],
            "non_manifold": int(check["non_manifold_edges"] + check["non_manifold_vertices"] > 0),
            "degenerate": check["degenerate_triangles"], "triangles": check["triangles"]}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--isovdb", default=os.path.join(ROOT, "build", "isovdb"))
    parser.add_argument("--shared", default=os.path.join(ROOT, "..", "shared", "data"))
    parser.add_argument("--grids", nargs="*", default=[], help="more GRDECL files (a smooth PORO where none)")
    args = parser.parse_args()
    reek = os.path.join(args.shared, "reservoir", "reek")
    emerald = os.path.join(args.shared, "reservoir", "emerald", "eme_small_w_hole_grid_params.grdecl")
    sweeps = [
        ("Reek", [os.path.join(reek, "reek_sim_grid.grdecl"), os.path.join(reek, "reek_sim_poro.grdecl")], "PORO",
         [round(0.10 + 0.01 * n, 2) for n in range(21)]),
        ("Emerald PORO", [emerald], "PORO", [0.1, 0.15, 0.2, 0.25, 0.3]),
        ("Emerald FACIES", [emerald], "FACIES", [0.5]),
        ("regular27cell", [os.path.join(ROOT, "data", "reservoir", "fault_test", "regular27cell.grdecl")], "PORO",
         [0.45]),
        ("ResInsight Reek box",
         [os.path.join(ROOT, "data", "reservoir", "reek_box", "reek_box_grid_w_props.grdecl")], "PORO",
         [0.1, 0.12, 0.15, 0.18, 0.2, 0.22, 0.25, 0.28, 0.3]),
    ]
    with tempfile.TemporaryDirectory() as work:
        for n, grid in enumerate(args.grids):
            poro = smooth_poro(grid, os.path.join(work, "poro%d.inc" % n))
            sweeps.append((os.path.basename(grid) + (" (smooth PORO)" if poro else ""),
                           [grid] + ([poro] if poro else []), "PORO", [0.12, 0.15, 0.2, 0.25, 0.28]))
        keys = ["elsewhere", "pinched", "inverted", "non_manifold", "degenerate", "triangles"]
        total = dict.fromkeys(keys, 0)
        print("| deck | meshes | pairs elsewhere | at pinched cells | at inverted cells | non-manifold meshes"
              " | degenerate | triangles |")
        print("| --- | --- | --- | --- | --- | --- | --- | --- |")
        meshes = 0
        for name, files, prop, isos in sweeps:
            if not all(os.path.exists(f) for f in files):
                print("| %s | skipped: no %s |" % (name, next(f for f in files if not os.path.exists(f))))
                continue
            row = dict.fromkeys(keys, 0)
            for iso in isos:
                for key, value in run(args.isovdb, files, prop, iso, work).items():
                    row[key] += value
            meshes += len(isos)
            for key in keys:
                total[key] += row[key]
            print("| %s | %d | %s |" % (name, len(isos), " | ".join("{:,}".format(row[k]) for k in keys)))
        print("| all | %d | %s |" % (meshes, " | ".join("{:,}".format(total[k]) for k in keys)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
