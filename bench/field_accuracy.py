#!/usr/bin/env python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Accuracy of the mask -> distance field -> mesh path on voxelised analytic solids.

Spheres and tori of several radii, each centred at a random sub-voxel offset
(seeded), are voxelised (a voxel is inside iff its centre is), written as uint8
NRRD files and meshed end to end with `isovdb extract` (regular and adaptive
modes, and any --distance choice given). Each mesh vertex's distance to the
analytic surface is measured; the table shows the mean and the maximum per
solid, and the mean over all solids per method.

Run on demand, never in CI (a minute or two):
    /usr/bin/python3 bench/field_accuracy.py [--build build] [--work DIR]
        [--radii 8,12,20,40,60] [--trials 2] [--distance exact,tracker]
It builds nothing: run scripts/build.sh first.
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ply_vertices import read_ply_vertices  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def write_nrrd(path, mask):
    """mask[z, y, x] (bool) -> attached-header uint8 NRRD, x fastest."""
    nz, ny, nx = mask.shape
    header = (f"NRRD0004\ntype: uint8\ndimension: 3\nsizes: {nx} {ny} {nz}\n"
              "spacings: 1 1 1\nencoding: raw\n\n")
    with open(path, "wb") as f:
        f.write(header.encode())
        f.write(np.ascontiguousarray(mask, np.uint8).tobytes())


class Sphere:
    def __init__(self, radius, centre):
        self.radius, self.centre = radius, centre

    def name(self):
        return f"sphere r={self.radius:g}"

    def extent(self):
        return self.radius

    def distance(self, p):
        return np.linalg.norm(p - self.centre, axis=-1) - self.radius


class Torus:
    """Axis z; major radius 2.5 x the minor one."""

    def __init__(self, radius, centre):
        self.minor, self.major, self.centre = radius, 2.5 * radius, centre

    def name(self):
        return f"torus r={self.minor:g}"

    def extent(self):
        return self.major + self.minor

    def distance(self, p):
        q = p - self.centre
        ring = np.hypot(q[..., 0], q[..., 1]) - self.major
        return np.hypot(ring, q[..., 2]) - self.minor


def voxelise(solid, margin=6):
    """The solid sampled at voxel centres (index space, voxel (i, j, k) at point (i, j, k))."""
    n = int(np.ceil(2 * solid.extent() + 2 * margin + 2))
    z, y, x = np.meshgrid(*(np.arange(n, dtype=np.float64),) * 3, indexing="ij")
    return solid.distance(np.stack([x, y, z], axis=-1)) < 0


def run(cli, mask_path, out_path, method, extra):
    args = [cli, "--quiet", "extract", mask_path, "-o", out_path, "--method", method, *extra]
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(" ".join(args) + "\n" + done.stderr)
    return read_ply_vertices(out_path)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--work", default=None)
    parser.add_argument("--radii", default="8,12,20,40,60")
    parser.add_argument("--trials", type=int, default=2, help="random sub-voxel centres per solid and radius")
    parser.add_argument("--distance", default="",
                        help="comma-separated --distance values to compare (default: the CLI's default only)")
    parser.add_argument("--methods", default="regular,adaptive")
    parser.add_argument("--extra", default="", help="more extract flags, space-separated (e.g. '--qef-tolerance 0.1')")
    parser.add_argument("--seed", type=int, default=19)
    args = parser.parse_args()
    cli = os.path.join(args.build, "isovdb")
    work = args.work or tempfile.mkdtemp(prefix="isovdb_accuracy_")
    os.makedirs(work, exist_ok=True)
    rng = np.random.default_rng(args.seed)
    variants = [(d, ["--distance", d]) for d in args.distance.split(",") if d] or [("default", [])]
    variants = [(name, flags + args.extra.split()) for name, flags in variants]
    methods = args.methods.split(",")

    rows, totals = [], {}
    for radius in [float(r) for r in args.radii.split(",")]:
        for kind in (Sphere, Torus):
            if kind is Torus and 2.5 * radius + radius > 90:
                continue  # keeps the volumes under ~200^3
            for trial in range(args.trials):
                probe = kind(radius, np.zeros(3))
                offset = probe.extent() + 7 + rng.uniform(0, 1, 3)
                solid = kind(radius, offset)
                mask = voxelise(solid)
                path = os.path.join(work, f"solid_{len(rows)}.nrrd")
                write_nrrd(path, mask)
                for variant, extra in variants:
                    for method in methods:
                        verts = run(cli, path, os.path.join(work, "mesh.ply"), method, extra)
                        d = np.abs(solid.distance(verts.astype(np.float64)))
                        key = (variant, method)
                        rows.append((solid.name(), trial, variant, method, len(verts), d.mean(), d.max()))
                        totals.setdefault(key, []).append((d.mean(), d.max(), len(verts)))

    print(f"{'solid':<16} {'trial':>5} {'distance':<10} {'method':<9} {'vertices':>9} {'mean':>7} {'max':>7}")
    for name, trial, variant, method, count, mean, worst in rows:
        print(f"{name:<16} {trial:>5} {variant:<10} {method:<9} {count:>9} {mean:7.4f} {worst:7.4f}")
    print()
    print(f"{'distance':<10} {'method':<9} {'mean of means':>14} {'worst mean':>11} {'worst max':>10} {'mean max':>9} {'vertices':>9}")
    for (variant, method), values in totals.items():
        means = [m for m, _, _ in values]
        print(f"{variant:<10} {method:<9} {np.mean(means):14.4f} {max(means):11.4f} {max(w for _, w, _ in values):10.4f}"
              f" {np.mean([w for _, w, _ in values]):9.4f} {sum(v for _, _, v in values):9d}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
