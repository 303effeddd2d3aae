# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""numpy volume -> extract -> write/check equals, byte for byte, the CLI on the same data as a raw file."""
import json

import numpy as np
import pytest

import isovdb
from conftest import ball, run_cli, torus


def two_bodies():
    """A torus and a ball cut by the x = 0 face (so the boundary caps matter), uint8 [x, y, z]."""
    shape = (56, 44, 36)
    body = torus(shape, (30, 22, 18), 13, 5) | ball(shape, (3, 10, 9), 7)
    return body.astype(np.uint8)


def write_raw(array, path):
    array.T.tofile(path)  # raw files are x fastest
    return path


CASES = [
    # (method, python keywords, CLI flags)
    ("adaptive", {}, []),
    ("adaptive", {"meta_cell": 16, "qef_tolerance": 0.5, "max_cell_size": 8}, ["--meta-cell", 16, "--qef-tolerance", 0.5, "--max-cell-size", 8]),
    ("regular", {"meta_cell": 32, "boundary": "open"}, ["--meta-cell", 32, "--boundary", "open"]),
    ("regular", {"finest_size": 2, "iso": 0.5}, ["--finest-size", 2, "--iso", 0.5]),
    ("vdb", {"adaptivity": 0.3, "half_width": 4}, ["--adaptivity", 0.3, "--half-width", 4]),
]


@pytest.mark.parametrize("method, keywords, flags", CASES)
def test_mask_mesh_bytes_equal_the_cli(tmp_path, cli, method, keywords, flags):
    array = two_bodies()
    raw = write_raw(array, tmp_path / "v.raw")
    common = [raw, "--dims", "56,44,36", "--type", "uint8", "--spacing", "0.5,0.5,2", "--method", method, *flags]
    # the CLI's default path (a streamed .ply for the octree methods) ...
    run_cli(cli, "extract", *common, "-o", tmp_path / "cli.ply")
    # ... and its --check path (mesh held, then written whole)
    # (exit 1 when the mesh fails the check, as `isovdb check`; the figures are compared below)
    run_cli(cli, "extract", *common, "--check", "--stats", tmp_path / "cli.json", "-o", tmp_path / "cli_held.ply",
            statuses=(0, 1))

    volume = isovdb.from_numpy(array, voxel_size=(0.5, 0.5, 2))
    stats = isovdb.extract(volume, method=method, output=tmp_path / "py.ply", **keywords)
    assert (tmp_path / "py.ply").read_bytes() == (tmp_path / "cli.ply").read_bytes()
    assert stats["output"].get("streamed", False) == (method != "vdb")

    mesh = isovdb.extract(volume, method=method, **keywords)
    assert mesh.triangle_count > 100
    mesh.write(tmp_path / "py_held.ply")
    assert (tmp_path / "py_held.ply").read_bytes() == (tmp_path / "cli_held.ply").read_bytes()

    # the validator's figures equal `isovdb extract --check` and `isovdb check`
    assert mesh.check() == json.loads((tmp_path / "cli.json").read_text())["check"]
    # (status 1: a guarantee fails, as it must for boundary="open")
    run_cli(cli, "check", tmp_path / "cli.ply", "--stats", tmp_path / "check.json", statuses=(0, 1))
    assert mesh.check() == json.loads((tmp_path / "check.json").read_text())["mesh"]


def test_scalar_mesh_bytes_equal_the_cli(tmp_path, cli):
    x, y, z = np.indices((40, 30, 20)).astype(np.float32)
    field = np.sin(x / 5) + np.cos(y / 4) + z / 10  # a wavy layer crossing every column
    raw = write_raw(field, tmp_path / "f.raw")
    run_cli(cli, "extract", raw, "--dims", "40,30,20", "--type", "float32", "--scalar", "--iso", 1.0,
            "--method", "adaptive", "--meta-cell", 16, "-o", tmp_path / "cli.ply")
    isovdb.extract(isovdb.from_numpy(field), method="adaptive", iso=1.0, meta_cell=16, output=tmp_path / "py.ply")
    assert (tmp_path / "py.ply").read_bytes() == (tmp_path / "cli.ply").read_bytes()
    mesh = isovdb.read_mesh(tmp_path / "py.ply")
    assert mesh.triangle_count > 100 and mesh.check()["closed"]


def test_a_different_option_gives_different_bytes(tmp_path, cli):
    """The comparison above can fail: another option changes the bytes."""
    array = two_bodies()
    raw = write_raw(array, tmp_path / "v.raw")
    run_cli(cli, "extract", raw, "--dims", "56,44,36", "--type", "uint8", "--method", "regular",
            "-o", tmp_path / "cli.ply")
    isovdb.extract(isovdb.from_numpy(array), method="regular", finest_size=2, output=tmp_path / "py.ply")
    assert (tmp_path / "py.ply").read_bytes() != (tmp_path / "cli.ply").read_bytes()
