#!/usr/bin/env python3
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Round trip SEG-Y -> .vdb -> dense float32 through the `isovdb` CLI, compared
sample for sample with segyio's own reading of the cube (python3-segyio).

Cubes: the four encodings of the real F3 crop and segyio's small.sgy (data/seismic/),
plus a crossline-sorted, little-endian IBM cube written by isovdb-segy-sample.
Usage (ctest runs it): /usr/bin/python3 segy_round_trip.py ISOVDB SEGY_SAMPLE DATA_DIR
Exit 77 (skipped) when segyio or numpy is missing.
"""
import os
import subprocess
import sys
import tempfile

try:
    import numpy
    import segyio
except ImportError as error:  # the dependency is installed by scripts/install-deps.sh
    print(f"skipped: {error}")
    sys.exit(77)


def dense_through_isovdb(isovdb, cube, work):
    """.sgy -> .vdb -> .raw (+ .nhdr); returns the samples as [inline, crossline, sample]."""
    vdb = os.path.join(work, "cube.vdb")
    raw = os.path.join(work, "cube.raw")
    subprocess.run([isovdb, "-q", "convert", cube, "-o", vdb], check=True, stdout=subprocess.DEVNULL)
    subprocess.run([isovdb, "-q", "convert", vdb, "-o", raw], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(work, "cube.nhdr")) as header:
        sizes = next(line for line in header if line.startswith("sizes:")).split()[1:]
    nx, ny, nz = (int(s) for s in sizes)
    # x (inline) fastest in the file: C order is [sample, crossline, inline].
    return numpy.fromfile(raw, dtype="<f4").reshape(nz, ny, nx).transpose(2, 1, 0)


def segyio_cube(cube, little_endian):
    with segyio.open(cube, endian="little" if little_endian else "big") as f:
        data = segyio.tools.cube(f).astype(numpy.float32)
        # segyio gives [slow line, fast line, sample]: make it [inline, crossline, sample].
        return data if f.sorting == segyio.TraceSortingFormat.INLINE_SORTING else data.transpose(1, 0, 2)


def main():
    isovdb, generator, data = sys.argv[1:4]
    with tempfile.TemporaryDirectory() as work:
        generated = os.path.join(work, "generated.sgy")
        subprocess.run([generator, "-o", generated, "--inlines", "12", "--crosslines", "9", "--samples", "40",
                        "--format", "1", "--little-endian", "--crossline-sorted"], check=True,
                       stdout=subprocess.DEVNULL)
        cubes = [(os.path.join(data, name), name == "f3-lsb.sgy") for name in
                 ("f3.sgy", "f3-lsb.sgy", "f3_format1_ibm_msb.sgy", "f3_format5_ieee_msb.sgy", "small.sgy")]
        cubes.append((generated, True))
        failures = 0
        for cube, little in cubes:
            expected = segyio_cube(cube, little)
            got = dense_through_isovdb(isovdb, cube, work)
            same = got.shape == expected.shape and numpy.array_equal(got, expected)
            print(f"{os.path.basename(cube)}: shape {got.shape}, segyio {expected.shape}: "
                  f"{'equal sample for sample' if same else 'DIFFERENT'}")
            failures += not same
        return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
