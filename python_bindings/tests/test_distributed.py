# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""isovdb.distributed on a real 2-worker Dask LocalCluster (worker processes): the output
file is the CLI's bytes for the same input and settings (frog, generated shapes, a SEG-Y
cube, a Zarr array), also when a worker is killed mid-run; bad input fails the run with
the reader's message and leaves no file."""
import filecmp
import os
import pathlib
import signal
import subprocess
import sys

import numpy as np
import pytest

import isovdb
from conftest import run_cli

distributed = pytest.importorskip("distributed")
zarr = pytest.importorskip("zarr")
import isovdb.distributed  # noqa: E402  (after the skips: it needs neither, its tests do)

ROOT = pathlib.Path(__file__).resolve().parents[2]
SAMPLE = pathlib.Path(os.environ.get("ISOVDB_BUILD_DIR", ROOT / "build")) / "data" / "isovdb-sample"


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    with cluster, distributed.Client(cluster) as c:
        yield c


def same_file(a, b):
    return filecmp.cmp(a, b, shallow=False)


def cli_mesh(cli, tmp_path, source, *args):
    out = tmp_path / "cli.ply"
    run_cli(cli, "extract", source, "-o", out, *args)
    return out


@pytest.mark.parametrize("method,meta_cell", [("adaptive", 128), ("adaptive", 32), ("regular", 32)])
def test_frog_gives_the_cli_bytes(client, cli, data_dir, tmp_path, method, meta_cell):
    frog = data_dir / "frog" / "frogtissue.mhd"
    expected = cli_mesh(cli, tmp_path, frog, "--labels", "13", "--method", method, "--meta-cell", meta_cell)
    out = tmp_path / "dask.ply"
    stats = isovdb.distributed.extract(frog, out, client, read=dict(labels=[13]), method=method, meta_cell=meta_cell)
    assert same_file(out, expected)
    slabs = stats["slabs"]
    assert len(slabs) >= 2 and sum(s["meta_cells"] for s in slabs) > 1
    assert all(s["seam_bytes"] <= s["bytes"] for s in slabs)
    assert stats["stitch"]["missing_cells"] == 0 and stats["stitch"]["edges"] > 0


@pytest.mark.parametrize("shape", ["salt-dome", "genus2", "gyroid-slab"])
@pytest.mark.parametrize("method", ["adaptive", "regular"])
def test_generated_shapes_give_the_cli_bytes(client, cli, tmp_path, shape, method):
    volume = tmp_path / f"{shape}.nrrd"
    subprocess.run([str(SAMPLE), shape, "-n", "80", "-o", str(volume)], check=True, capture_output=True)
    expected = cli_mesh(cli, tmp_path, volume, "--method", method, "--meta-cell", 16)
    out = tmp_path / "dask.ply"
    isovdb.distributed.extract(volume, out, client, method=method, meta_cell=16, slab_layers=2)
    assert same_file(out, expected)


@pytest.mark.parametrize("method", ["adaptive", "regular"])
def test_segy_cube_gives_the_cli_bytes(client, cli, data_dir, tmp_path, method):
    # SEG-Y's grid z is the samples along each trace: a slab blanks samples, not file slices.
    cube = data_dir / "seismic" / "f3.sgy"
    expected = cli_mesh(cli, tmp_path, cube, "--mask", "above 3000", "--method", method, "--meta-cell", 16)
    out = tmp_path / "dask.ply"
    isovdb.distributed.extract(cube, out, client, read=dict(mask="above 3000"), method=method, meta_cell=16)
    assert same_file(out, expected)


@pytest.mark.parametrize("method,iso", [("adaptive", None), ("regular", -2500.0), ("adaptive", 4000.0)])
def test_segy_amplitude_gives_the_cli_bytes(client, cli, data_dir, tmp_path, method, iso):
    # A scalar field: the slabs' first pass measures the whole cube's range (the default
    # iso is its middle; the caps' far-outside value derives from it).
    cube = data_dir / "seismic" / "f3.sgy"
    flags = ["--iso", iso] if iso is not None else []
    expected = cli_mesh(cli, tmp_path, cube, "--method", method, "--meta-cell", 16, *flags)
    out = tmp_path / "dask.ply"
    settings = dict(method=method, meta_cell=16) | ({"iso": iso} if iso is not None else {})
    stats = isovdb.distributed.extract(cube, out, client, **settings)
    assert same_file(out, expected)
    assert stats["contour"]["triangles"] > 1000


@pytest.mark.parametrize("method", ["adaptive", "regular"])
def test_vdb_level_set_gives_the_cli_bytes(client, cli, data_dir, tmp_path, method):
    # cortex's level-set sphere: each task reads its slab's leaves (OpenVDB's clipped
    # read); the slabs come from the grid's recorded active box, the range from a first pass.
    sphere = data_dir / "vdb" / "sphere.vdb"
    expected = cli_mesh(cli, tmp_path, sphere, "--method", method, "--meta-cell", 32)
    out = tmp_path / "dask.ply"
    stats = isovdb.distributed.extract(sphere, out, client, method=method, meta_cell=32)
    assert same_file(out, expected)
    assert len(stats["slabs"]) >= 4


def blobs_zyx(shape, seed):
    """uint8 [z, y, x]: random overlapping balls (a raw file's sample order)."""
    rng = np.random.default_rng(seed)
    z, y, x = np.ogrid[:shape[0], :shape[1], :shape[2]]
    mask = np.zeros(shape, np.uint8)
    for _ in range(25):
        c = rng.uniform(0, shape)
        r = rng.uniform(3, 15)
        mask |= ((z - c[0]) ** 2 + (y - c[1]) ** 2 + (x - c[2]) ** 2 < r * r).astype(np.uint8)
    return mask


@pytest.mark.parametrize("method", ["adaptive", "regular"])
def test_zarr_array_gives_the_bytes_of_the_same_raw_file(client, cli, tmp_path, method):
    stack = blobs_zyx((100, 70, 60), seed=5)
    raw = tmp_path / "blobs.raw"
    stack.tofile(raw)
    array = zarr.open(str(tmp_path / "blobs.zarr"), mode="w", shape=stack.shape, chunks=(24, 32, 32),
                      dtype=stack.dtype)
    array[:] = stack
    nz, ny, nx = stack.shape
    expected = cli_mesh(cli, tmp_path, raw, "--dims", nx, ny, nz, "--type", "uint8", "--method", method,
                        "--meta-cell", 16)
    out = tmp_path / "zarr.ply"
    isovdb.distributed.extract(zarr.open(str(tmp_path / "blobs.zarr"), mode="r"), out, client, method=method,
                               meta_cell=16)
    assert same_file(out, expected)
    by_path = tmp_path / "zarr_path.ply"
    isovdb.distributed.extract(tmp_path / "blobs.zarr", by_path, client, method=method, meta_cell=16)
    assert same_file(by_path, expected)


def test_zarr_field_gives_the_bytes_of_the_same_raw_file(client, cli, tmp_path):
    z, y, x = np.ogrid[:90, :50, :60]
    field = (np.exp(-((z - 40) ** 2 + (y - 25) ** 2 + (x - 30) ** 2) / 400.0)
             + 0.6 * np.exp(-((z - 70) ** 2 + (y - 20) ** 2 + (x - 35) ** 2) / 90.0)).astype(np.float32)
    raw = tmp_path / "field.raw"
    field.tofile(raw)
    zarr.open(str(tmp_path / "field.zarr"), mode="w", shape=field.shape, chunks=(20, 25, 30), dtype=field.dtype)[:] = field
    expected = cli_mesh(cli, tmp_path, raw, "--dims", 60, 50, 90, "--type", "float32", "--scalar", "--meta-cell", 16)
    out = tmp_path / "zarr.ply"
    isovdb.distributed.extract(tmp_path / "field.zarr", out, client, meta_cell=16)
    assert same_file(out, expected)


def test_a_worker_killed_mid_run_changes_no_byte(client, cli, data_dir, tmp_path):
    frog = data_dir / "frog" / "frogtissue.mhd"
    expected = cli_mesh(cli, tmp_path, frog, "--labels", "13", "--meta-cell", 16)
    pids = client.run(os.getpid)  # worker address -> process id
    victim = sorted(pids.values())[0]
    killed = []

    def kill_one_worker(stage, percent):
        # When the first slab reaches the client the others are running or waiting on the
        # workers (their results held there): the victim takes its share with it.
        if stage == "slabs" and not killed:
            os.kill(victim, signal.SIGKILL)
            killed.append(victim)

    out = tmp_path / "dask.ply"
    stats = isovdb.distributed.extract(frog, out, client, read=dict(labels=[13]), meta_cell=16,
                                       progress=kill_one_worker)
    assert killed
    assert same_file(out, expected)
    # Every slab the client took after the kill came from a live process.
    assert len(stats["slabs"]) > 2 and victim not in {s["pid"] for s in stats["slabs"][1:]}
    client.wait_for_workers(2, timeout=60)  # the nanny restarted it, for the next tests
    assert victim not in client.run(os.getpid).values()


def test_a_relative_path_is_the_clients(client, cli, data_dir, tmp_path, monkeypatch):
    # The workers stay in the folder they started in (or on another machine): the client
    # resolves the path before sending it.
    frog = data_dir / "frog" / "frogtissue.mhd"
    expected = cli_mesh(cli, tmp_path, frog, "--labels", "13", "--method", "regular")
    monkeypatch.chdir(frog.parent)
    out = tmp_path / "relative.ply"
    isovdb.distributed.extract("frogtissue.mhd", out, client, read=dict(labels=[13]), method="regular")
    assert same_file(out, expected)


def test_none_is_the_default_as_in_extract(client, cli, data_dir, tmp_path):
    # extract() reads None as the default of any keyword; so does a distributed run
    # (meta_cell=None once failed as "not 0", threads=None gave every task all cores).
    sphere = data_dir / "vdb" / "sphere.vdb"
    expected = cli_mesh(cli, tmp_path, sphere)
    out = tmp_path / "dask.ply"
    isovdb.distributed.extract(sphere, out, client, meta_cell=None, threads=None, max_error=None, method=None)
    assert same_file(out, expected)


def test_bad_input_fails_the_run_with_the_readers_message_and_leaves_no_file(client, tmp_path):
    stack = blobs_zyx((64, 40, 40), seed=2)
    short = tmp_path / "short.raw"
    stack[:40].tofile(short)  # 40 of the 64 slices the dims declare
    out = tmp_path / "never.ply"
    with pytest.raises(ValueError, match="short.raw"):
        isovdb.distributed.extract(short, out, client, read=dict(dims=(40, 40, 64), dtype="uint8"), meta_cell=16)
    assert not out.exists()
    assert not any(p.name.startswith("never") for p in tmp_path.iterdir())


def test_settings_outside_a_distributed_run_are_refused(client, data_dir, tmp_path):
    frog = data_dir / "frog" / "frogtissue.mhd"
    with pytest.raises(ValueError, match="meta_cell"):
        isovdb.distributed.extract(frog, tmp_path / "a.ply", client, read=dict(labels=[13]), meta_cell=0)
    with pytest.raises(ValueError, match="distributed run"):
        isovdb.distributed.extract(frog, tmp_path / "b.ply", client, read=dict(labels=[13]), method="vdb")
    assert not any(tmp_path.iterdir())


def test_module_runs_as_a_command_on_its_own_local_cluster(cli, data_dir, tmp_path):
    frog = data_dir / "frog" / "frogtissue.mhd"
    expected = cli_mesh(cli, tmp_path, frog, "--labels", "13", "--method", "regular")
    out = tmp_path / "command.ply"
    done = subprocess.run([sys.executable, "-m", "isovdb.distributed", str(frog), "-o", str(out), "--labels", "13",
                           "--method", "regular"], capture_output=True, text=True, timeout=240)
    assert done.returncode == 0, done.stderr
    assert "triangles" in done.stdout
    assert same_file(out, expected)
    missing = subprocess.run([sys.executable, "-m", "isovdb.distributed", str(tmp_path / "none.nrrd"), "-o",
                              str(tmp_path / "none.ply")], capture_output=True, text=True, timeout=240)
    assert missing.returncode == 1 and "none.nrrd" in missing.stderr
