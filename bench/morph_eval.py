#!/usr/bin/python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Evaluation of `isovdb morph` (issue #8, paper 002), on demand.

1. Ground truth: an analytic torus tilted 30 degrees and a twisted rounded box,
   labelled every 8th z-slice, reconstructed and compared with the full solid
   between the first and the last labelled slice: volume error (voxel counts of
   the completed stack) and mean surface distance (symmetric: reconstructed mesh
   vertices -> analytic distance; analytic surface points -> reconstructed .vdb).
   Level set (arrival and iterations progress), particle level set, plain
   stacking (nearest slice) and shape-based interpolation (linear) side by side.
2. Corner sharpness: a pyramid of rectangles 8 apart; every intermediate slice of
   a morph between rectangles should stay close to a rectangle: area / bounding-box
   area (1 = sharp corners).
3. Real data: the CT head (headsq, bone > 1150, skin > 500) and the frog
   skeleton (label 13), every 4th z-slice kept; Dice of each withheld slice.
4. Speed: seconds per morph iteration (paper 002's "intermediate slice": one
   per iteration) and per output plane, against the paper's 1.2-2.4 s (level set)
   and 20-51 s (particle level set) in MATLAB.

Usage: bench/morph_eval.py [--build build] [--work /tmp/morph_eval] [--skip-frog-pls]
"""
import argparse
import json
import os
import struct
import subprocess
import sys
import time
import zlib
from pathlib import Path

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ply_vertices import read_ply_vertices  # noqa: E402
import pyopenvdb as vdb

ROOT = Path(__file__).resolve().parent.parent
SHARED = ROOT.parent / "shared" / "data"

METHODS = {
    "levelset": [],  # default progress: exponential time of arrival
    "levelset-arrival": ["--progress", "arrival"],
    "levelset-iterations": ["--progress", "iterations"],
    "pls": ["--pls"],
    "levelset-nocentring": ["--no-centring"],
    "levelset-noareamatch": ["--no-area-match"],
    "nearest": ["--interpolate", "nearest"],
    "linear": ["--interpolate", "linear"],
}


# ---------------------------------------------------------------- files
def read_png(path):
    """8-bit grey PNG (as isovdb writes them) -> bool array (rows = y)."""
    data = Path(path).read_bytes()
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", chunk[:10])
            assert depth == 8 and colour == 0, "expected 8-bit grey"
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + length
    raw = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(height, width + 1)
    out = np.zeros((height, width), np.int32)
    prev = np.zeros(width, np.int32)
    for y in range(height):
        f, row = raw[y, 0], raw[y, 1:].astype(np.int32)
        if f == 0:
            cur = row
        elif f == 2:
            cur = (row + prev) & 255
        else:
            cur = np.zeros(width, np.int32)
            for x in range(width):
                a = cur[x - 1] if x else 0
                b = prev[x]
                c = prev[x - 1] if x else 0
                if f == 1:
                    p = a
                elif f == 3:
                    p = (a + b) >> 1
                else:
                    pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                    p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                cur[x] = (row[x] + p) & 255
        out[y] = cur
        prev = cur
    return out > 127


def write_raw(path, mask):
    """mask[z, y, x] -> uint8 raw file (x fastest)."""
    np.ascontiguousarray(mask, np.uint8).tofile(path)


# ---------------------------------------------------------------- runs
def run_morph(cli, source, out_dir, extra):
    out_dir.mkdir(parents=True, exist_ok=True)
    args = [cli, "--quiet", "morph", *source, "-o", str(out_dir / "mesh.ply"), "--save-slices",
            str(out_dir / "planes"), "--stats", str(out_dir / "stats.json"), "--vdb", str(out_dir / "sdf.vdb"), *extra]
    start = time.time()
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(" ".join(args) + "\n" + done.stderr)
    stats = json.loads((out_dir / "stats.json").read_text())
    stats["wall_s"] = time.time() - start
    heights = [float(h) for h in (out_dir / "planes" / "heights.txt").read_text().split()]
    planes = np.stack([read_png(out_dir / "planes" / f"plane_{k:04d}.png") for k in range(len(heights))])
    return stats, planes


def dice(a, b):
    total = a.sum() + b.sum()
    return 1.0 if total == 0 else 2.0 * np.logical_and(a, b).sum() / total


def sample_sdf(grid, points):
    """Trilinear value of a .vdb level set at world points (N x 3), in voxels."""
    acc = grid.getConstAccessor()
    out = np.empty(len(points))
    scale = grid.transform.voxelSize()[0]
    for i, point in enumerate(points):
        x, y, z = grid.transform.worldToIndex(tuple(float(c) for c in point))
        x0, y0, z0 = int(np.floor(x)), int(np.floor(y)), int(np.floor(z))
        fx, fy, fz = x - x0, y - y0, z - z0
        v = 0.0
        for dz in (0, 1):
            for dy in (0, 1):
                for dx in (0, 1):
                    w = (fx if dx else 1 - fx) * (fy if dy else 1 - fy) * (fz if dz else 1 - fz)
                    v += w * acc.getValue((x0 + dx, y0 + dy, z0 + dz))
        out[i] = v / scale
    return out


# ---------------------------------------------------------------- ground truth
def torus_sdf(x, y, z, centre, big=30.0, small=12.0, tilt=np.radians(30)):
    px, py, pz = x - centre[0], y - centre[1], z - centre[2]
    ry = py * np.cos(tilt) + pz * np.sin(tilt)
    rz = -py * np.sin(tilt) + pz * np.cos(tilt)
    return np.hypot(np.hypot(px, ry) - big, rz) - small


def twisted_box_sdf(x, y, z, centre, half=(30.0, 16.0, 32.0), radius=5.0, twist=np.radians(60)):
    px, py, pz = x - centre[0], y - centre[1], z - centre[2]
    angle = twist * pz / (2 * half[2])
    rx = px * np.cos(angle) + py * np.sin(angle)
    ry = -px * np.sin(angle) + py * np.cos(angle)
    q = [np.abs(rx) - (half[0] - radius), np.abs(ry) - (half[1] - radius), np.abs(pz) - (half[2] - radius)]
    outside = np.sqrt(sum(np.maximum(c, 0) ** 2 for c in q))
    inside = np.minimum(np.maximum(np.maximum(q[0], q[1]), q[2]), 0)
    return outside + inside - radius


def surface_points(sdf, mask, centre):
    """Boundary voxels of `mask` projected onto the zero set of `sdf` (two Newton steps)."""
    edge = mask & ~(np.roll(mask, 1, 0) & np.roll(mask, -1, 0) & np.roll(mask, 1, 1) & np.roll(mask, -1, 1)
                    & np.roll(mask, 1, 2) & np.roll(mask, -1, 2))
    z, y, x = np.nonzero(edge)
    p = np.stack([x, y, z], 1).astype(float)
    h = 1e-3
    for _ in range(2):
        f = sdf(p[:, 0], p[:, 1], p[:, 2], centre)
        g = np.stack([(sdf(p[:, 0] + h, p[:, 1], p[:, 2], centre) - f) / h,
                      (sdf(p[:, 0], p[:, 1] + h, p[:, 2], centre) - f) / h,
                      (sdf(p[:, 0], p[:, 1], p[:, 2] + h, centre) - f) / h], 1)
        g /= np.maximum(np.linalg.norm(g, axis=1, keepdims=True), 1e-9)
        p -= f[:, None] * g
    return p


def ground_truth(cli, work, step=8):
    shapes = {"tilted torus": (torus_sdf, (100, 100, 72)), "twisted box": (twisted_box_sdf, (88, 88, 76))}
    rows = []
    for name, (sdf, (nx, ny, nz)) in shapes.items():
        centre = ((nx - 1) / 2, (ny - 1) / 2, (nz - 1) / 2)
        z, y, x = np.mgrid[0:nz, 0:ny, 0:nx].astype(float)
        mask = sdf(x, y, z, centre) <= 0
        filled = np.nonzero(mask.any(axis=(1, 2)))[0]
        z0 = int(filled[0])
        z1 = z0 + (int(filled[-1]) - z0) // step * step
        raw = work / f"{name.replace(' ', '_')}.raw"
        write_raw(raw, mask)
        truth = mask[z0:z1 + 1]
        points = surface_points(sdf, mask, centre)
        points = points[(points[:, 2] >= z0) & (points[:, 2] <= z1)]
        for method, extra in METHODS.items():
            out = work / f"gt_{name.replace(' ', '_')}_{method}"
            stats, planes = run_morph(cli, [str(raw), "--dims", f"{nx},{ny},{nz}", "--type", "uint8",
                                            "--slice-step", str(step), "--slice-offset", str(z0)], out, extra)
            planes = planes[:len(truth)]  # a last, empty labelled slice may follow z1
            volume_error = abs(int(planes.sum()) - int(truth.sum())) / truth.sum()
            verts = read_ply_vertices(out / "mesh.ply")
            verts = verts[(verts[:, 2] >= z0) & (verts[:, 2] <= z1)]
            to_truth = np.abs(sdf(verts[:, 0], verts[:, 1], verts[:, 2], centre)).mean()
            grid = vdb.read(str(out / "sdf.vdb"), "sdf")
            to_rec = np.abs(sample_sdf(grid, points)).mean()
            rows.append({"shape": name, "method": method, "volume_error_pct": 100 * volume_error,
                         "mean_surface_distance_vox": (to_truth + to_rec) / 2,
                         "rec_to_truth": to_truth, "truth_to_rec": to_rec,
                         "iterations": stats["morph"]["iterations_total"],
                         "progress_error": stats["morph"]["progress_error_mean"],
                         "wall_s": stats["wall_s"]})
            print(f"  {name:13s} {method:20s} volume error {100 * volume_error:5.2f} %  "
                  f"mean surface distance {(to_truth + to_rec) / 2:.3f} vox ({to_truth:.3f} / {to_rec:.3f})  "
                  f"progress error {stats['morph']['progress_error_mean']:.3f}", flush=True)
    return rows


def corner_sharpness(cli, work):
    nx, ny = 100, 70  # paper 002's pyramid slices are 70 x 100
    rects = [(8, 6, 91, 63), (20, 14, 79, 55), (32, 22, 67, 47), (44, 28, 55, 41)]
    nz = 8 * (len(rects) - 1) + 1
    mask = np.zeros((nz, ny, nx), bool)
    for k, (x0, y0, x1, y1) in enumerate(rects):
        mask[8 * k, y0:y1 + 1, x0:x1 + 1] = True
    raw = work / "pyramid.raw"
    write_raw(raw, mask)
    rows = []
    for method, extra in METHODS.items():
        stats, planes = run_morph(cli, [str(raw), "--dims", f"{nx},{ny},{nz}", "--type", "uint8",
                                        "--slice-step", "8"], work / f"pyramid_{method}", extra)
        ratios = []
        for z in range(nz):
            if z % 8 == 0 or not planes[z].any():
                continue
            ys, xs = np.nonzero(planes[z])
            ratios.append(planes[z].sum() / ((xs.max() - xs.min() + 1) * (ys.max() - ys.min() + 1)))
        rows.append({"method": method, "area_over_bbox": float(np.mean(ratios)), "min": float(np.min(ratios)),
                     "seconds_per_iteration": stats["morph"]["seconds_per_iteration"],
                     "seconds_per_plane": stats["morph"]["seconds_per_intermediate_slice"],
                     "iterations": stats["morph"]["iterations_total"]})
        print(f"  pyramid 100x70 {method:20s} corner sharpness (area / bbox area) mean {np.mean(ratios):.4f} "
              f"min {np.min(ratios):.4f}  {stats['morph']['seconds_per_iteration'] * 1e3:.3f} ms/iteration",
              flush=True)
    return rows


# ---------------------------------------------------------------- real data
def withheld_dice(cli, work, name, source, truth, step, methods):
    rows = []
    last = (truth.shape[0] - 1) // step * step
    withheld = [z for z in range(last + 1) if z % step and (truth[z].any())]
    for method in methods:
        stats, planes = run_morph(cli, source + ["--slice-step", str(step)], work / f"{name}_{method}",
                                  METHODS[method])
        # Labelled slices are z = 0, step, 2 step, ...: plane k is z = k.
        scores = []
        for z in withheld:
            rec = planes[z] if z < len(planes) else np.zeros_like(truth[z])
            scores.append(dice(rec, truth[z]))
        scores = np.array(scores)
        rows.append({"data": name, "method": method, "dice_mean": float(scores.mean()),
                     "dice_min": float(scores.min()), "dice_median": float(np.median(scores)),
                     "withheld": len(withheld), "scores": scores.tolist(),
                     "iterations": stats["morph"]["iterations_total"],
                     "intermediate": stats["morph"]["intermediate_slices"],
                     "seconds_morph": stats["timings_s"]["morph"],
                     "seconds_per_iteration": stats["morph"]["seconds_per_iteration"],
                     "seconds_per_plane": stats["morph"]["seconds_per_intermediate_slice"],
                     "wall_s": stats["wall_s"]})
        print(f"  {name:10s} {method:20s} Dice mean {scores.mean():.4f} median {np.median(scores):.4f} "
              f"min {scores.min():.4f} over {len(withheld)} withheld slices; morph {stats['timings_s']['morph']:.2f} s, "
              f"{stats['morph']['seconds_per_iteration'] * 1e3:.3f} ms/iteration, "
              f"{stats['morph']['seconds_per_intermediate_slice'] * 1e3:.1f} ms/plane", flush=True)
    return rows


def real_data(cli, work, skip_frog_pls):
    rows = []
    head = np.stack([np.fromfile(SHARED / "slices" / "headsq_ct" / f"quarter.{k}", "<u2").reshape(64, 64)
                     for k in range(1, 94)])
    raw = work / "headsq.raw"
    head.tofile(raw)
    for tissue, threshold in (("bone", 1150), ("skin", 500)):
        rows += withheld_dice(cli, work, f"head-{tissue}",
                              [str(raw), "--dims", "64,64,93", "--type", "uint16", "--threshold", str(threshold)],
                              head > threshold, 4, list(METHODS))
    mhd = SHARED / "binary" / "frog_tissue" / "frogtissue.mhd"
    frog = np.frombuffer(zlib.decompress((mhd.parent / "frogtissue.zraw").read_bytes()), np.uint8)
    frog = frog.reshape(136, 470, 500) == 13
    methods = [m for m in METHODS if not (skip_frog_pls and m == "pls")]
    rows += withheld_dice(cli, work, "frog", [str(mhd), "--labels", "13"], frog, 4, methods)
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--work", default="/tmp/morph_eval")
    parser.add_argument("--skip-frog-pls", action="store_true")
    parser.add_argument("--only", choices=["truth", "corners", "real"], action="append")
    parser.add_argument("--methods", help="comma-separated subset of " + ",".join(METHODS))
    args = parser.parse_args()
    cli = str(Path(args.build) / "isovdb")
    if args.methods:
        for name in [m for m in METHODS if m not in args.methods.split(",")]:
            del METHODS[name]
    work = Path(args.work)
    work.mkdir(parents=True, exist_ok=True)
    report = {"machine": os.uname().nodename, "cores": os.cpu_count()}
    parts = args.only or ["truth", "corners", "real"]
    if "truth" in parts:
        print("ground truth (labelled every 8th slice; compared between the first and last labelled slice):")
        report["ground_truth"] = ground_truth(cli, work)
    if "corners" in parts:
        print("corner sharpness and speed on paper-sized (70 x 100) rectangles:")
        report["corners"] = corner_sharpness(cli, work)
    if "real" in parts:
        print("real data, every 4th slice kept, Dice per withheld slice:")
        report["real"] = real_data(cli, work, args.skip_frog_pls)
    (work / "report.json").write_text(json.dumps(report, indent=1, default=float))
    print(f"report: {work / 'report.json'}")


if __name__ == "__main__":
    sys.exit(main())
