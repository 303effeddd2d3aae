#!/usr/bin/env python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Memory benchmark for SEG-Y ingest: a synthetic float SEG-Y cube (default
1000 x 1000 x 500, about 90 % of the samples in the dead band |a| < 1000) is
streamed trace by trace into the sparse amplitude grid; the peak RSS of the
whole `isovdb` process is compared with the file size (target: < 25 %).

Run on demand, never in CI (it writes a 2.2 GB file and takes a few minutes):
    /usr/bin/python3 bench/segy_memory.py [--inlines 1000 --crosslines 1000 --samples 500]
                                          [--clip 1000] [--work DIR] [--keep]
It builds nothing: run scripts/build.sh first (build/isovdb, build/data/isovdb-segy-sample).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TARGET_RATIO = 0.25


def timed(cmd):
    start = time.monotonic()
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return out, time.monotonic() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--inlines", type=int, default=1000)
    parser.add_argument("--crosslines", type=int, default=1000)
    parser.add_argument("--samples", type=int, default=500)
    parser.add_argument("--clip", type=float, default=1000.0, help="dead band |a| < clip (default 1000)")
    parser.add_argument("--work", default=tempfile.gettempdir(), help="folder for the generated cube")
    parser.add_argument("--keep", action="store_true", help="keep the generated cube and .vdb")
    args = parser.parse_args()

    isovdb = os.path.join(ROOT, "build", "isovdb")
    generator = os.path.join(ROOT, "build", "data", "isovdb-segy-sample")
    for tool in (isovdb, generator):
        if not os.path.exists(tool):
            sys.exit(f"{tool} is missing: run scripts/build.sh first")

    name = f"salt-{args.inlines}x{args.crosslines}x{args.samples}"
    cube = os.path.join(args.work, name + ".sgy")
    vdb = os.path.join(args.work, name + ".vdb")
    stats = os.path.join(args.work, name + ".json")
    print(f"generating {cube} ...", file=sys.stderr)
    out, gen_s = timed([generator, "-o", cube, "--inlines", str(args.inlines), "--crosslines", str(args.crosslines),
                        "--samples", str(args.samples), "--format", "5"])
    print(out.strip(), file=sys.stderr)
    file_bytes = os.path.getsize(cube)
    try:
        rows = []
        for label, cmd in (
            ("info (ingest + histograms)", [isovdb, "-q", "info", cube, "--clip", str(args.clip), "--stats", stats]),
            ("convert -> .vdb", [isovdb, "-q", "convert", cube, "--clip", str(args.clip), "-o", vdb, "--stats", stats]),
        ):
            _, seconds = timed(cmd)
            with open(stats) as f:
                report = json.load(f)
            peak = report["memory"]["peak_rss_bytes"]
            rows.append((label, seconds, peak, report["input"]))
        first = rows[0][3]
        print(f"cube: {args.inlines} x {args.crosslines} x {args.samples} IEEE float, file {file_bytes / 2**20:.0f} MiB "
              f"(generated in {gen_s:.0f} s)")
        print(f"samples outside the dead band |a| < {args.clip:g}: {100 * first['samples']['active_fraction']:.1f} %, "
              f"active voxels {first['active_voxels']}, leaves {first['leaf_nodes']}, "
              f"grid {first['grid_memory_bytes'] / 2**20:.0f} MiB")
        print(f"{'run':28} {'time s':>8} {'peak RSS MiB':>13} {'RSS / file':>11}")
        ok = True
        for label, seconds, peak, _ in rows:
            ratio = peak / file_bytes
            ok = ok and ratio < TARGET_RATIO
            print(f"{label:28} {seconds:8.1f} {peak / 2**20:13.0f} {100 * ratio:10.1f}%")
        print(f"target: peak RSS < {100 * TARGET_RATIO:.0f} % of the file size: {'met' if ok else 'NOT met'}")
        return 0 if ok else 1
    finally:
        if not args.keep:
            for path in (cube, vdb, stats):
                if os.path.exists(path):
                    os.remove(path)


if __name__ == "__main__":
    sys.exit(main())
