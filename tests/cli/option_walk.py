#!/usr/bin/python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Every numeric option of every `isovdb` command, given NaN, +-inf, negative, zero,
huge and non-numeric values, on tiny valid inputs: the exit status is 0 (the value
is valid), or 1/2 with a message naming the option (or the input it was applied
to); never 3 (an internal error), a signal or a run beyond the time limit.

The options come from each command's --help, so a new option is walked too.

Usage: option_walk.py ISOVDB ISOVDB_SAMPLE DATA_DIR
"""
import os
import re
import subprocess
import sys
import tempfile

VALUES = ["nan", "inf", "-inf", "-1", "0", "1e30", "-2147483648", "99999999999", "abc"]
# "--dims INT x 3", "--labels FLOAT ...", "--iso FLOAT=0", "--adjacency INT:{6,26}=26"
OPTION = re.compile(r"^\s+(?:-\w,)?(--[\w-]+)(?:,-[-\w]+)*(?:\{[^}]*\})?\s+(INT|UINT|FLOAT)\b( x 3| x 2| \.\.\.)?")
TIME_LIMIT_S = 60
VERDICTS = {"check", "compare"}  # exit 1 is their "a guarantee failed" verdict


def numeric_options(isovdb, command):
    text = subprocess.run([isovdb, command, "--help"], capture_output=True, text=True, check=True).stdout
    options = []
    for line in text.splitlines():
        match = OPTION.match(line)
        if match:
            count = {" x 3": 3, " x 2": 2}.get(match.group(3) or "", 1)
            options.append((match.group(1), count, line.strip()))
    return options


def main():
    isovdb, sample, data = sys.argv[1], sys.argv[2], sys.argv[3]
    with tempfile.TemporaryDirectory() as tmp:
        torus = os.path.join(tmp, "t.nrrd")
        subprocess.run([sample, "torus", "-n", "24", "-o", torus], check=True, capture_output=True)
        reference = os.path.join(tmp, "ref.ply")
        subprocess.run([isovdb, "-q", "extract", torus, "-o", reference], check=True, capture_output=True)
        deck = os.path.join(data, "reservoir", "fault_test", "regular27cell.DATA")
        out = lambda name: os.path.join(tmp, "out", name)
        base = {
            "info": [torus],
            "sdf": [torus, "-o", out("o.vdb")],
            "extract": [torus, "-o", out("o.ply")],
            "octree": [torus],
            "convert": [torus, "-o", out("o.vdb")],
            "morph": [torus, "--labels", "1", "--slice-step", "4", "-o", out("m.ply")],
            "reservoir": [deck, "--property", "PORO", "-o", out("r.ply")],
            "check": [reference],
            "compare": [reference, reference],
        }
        # Required numeric options, given a valid value while another option is walked.
        required = {"reservoir": ["--iso", "0.5"]}
        failures = []
        runs = 0
        walked = set()  # help lines: the input flags every command shares are walked once
        for command, arguments in base.items():
            options = numeric_options(isovdb, command)
            assert options, f"no numeric options parsed from '{command} --help'"
            for option, count, help_line in options:
                if help_line in walked:
                    continue
                walked.add(help_line)
                for value in VALUES:
                    os.makedirs(os.path.join(tmp, "out"), exist_ok=True)
                    given = ",".join([value] * count)
                    extra = required.get(command, [])
                    extra = [] if option in extra else extra
                    argv = [isovdb, "-q", command] + arguments + extra + [option, given]
                    runs += 1
                    try:
                        run = subprocess.run(argv, capture_output=True, text=True, timeout=TIME_LIMIT_S)
                    except subprocess.TimeoutExpired:
                        failures.append(f"{command} {option} {given}: still running after {TIME_LIMIT_S} s")
                        continue
                    message = run.stderr.strip()
                    left = os.listdir(os.path.join(tmp, "out"))
                    for name in left:
                        os.remove(os.path.join(tmp, "out", name))
                    if run.returncode == 0 or (run.returncode == 1 and command in VERDICTS):
                        continue  # a valid value, or a valid verdict (the meshes differ by more than it)
                    if run.returncode not in (1, 2):
                        failures.append(f"{command} {option} {given}: exit {run.returncode}: {message[-300:]}")
                    elif option.lstrip("-") not in message and "isovdb: error:" not in message:
                        failures.append(f"{command} {option} {given}: message names neither option nor input: "
                                        f"{message[-300:]}")
                    if left:
                        failures.append(f"{command} {option} {given}: failed but left {left}")
        print(f"{runs} runs, {len(failures)} failures")
        for failure in failures:
            print(failure)
        return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
