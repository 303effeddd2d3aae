#!/usr/bin/env python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""isovdb.extract against scikit-image's measure.marching_cubes on numpy arrays, in one
Python process, as a notebook user would call them (#24): wall time (median of the runs,
the two interleaved run by run), triangles, and whether each mesh is closed and manifold
(isovdb's exact validator on both). Inputs at each size N: a ball mask (bool), a
surface-heavy mask of random overlapping balls (bool), and a smooth Gaussian field
(float32, level 0.5). Masks go to skimage as float at level 0.5 (its only way to mesh a
mask), to isovdb as they are (the distance field is then part of isovdb's time).

Run on demand, never in CI:
    /usr/bin/python3 bench/python_api.py [--sizes 128,256] [--runs 5] [--methods adaptive,regular]
It builds nothing: run `scripts/build.sh --target isovdb_python` first (build/python), and
`apt-get install python3-skimage`.
"""
import argparse
import os
import platform
import statistics
import sys
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def radius_grid(n, centre):
    z, y, x = np.ogrid[:n, :n, :n]
    return np.sqrt((x - centre[0]) ** 2 + (y - centre[1]) ** 2 + (z - centre[2]) ** 2)


def ball_mask(n):
    return radius_grid(n, (0.49 * n, 0.51 * n, 0.5 * n)) < 0.38 * n


def blobs_mask(n, seed=7):
    """Random overlapping balls, radii 2-8 % of N: many small bodies, much surface."""
    rng = np.random.default_rng(seed)
    mask = np.zeros((n, n, n), bool)
    for _ in range(max(40, n // 2)):
        c = rng.uniform(0.1 * n, 0.9 * n, 3)
        r = rng.uniform(0.02 * n, 0.08 * n)
        lo = np.maximum(np.floor(c - r).astype(int), 0)
        hi = np.minimum(np.ceil(c + r).astype(int) + 1, n)
        z, y, x = np.ogrid[lo[2]:hi[2], lo[1]:hi[1], lo[0]:hi[0]]
        mask[lo[2]:hi[2], lo[1]:hi[1], lo[0]:hi[0]] |= (x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - c[2]) ** 2 < r * r
    return mask


def gaussian_field(n):
    return np.exp(-(radius_grid(n, (0.49 * n, 0.51 * n, 0.5 * n)) / (0.3 * n)) ** 2).astype(np.float32)


def timed(call, runs_out):
    start = time.perf_counter()
    result = call()
    runs_out.append(time.perf_counter() - start)
    return result


def report_of(isovdb, vertices, faces):
    mesh = isovdb.Mesh(np.ascontiguousarray(vertices, np.float32), np.ascontiguousarray(faces, np.uint32))
    check = mesh.check(self_intersections=False)
    return mesh.triangle_count, check["closed"] and check["manifold"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="128,256")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--methods", default="adaptive,regular")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    args = parser.parse_args()
    sys.path.insert(0, os.path.join(args.build, "python"))
    try:
        import isovdb
        from skimage import __version__ as skimage_version
        from skimage.measure import marching_cubes
    except ImportError as error:
        sys.exit(f"python_api.py: {error} (build isovdb_python; apt-get install python3-skimage)")

    print(f"# {platform.node()}: {os.cpu_count()} cores, Python {platform.python_version()}, "
          f"numpy {np.__version__}, scikit-image {skimage_version}; median of {args.runs} interleaved runs")
    print("| input | N | peer | seconds | ratio to skimage | triangles | closed+manifold |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    methods = args.methods.split(",")
    for n in (int(s) for s in args.sizes.split(",")):
        inputs = (("ball mask", ball_mask(n), None), ("blobs mask", blobs_mask(n), None),
                  ("gaussian field", gaussian_field(n), 0.5))
        for name, array, level in inputs:
            # skimage takes (z, y, x) as (x, y, z)-agnostic axes; both get the same array.
            skimage_input = array.astype(np.float32) if array.dtype == bool else array
            skimage_level = 0.5 if level is None else level
            times = {"skimage": []}
            times.update({m: [] for m in methods})
            results = {}
            for _ in range(args.runs):
                verts, faces, _, _ = timed(lambda: marching_cubes(skimage_input, skimage_level), times["skimage"])
                results["skimage"] = (verts, faces)
                for method in methods:
                    kwargs = {"method": method}
                    if level is not None:
                        kwargs["iso"] = level
                    mesh = timed(lambda: isovdb.extract(array, **kwargs), times[method])
                    results[method] = (mesh.vertices, mesh.triangles)
            base = statistics.median(times["skimage"])
            for peer in ["skimage"] + methods:
                seconds = statistics.median(times[peer])
                triangles, closed = report_of(isovdb, *results[peer])
                label = peer if peer == "skimage" else f"isovdb {peer}"
                print(f"| {name} | {n} | {label} | {seconds:.3f} | {seconds / base:.2f} | {triangles} | "
                      f"{'yes' if closed else 'no'} |", flush=True)


if __name__ == "__main__":
    main()
