#!/usr/bin/python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""A disk that fills up at any point of a run: `isovdb extract` (mesh, statistics,
picture), `sdf` (.vdb, statistics) and `morph` (mesh, .vdb, statistics) either write
every output or none, never a part of them, never a temporary file, and fail with a
one-line error naming the file. The disk is a small tmpfs (root only; otherwise the
test is skipped, exit 77) filled so that from 0 to all the room a run needs is left.

Usage: full_disk.py ISOVDB DATA_DIR
"""
import os
import subprocess
import sys
import tempfile

STEP = 4096  # tmpfs allocates whole pages


def free_bytes(path):
    stats = os.statvfs(path)
    return stats.f_bavail * stats.f_frsize


def fill(disk, leave):
    """A filler file leaving about `leave` bytes free on the disk."""
    filler = os.path.join(disk, "filler")
    size = max(0, free_bytes(disk) - leave)
    with open(filler, "wb") as f:
        f.truncate(0)
        f.write(b"\0" * size)
    return filler


def one_run(isovdb, disk, command, outputs, leave):
    filler = fill(disk, leave)
    run = subprocess.run([isovdb, "-q"] + command, capture_output=True, text=True, timeout=120)
    present = sorted(name for name in os.listdir(disk) if name != "filler")
    problems = []
    if run.returncode == 0:
        if present != sorted(outputs):
            problems.append(f"exit 0 with {present}, expected {sorted(outputs)}")
    else:
        if run.returncode != 2:
            problems.append(f"exit status {run.returncode}: {run.stderr.strip()[-300:]}")
        if present:
            problems.append(f"failed and left {present}")
        # The reason's wording is the system's (a stream may not keep errno): not checked.
        if "error:" not in run.stderr or not any(name in run.stderr for name in outputs):
            problems.append(f"the error names no output: {run.stderr.strip()[-300:]}")
    for name in present:
        os.remove(os.path.join(disk, name))
    os.remove(filler)
    return run.returncode == 0, problems


def sweep(isovdb, disk, command, outputs):
    """Runs `command` with every amount of room from none to enough, one page apart."""
    problems, failures, leave = [], 0, 0
    while True:
        ok, found = one_run(isovdb, disk, command, outputs, leave)
        problems += [f"{leave} bytes free: {p}" for p in found]
        if ok or found:
            break
        failures += 1
        leave += STEP
        if leave > 2 << 20:  # the runs need about 0.2 MiB
            problems.append("never succeeded with 2 MiB free")
            break
    if failures < 3:
        problems.append(f"only {failures} runs failed for lack of room: the sweep did not test much")
    return problems


def main():
    isovdb, data = sys.argv[1], sys.argv[2]
    if os.geteuid() != 0:
        print("skipped: mounting a small tmpfs needs root")
        return 77
    volume = os.path.join(data, "nrrd", "small.nrrd")
    with tempfile.TemporaryDirectory() as disk:
        mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=16m", "tmpfs", disk], capture_output=True,
                                 text=True)
        if mounted.returncode != 0:
            print(f"skipped: cannot mount a tmpfs: {mounted.stderr.strip()}")
            return 77
        try:
            at = lambda name: os.path.join(disk, name)  # noqa: E731
            runs = {
                "extract": (["extract", volume, "--threshold", "94.06", "-o", at("m.ply"), "--stats", at("s.json"),
                             "--preview", at("p.png")], ["m.ply", "s.json", "p.png"]),
                "extract --check": (["extract", volume, "--threshold", "94.06", "--check", "-o", at("m.ply"),
                                     "--stats", at("s.json")], ["m.ply", "s.json"]),
                "sdf": (["sdf", volume, "--threshold", "94.06", "-o", at("d.vdb"), "--stats", at("s.json")],
                        ["d.vdb", "s.json"]),
                "morph": (["morph", volume, "--threshold", "94.06", "-o", at("m.ply"), "--vdb", at("d.vdb"), "--stats",
                           at("s.json")], ["m.ply", "d.vdb", "s.json"]),
            }
            problems = []
            for name, (command, outputs) in runs.items():
                problems += [f"{name}: {p}" for p in sweep(isovdb, disk, command, outputs)]
        finally:
            subprocess.run(["umount", disk], check=False)
    for p in problems:
        print(p)
    print("full disk: every run wrote all its outputs or none" if not problems else f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
