# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Shared fixtures: the CLI, the bundled data, and small volumes built in code."""
import os
import pathlib
import subprocess

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def cli():
    """Path of the `isovdb` command-line tool of the same build."""
    path = pathlib.Path(os.environ.get("ISOVDB_CLI", ROOT / "build" / "isovdb"))
    if not path.exists():
        pytest.fail(f"isovdb CLI not found at {path} (set ISOVDB_CLI)")
    return path


@pytest.fixture(scope="session")
def data_dir():
    return pathlib.Path(os.environ.get("ISOVDB_DATA_DIR", ROOT / "data"))


def run_cli(cli, *args, statuses=(0,)):
    """Runs the CLI quietly; returns the completed process. Fails on an exit status not in `statuses`."""
    done = subprocess.run([str(cli), "-q", *map(str, args)], capture_output=True, text=True)
    assert done.returncode in statuses, f"{args}: status {done.returncode}: {done.stderr}"
    return done


def ball(shape, centre, radius):
    """bool array [x, y, z]: voxels within `radius` of `centre`."""
    x, y, z = np.indices(shape)
    return (x - centre[0]) ** 2 + (y - centre[1]) ** 2 + (z - centre[2]) ** 2 < radius ** 2


def torus(shape, centre, major, minor):
    """bool array [x, y, z]: a torus around the z axis through `centre` (genus 1)."""
    x, y, z = np.indices(shape).astype(float)
    ring = np.hypot(x - centre[0], y - centre[1]) - major
    return ring ** 2 + (z - centre[2]) ** 2 < minor ** 2


@pytest.fixture
def sphere_mask():
    """A 40x36x32 uint8 ball (anisotropic shape, so axis mix-ups show)."""
    return ball((40, 36, 32), (21, 17, 15), 11).astype(np.uint8)
