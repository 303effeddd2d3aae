#!/usr/bin/python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Decompression bombs by declaration: a tiny gzip NRRD or compressed MetaImage
whose header declares 30000 x 30000 samples must fail with the reader's error
("ends early") at a memory cost that follows the bytes present, not the
declared 900 M samples (it was 11.6 GB).

Usage: declared_sizes.py ISOVDB
"""
import gzip
import os
import subprocess
import sys
import tempfile
import zlib

LIMIT_MB = 400  # the process itself (OpenVDB, TBB) takes ~50 MB; one declared slice as floats would be 3.6 GB
# Under AddressSanitizer (CI's sanitizer build sets this) the declared-size buffers, left
# untouched until data arrives, still cost their shadow memory (1/8 of their size): the
# peak says nothing there, the exit status and the message still do.
MEASURE_MEMORY = os.environ.get("ISOVDB_SANITIZED") != "1"


def run_measured(argv):
    """Runs argv from a fresh interpreter, whose only child it is: (result, peak RSS in MB)."""
    probe = ("import resource, subprocess, sys\n"
             "r = subprocess.run(sys.argv[1:], capture_output=True, text=True, timeout=120)\n"
             "sys.stderr.write(r.stderr)\n"
             "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n"
             "sys.exit(r.returncode)\n")
    run = subprocess.run([sys.executable, "-c", probe] + argv, capture_output=True, text=True, timeout=180)
    return run, int(run.stdout.strip().splitlines()[-1]) / 1024


def main():
    isovdb = sys.argv[1]
    problems = []
    with tempfile.TemporaryDirectory() as tmp:
        payload = bytes(1000)  # 1000 samples of the 900 M declared
        nrrd = os.path.join(tmp, "bomb.nrrd")
        with open(nrrd, "wb") as f:
            f.write(b"NRRD0004\ntype: uint8\ndimension: 3\nsizes: 30000 30000 1\nencoding: gzip\n\n")
            f.write(gzip.compress(payload))
        mhd = os.path.join(tmp, "bomb.mha")
        with open(mhd, "wb") as f:
            f.write(b"ObjectType = Image\nNDims = 3\nDimSize = 30000 30000 1\nElementType = MET_UCHAR\n"
                    b"CompressedData = True\nElementDataFile = LOCAL\n")
            f.write(zlib.compress(payload))
        for path in (nrrd, mhd):
            name = os.path.basename(path)
            for command in (["extract", path, "-o", os.path.join(tmp, "m.ply")], ["info", path]):
                run, peak_mb = run_measured([isovdb, "-q"] + command)
                label = f"{command[0]} {name}"
                print(f"{label}: exit {run.returncode}, peak {peak_mb:.0f} MB: {run.stderr.strip()[-160:]}")
                if run.returncode != 2 or name not in run.stderr:
                    problems.append(f"{label}: exit {run.returncode}, expected 2 naming the file: {run.stderr[-300:]}")
                if MEASURE_MEMORY and peak_mb > LIMIT_MB:
                    problems.append(f"{label}: peak {peak_mb:.0f} MB for {os.path.getsize(path)} bytes of file")
            if os.path.exists(os.path.join(tmp, "m.ply")):
                problems.append(f"{name}: left m.ply")
    for problem in problems:
        print(problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
