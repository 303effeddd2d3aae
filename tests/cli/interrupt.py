#!/usr/bin/python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""SIGINT and SIGTERM while `isovdb extract` streams its mesh: the run stops with
exit status 130 / 143 and "interrupted", and leaves neither the mesh nor its
temporary file (.NAME.ply.tmp.*) behind.

Usage: interrupt.py ISOVDB ISOVDB_SAMPLE
"""
import os
import signal
import subprocess
import sys
import tempfile
import time


def interrupt_once(isovdb, volume, out_dir, sig):
    mesh = os.path.join(out_dir, "mesh.ply")
    run = subprocess.Popen([isovdb, "-q", "extract", volume, "--method", "regular", "--meta-cell", "16", "-o", mesh],
                           stderr=subprocess.PIPE, text=True)
    # Signal once the temporary mesh file holds bytes: the streamed write is under way.
    def writing():
        for name in os.listdir(out_dir):
            try:
                if name.startswith(".mesh.ply.tmp") and os.path.getsize(os.path.join(out_dir, name)) > 0:
                    return True
            except FileNotFoundError:
                pass
        return False

    deadline = time.monotonic() + 120
    while not writing():
        if run.poll() is not None or time.monotonic() > deadline:
            run.kill()
            raise SystemExit(f"the run ended (status {run.returncode}) before its temporary file was seen")
        time.sleep(0.005)
    run.send_signal(sig)
    _, err = run.communicate(timeout=120)
    expected = 128 + sig
    problems = []
    if run.returncode != expected:
        problems.append(f"exit status {run.returncode}, expected {expected}: {err.strip()[-300:]}")
    if "interrupted" not in err:
        problems.append(f"no 'interrupted' message: {err.strip()[-300:]}")
    left = os.listdir(out_dir)
    if left:
        problems.append(f"left behind: {left}")
    return problems


def main():
    isovdb, sample = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        volume = os.path.join(tmp, "blobs.nrrd")
        subprocess.run([sample, "blobs", "-n", "256", "-o", volume], check=True, capture_output=True)
        out_dir = os.path.join(tmp, "out")
        os.mkdir(out_dir)
        problems = []
        for sig in (signal.SIGINT, signal.SIGTERM):
            problems += [f"{signal.Signals(sig).name}: {p}" for p in interrupt_once(isovdb, volume, out_dir, sig)]
        for problem in problems:
            print(problem)
        print("ok" if not problems else f"{len(problems)} problems")
        return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
