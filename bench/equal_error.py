#!/usr/bin/env python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Triangles at equal error: adaptive mode's --max-error against OpenVDB's adaptivity.

For each input and each bound E (voxels), two rows:
- isovdb: `extract --method adaptive --max-error E`, its two-sided distance to
  regular mode's mesh of the same field (`--method regular`, the mesh the bound is
  stated against: on masks both modes read ambiguous cells as the voxel object);
- OpenVDB: the largest `--method vdb --adaptivity A` (A on a grid: 0.01 steps
  up to 0.1, then 0.1 steps) whose mesh stays within E of its own adaptivity-0
  mesh, the usual way to pick A when a distance is what one wants (A = 0 when
  no coarser one does).
The floor column is the distance between the two full-resolution meshes
(adaptive mode with 1-voxel leaves against regular mode's mesh): where
Ju-Udeshi fans replace regular mode's quads they differ by a few hundredths to
tenths of a voxel.
Distances are `isovdb compare`'s sampled two-sided Hausdorff distance (spacing
0.25 voxel); each mesh goes through `isovdb check` for self-intersections.
Both methods read the same distance field, so only the meshing differs.

Inputs: isovdb-sample's salt-dome, blobs and gyroid-slab at --size, and the
frog skeleton (label 13; its voxels are 1.5 units tall in z, so E is scaled by
1.5 there: mesh units).

Run on demand, never in CI (minutes):
    /usr/bin/python3 bench/equal_error.py [--build build] [--work DIR] [--size 128]
        [--bounds 1,0.5,0.25] [--adaptivities 0.01,0.02,...] [--inputs salt-dome,blobs,gyroid-slab,frog]
It builds nothing: run scripts/build.sh first.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FROG = os.path.join(ROOT, "data", "frog", "frogtissue.mhd")


def run(args):
    done = subprocess.run([str(a) for a in args], capture_output=True, text=True)
    if done.returncode not in (0, 1):  # compare and check exit 1 when a bound or a guarantee fails
        raise RuntimeError(" ".join(map(str, args)) + "\n" + done.stderr)
    return done


def figures(cli, command, work):
    """Runs an isovdb subcommand with --stats and returns its JSON figures."""
    path = os.path.join(work, "figures.json")
    run([cli, "--quiet", *command, "--stats", path])
    with open(path) as f:
        return json.load(f)


def mesh_figures(cli, mesh, work):
    m = figures(cli, ["check", mesh], work)["mesh"]
    return m["triangles"], m["self_intersecting_pairs"]


def distance(cli, a, b, work):
    return figures(cli, ["compare", a, b, "--spacing", "0.25"], work)["distance"]["hausdorff"]


def extract(cli, source, flags, out):
    run([cli, "--quiet", "extract", *source, "-o", out, *flags])
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--work", default=None)
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--bounds", default="1,0.5,0.25")
    parser.add_argument("--adaptivities", default=",".join(
        [f"{i / 100:g}" for i in range(1, 10)] + [f"{i / 10:g}" for i in range(1, 11)]))
    parser.add_argument("--inputs", default="salt-dome,blobs,gyroid-slab,frog")
    args = parser.parse_args()
    cli = os.path.join(args.build, "isovdb")
    sample = os.path.join(args.build, "data", "isovdb-sample")
    work = args.work or tempfile.mkdtemp(prefix="isovdb_equal_error_")
    os.makedirs(work, exist_ok=True)
    bounds = [float(b) for b in args.bounds.split(",")]
    adaptivities = [float(a) for a in args.adaptivities.split(",")]

    rows = []
    for name in args.inputs.split(","):
        if name == "frog":
            source, unit = [FROG, "--labels", "13"], 1.5
        else:
            path = os.path.join(work, f"{name}.nrrd")
            run([sample, name, "--size", args.size, "-o", path])
            source, unit = [path], 1.0
        mesh = lambda tag: os.path.join(work, f"{name}_{tag}.ply")  # noqa: E731
        regular = extract(cli, source, ["--method", "regular"], mesh("regular"))
        vdb0 = extract(cli, source, ["--method", "vdb", "--adaptivity", "0"], mesh("vdb0"))
        full = extract(cli, source, ["--method", "adaptive", "--max-cell-size", "1", "--max-error", "0"],
                       mesh("adaptive_full"))
        floor = distance(cli, regular, full, work) / unit
        # OpenVDB's distance to its adaptivity-0 mesh for every adaptivity on the grid, once.
        vdb = [(0.0, 0.0, *mesh_figures(cli, vdb0, work))]
        for a in adaptivities:
            out = extract(cli, source, ["--method", "vdb", "--adaptivity", a], mesh(f"vdb{a}"))
            vdb.append((a, distance(cli, vdb0, out, work), *mesh_figures(cli, out, work)))
        for e in bounds:
            ours = extract(cli, source, ["--method", "adaptive", "--max-error", e], mesh(f"adaptive{e}"))
            triangles, pairs = mesh_figures(cli, ours, work)
            d = distance(cli, regular, ours, work)
            within = [row for row in vdb if row[1] <= e * unit]
            best = max(within, key=lambda row: row[0])  # A = 0 is always within
            rows.append((name, e, triangles, d / unit, floor, pairs, best))
            print(f"{name} E={e}: ours {triangles} triangles, {d / unit:.3f} voxels (floor {floor:.3f}), {pairs} "
                  f"pairs; OpenVDB adaptivity {best[0]}, {best[2]} triangles, {best[1] / unit:.3f}, {best[3]} pairs",
                  file=sys.stderr)

    print(f"{'input':<12} {'E':>5} | {'ours: tris':>11} {'dist':>6} {'floor':>6} {'pairs':>6} | {'vdb: A':>7} "
          f"{'tris':>9} {'dist':>6} {'pairs':>6} | {'vdb / ours':>10}")
    for name, e, triangles, d, floor, pairs, (a, vd, vt, vp) in rows:
        unit = 1.5 if name == "frog" else 1.0
        print(f"{name:<12} {e:5.2f} | {triangles:11d} {d:6.3f} {floor:6.3f} {pairs:6d} | {a:7.2f} {vt:9d} "
              f"{vd / unit:6.3f} {vp:6d} | {vt / triangles:10.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
