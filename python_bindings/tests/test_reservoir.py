# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""extract_reservoir: isosurfaces of Eclipse corner-point grids, equal to the CLI's output."""
import numpy as np
import pytest

import isovdb
from conftest import run_cli


def test_spe9_permx_is_manifold_with_normals(data_dir):
    deck = data_dir / "reservoir" / "spe9" / "SPE9_CP.DATA"
    mesh = isovdb.extract_reservoir(deck, property="PERMX", iso=100)
    assert mesh.triangles.shape[0] > 1000
    assert mesh.normals is not None and mesh.normals.shape == mesh.vertices.shape
    assert np.allclose(np.linalg.norm(mesh.normals, axis=1), 1, atol=1e-3)
    report = mesh.check()
    assert report["non_manifold_edges"] == 0
    refined = isovdb.extract_reservoir(deck, property="PERMX", iso=100, tessellate=4)
    assert refined.triangles.shape[0] > mesh.triangles.shape[0]
    after = refined.check()
    # Refinement splits boundary edges but opens no crack: same components, same χ.
    assert after["non_manifold_edges"] == 0
    assert (after["components"], after["euler_characteristic"]) == (report["components"],
                                                                   report["euler_characteristic"])


def test_same_bytes_as_the_cli(cli, data_dir, tmp_path):
    deck = data_dir / "reservoir" / "spe9" / "SPE9_CP.DATA"
    run_cli(cli, "reservoir", deck, "--property", "PORO", "--iso", "0.1", "--tessellate", "max=4",
            "-o", tmp_path / "cli.ply")
    isovdb.extract_reservoir([deck], property="PORO", iso=0.1, tessellate=4).write(tmp_path / "py.ply")
    assert (tmp_path / "cli.ply").read_bytes() == (tmp_path / "py.ply").read_bytes()


def test_threads_do_not_change_the_mesh(data_dir):
    deck = data_dir / "reservoir" / "spe9" / "SPE9_CP.DATA"
    one = isovdb.extract_reservoir(deck, property="PERMX", iso=100, threads=1)
    every = isovdb.extract_reservoir(deck, property="PERMX", iso=100, threads=None)
    assert np.array_equal(one.vertices, every.vertices) and np.array_equal(one.triangles, every.triangles)
    assert np.array_equal(one.normals, every.normals)
    with pytest.raises(ValueError, match=r"^threads: expected 0 \(every core\) or more, got -1"):
        isovdb.extract_reservoir(deck, property="PERMX", iso=100, threads=-1)


def test_bad_decks(tmp_path):
    with pytest.raises(OSError):
        isovdb.extract_reservoir(tmp_path / "missing.grdecl", property="PORO", iso=0.1)
    bad = tmp_path / "bad.grdecl"
    bad.write_text("SPECGRID\n 1 1 1 1 F /\nCOORD\n 24*0 /\nZCORN\n 7*0 /\nPORO\n 1 /\n")
    with pytest.raises(ValueError, match="bad.grdecl"):
        isovdb.extract_reservoir(bad, property="PORO", iso=0.5)


def test_max_values_bounds_the_deck(data_dir):
    deck = data_dir / "reservoir" / "spe9" / "SPE9_CP.DATA"  # 24 x 25 x 15: ZCORN has 72,000 values
    with pytest.raises(ValueError, match=r"ZCORN \(72000 values\) would exceed max_values 1000"):
        isovdb.extract_reservoir(deck, property="PORO", iso=0.1, max_values=1000)
    with pytest.raises(ValueError, match="max_values 80000"):  # COORD, ZCORN and the properties together
        isovdb.extract_reservoir(deck, property="PORO", iso=0.1, max_values=80000)
    assert isovdb.extract_reservoir(deck, property="PORO", iso=0.1, max_values=10**6).triangle_count > 0
    with pytest.raises(ValueError, match="max_values"):
        isovdb.extract_reservoir(deck, property="PORO", iso=0.1, max_values=0)


def test_progress_reports_each_stage_and_raising_cancels(data_dir):
    deck = data_dir / "reservoir" / "spe9" / "SPE9_CP.DATA"
    seen = []
    isovdb.extract_reservoir(deck, property="PERMX", iso=100, tessellate=2,
                             progress=lambda stage, percent: seen.append((stage, percent)))
    stages = [stage for stage, _ in seen]
    for stage in ("read grdecl", "corner-point grid", "marching cubes", "untangle loops", "pn triangles"):
        assert stage in stages
    assert ("marching cubes", 100) in seen

    class Stop(Exception):
        pass

    def stop(stage, percent):
        if stage == "marching cubes":
            raise Stop()

    with pytest.raises(Stop):
        isovdb.extract_reservoir(deck, property="PERMX", iso=100, progress=stop)
