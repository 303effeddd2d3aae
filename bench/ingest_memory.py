#!/usr/bin/env python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Memory benchmark: stream a salt-like uint8 volume from disk into the mask and
the narrow-band SDF written to a .vdb (`isovdb sdf`: the band goes to the file
chunk by chunk and is never held whole), and compare peak RSS of the whole run
with the raw file size and with a dense peer (numpy reading the same file, as
any dense tool must) in the same run.

Run on demand, never in CI:
    /usr/bin/python3 bench/ingest_memory.py [--size 1024] [--work DIR]
It builds nothing: run scripts/build.sh first (build/isovdb, build/data/isovdb-sample).
"""
import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(cmd):
    start = time.monotonic()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return time.monotonic() - start


def dense_peer(path, size):
    """Peak RSS of a child that loads the whole volume with numpy and thresholds it."""
    code = (
        "import numpy, resource, sys\n"
        f"a = numpy.fromfile({path!r}, dtype=numpy.uint8).reshape({size},{size},{size})\n"
        "m = a > 0\n"
        "print(int(m.sum()), resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024)\n"
    )
    start = time.monotonic()
    out = subprocess.run(["/usr/bin/python3", "-c", code], check=True, capture_output=True, text=True).stdout
    inside, peak = map(int, out.split())
    return inside, peak, time.monotonic() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--size", type=int, default=1024, help="edge of the cube in voxels (default 1024)")
    parser.add_argument("--work", default=tempfile.gettempdir(), help="folder for the generated volume")
    parser.add_argument("--half-width", type=int, default=3, help="SDF narrow-band half-width (voxels)")
    parser.add_argument("--sdf-chunk", type=int, default=None,
                        help="isovdb sdf --sdf-chunk (default: isovdb's; smaller chunks: less memory, more time)")
    args = parser.parse_args()

    isovdb = os.path.join(ROOT, "build", "isovdb")
    sample = os.path.join(ROOT, "build", "data", "isovdb-sample")
    for tool in (isovdb, sample):
        if not os.path.exists(tool):
            sys.exit(f"{tool} is missing: run scripts/build.sh first")

    raw = os.path.join(args.work, f"salt-dome-{args.size}.raw")
    if not os.path.exists(raw):
        print(f"generating {raw} ...", file=sys.stderr)
        run([sample, "salt-dome", "--size", str(args.size), "-o", raw])
    file_bytes = os.path.getsize(raw)

    stats_path = os.path.join(args.work, f"salt-dome-{args.size}-sdf.json")
    vdb = os.path.join(args.work, f"salt-dome-{args.size}.vdb")
    dims = f"{args.size},{args.size},{args.size}"
    seconds = run([isovdb, "-q", "sdf", raw, "--dims", dims, "--type", "uint8", "--half-width",
                   str(args.half_width), "-o", vdb, "--stats", stats_path]
                  + (["--sdf-chunk", str(args.sdf_chunk)] if args.sdf_chunk is not None else []))
    stats = json.load(open(stats_path))
    mem = stats["memory"]
    ours = mem["peak_rss_bytes"]  # the whole run: read, distance field and writing the .vdb
    inside, dense_peak, dense_seconds = dense_peer(raw, args.size)
    if inside != stats["input"]["active_voxels"]:
        sys.exit(f"mismatch: numpy counts {inside} inside voxels, isovdb {stats['input']['active_voxels']}")

    mb = 1 << 20
    print(f"salt-dome {args.size}^3 uint8, raw file {file_bytes / mb:.0f} MiB, "
          f"{inside} voxels inside, SDF half-width {args.half_width}")
    print(f"{'run':<36}{'peak RSS MiB':>14}{'% of file':>11}{'time s':>9}")
    rows = [
        ("isovdb read -> mask", mem["peak_rss_after_read_bytes"], stats["timings_s"]["read"]),
        ("isovdb read -> mask -> SDF -> .vdb", ours,
         stats["timings_s"]["read"] + stats["timings_s"]["distance_field"] + stats["timings_s"]["write"]),
        ("numpy dense load + threshold (peer)", dense_peak, dense_seconds),
    ]
    for name, peak, secs in rows:
        print(f"{name:<36}{peak / mb:>14.1f}{100 * peak / file_bytes:>10.1f}%{secs:>9.1f}")
    band = stats["distance_field"]
    held = "streamed to the file" if band.get("streamed_to_file") else \
        f"held whole: {band['grid_memory_bytes'] / mb:.1f} MiB"
    print(f"mask grid {stats['input']['grid_memory_bytes'] / mb:.1f} MiB; SDF band "
          f"{band['active_voxels']} voxels in {band['leaf_nodes']} leaves ({held}; "
          f"leaf blocks of ~2 KiB each would be {band['leaf_nodes'] * 2 / 1024:.1f} MiB), "
          f".vdb {stats['output'].get('file_bytes', os.path.getsize(vdb)) / mb:.1f} MiB")
    print(f"ratio dense peer / isovdb peak RSS: {dense_peak / ours:.1f}x; "
          f"whole run {seconds:.1f} s incl. writing {vdb}")
    print(f"target (issue: Foundation): isovdb peak below 15% of the file -> "
          f"{'met' if ours < 0.15 * file_bytes else 'NOT met'}")


if __name__ == "__main__":
    main()
