#!/usr/bin/env python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Every guarantee at once (#22), swept over many small random inputs in both octree
modes: how many meshes are closed, manifold (no non-manifold edge or vertex),
consistently oriented and free of self-intersections (isovdb's exact validator), and
how many have the object's topology:
- masks: random voxel sets, uncorrelated (each voxel inside with probability p) and
  blobby (a smoothed noise thresholded at density p), at 4 densities, with seams
  (--meta-cell 16) and without (one block): chi(mesh) against 2 chi(26, 6) of the mask;
- fields: seeded sums of Gaussian bumps and a weak wave (the property test's kind,
  tests/pipeline/random_field_guarantees_test.cc) at two isovalues: chi of each mode
  against the other's (a field has no voxel object to compare with).
Prints one row per (input kind, density, seams, mode): meshes, and the failures per
guarantee. The CI property test covers the fields; this sweep is the longer run, and
the masks, whose guarantees do not all hold yet (ARCHITECTURE.md).
Run on demand, never in CI:
    /usr/bin/python3 bench/guarantee_sweep.py [--seeds 50] [--size 24] [--densities 0.1,0.3,0.5,0.7]
It builds nothing: run `scripts/build.sh --target isovdb_python` first (build/python).
"""
import argparse
import os
import sys
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GUARANTEES = ("closed", "manifold", "oriented", "intersection-free", "topology")


def random_mask(rng, n, density, blobby):
    """A bool array of about `density` inside; blobby: smoothed noise, so bodies of a few voxels."""
    noise = rng.random((n, n, n))
    if blobby:
        for axis in range(3):  # a box filter of 3 along each axis, twice
            for _ in range(2):
                noise = (np.roll(noise, 1, axis) + noise + np.roll(noise, -1, axis)) / 3.0
    return noise < np.quantile(noise, density)


def random_field(rng, n):
    x, y, z = np.mgrid[0:n, 0:n, 0:n].astype(np.float64)
    values = 0.1 * rng.random() * np.sin(0.5 * x) * np.cos(0.4 * y + 0.3 * z)
    for _ in range(3 + int(rng.integers(0, 5))):
        c, width = rng.uniform(0, n, 3), rng.uniform(2.0, 8.0)
        height = (1.0 if rng.random() < 0.8 else -0.6) * rng.uniform(0.5, 1.5)
        values += height * np.exp(-((x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - c[2]) ** 2) / (2.0 * width ** 2))
    return values.astype(np.float32)


def failures(report):
    """The guarantees (but topology) this mesh's report breaks."""
    broken = set()
    if not report["closed"]:
        broken.add("closed")
    if report["non_manifold_edges"] or report["non_manifold_vertices"]:
        broken.add("manifold")
    if report["inconsistently_oriented_edges"]:
        broken.add("oriented")
    if report["self_intersecting_pairs"]:
        broken.add("intersection-free")
    return broken


class Table:
    def __init__(self):
        self.rows = {}

    def add(self, key, broken):
        meshes, counts = self.rows.setdefault(key, [0, {g: 0 for g in GUARANTEES}])
        self.rows[key][0] = meshes + 1
        for g in broken:
            counts[g] += 1

    def print(self):
        header = f"{'input':<26} {'seams':<6} {'mode':<9} {'meshes':>6}  " + "  ".join(f"{g:>17}" for g in GUARANTEES)
        print(header)
        for (name, seams, mode), (meshes, counts) in self.rows.items():
            print(f"{name:<26} {seams:<6} {mode:<9} {meshes:>6}  " + "  ".join(f"{counts[g]:>17}" for g in GUARANTEES))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=50, help="random inputs per row")
    parser.add_argument("--size", type=int, default=24, help="edge of each volume in voxels")
    parser.add_argument("--densities", default="0.1,0.3,0.5,0.7")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    args = parser.parse_args()
    sys.path.insert(0, os.path.join(args.build, "python"))
    try:
        import isovdb
    except ImportError as error:
        sys.exit(f"guarantee_sweep.py: {error} (build isovdb_python first)")
    densities = [float(d) for d in args.densities.split(",")]
    table = Table()
    start = time.perf_counter()
    for blobby in (False, True):
        for density in densities:
            name = f"{'blobby' if blobby else 'voxel noise'} mask p={density}"
            for seed in range(args.seeds):
                rng = np.random.default_rng(seed)
                mask = isovdb.from_numpy(random_mask(rng, args.size, density, blobby))
                solid = isovdb.euler_characteristic(mask, adjacency=26)
                for seams, meta_cell in (("yes", 16), ("no", 0)):
                    for mode in ("regular", "adaptive"):
                        report = isovdb.extract(mask, method=mode, meta_cell=meta_cell).check()
                        broken = failures(report)
                        if report["euler_characteristic"] != 2 * solid:
                            broken.add("topology")
                        table.add((name, seams, mode), broken)
    for seed in range(args.seeds):
        field = isovdb.from_numpy(random_field(np.random.default_rng(1000 + seed), args.size))
        for iso in (0.3, 0.55):
            for seams, meta_cell in (("yes", 16), ("no", 0)):
                reports = {mode: isovdb.extract(field, method=mode, iso=iso, meta_cell=meta_cell).check()
                           for mode in ("regular", "adaptive")}
                for mode, report in reports.items():
                    broken = failures(report)
                    other = reports["adaptive" if mode == "regular" else "regular"]
                    if report["euler_characteristic"] != other["euler_characteristic"]:
                        broken.add("topology")
                    table.add(("smooth field", seams, mode), broken)
    table.print()
    print(f"{time.perf_counter() - start:.1f} s; size {args.size}^3, {args.seeds} seeds per row; "
          "topology: masks 2 chi(26, 6) of the mask, fields the other mode's chi")


if __name__ == "__main__":
    main()
