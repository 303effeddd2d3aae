# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Interoperation with Debian's pyopenvdb through .vdb files, both ways."""
import numpy as np
import pytest

import isovdb
from conftest import ball

vdb = pytest.importorskip("pyopenvdb")


def test_isovdb_sdf_reads_in_pyopenvdb_as_a_world_unit_level_set(tmp_path):
    mask = isovdb.from_numpy(ball((30, 30, 30), (15, 15, 15), 9), voxel_size=0.25)
    sdf = isovdb.distance_field(mask)
    sdf.write(tmp_path / "s.vdb", grid_name="ball")
    grid = vdb.read(str(tmp_path / "s.vdb"), "ball")
    assert grid.gridClass == vdb.GridClass.LEVEL_SET
    assert grid.transform.voxelSize()[0] == pytest.approx(0.25)
    (lo, hi) = sdf.info()["bbox_min"], sdf.info()["bbox_max"]
    dense = np.zeros([h - l + 1 for l, h in zip(lo, hi)], np.float32)
    grid.copyToArray(dense, ijk=lo)
    # isovdb keeps voxels inside; the file holds world units (x voxel size)
    assert np.allclose(dense, sdf.to_numpy(bbox=(lo, hi)) * 0.25, atol=1e-6)


def test_isovdb_mask_reads_in_pyopenvdb(tmp_path):
    array = ball((20, 22, 24), (9, 10, 11), 6)
    isovdb.from_numpy(array).write(tmp_path / "m.vdb")
    grid = vdb.readAll(str(tmp_path / "m.vdb"))[0][0]
    dense = np.zeros(array.shape, np.bool_)
    grid.copyToArray(dense)
    assert np.array_equal(dense, array)


def test_pyopenvdb_level_set_reads_and_meshes_in_isovdb(tmp_path):
    grid = vdb.createLevelSetSphere(radius=3.0, center=(1, 2, 3), voxelSize=0.2, halfWidth=3.0)
    grid.name = "sphere"
    vdb.write(str(tmp_path / "sphere.vdb"), grids=[grid])
    volume = isovdb.read_volume(tmp_path / "sphere.vdb")
    assert volume.kind == "distance field" and volume.spacing == pytest.approx((0.2, 0.2, 0.2))
    mesh = isovdb.extract(volume, method="regular")
    report = mesh.check()
    assert report["closed"] and report["euler_characteristic"] == 2
    radii = np.linalg.norm(mesh.vertices - np.array([1, 2, 3], np.float32), axis=1)
    assert np.allclose(radii, 3.0, atol=0.05)


def test_pyopenvdb_float_grid_round_trips_through_isovdb(tmp_path):
    values = np.random.default_rng(7).normal(size=(12, 10, 8)).astype(np.float32)
    grid = vdb.FloatGrid()
    grid.copyFromArray(values)
    grid.name = "noise"
    vdb.write(str(tmp_path / "noise.vdb"), grids=[grid])
    volume = isovdb.read_volume(tmp_path / "noise.vdb", grid="noise")
    assert volume.kind == "scalar"
    assert np.array_equal(volume.to_numpy(((0, 0, 0), (11, 9, 7))), values)
    volume.write(tmp_path / "again.vdb", grid_name="again")
    back = vdb.read(str(tmp_path / "again.vdb"), "again")
    dense = np.zeros_like(values)
    back.copyToArray(dense)
    assert np.array_equal(dense, values)


def test_streamed_distance_field_reads_in_pyopenvdb_like_the_in_memory_one(tmp_path):
    # distance_field(output=...) writes the band chunk by chunk (isovdb sdf's path):
    # pyopenvdb must read the same level set as from the grid written in memory.
    mask = isovdb.from_numpy(ball((40, 36, 44), (20, 18, 22), 13), voxel_size=0.5)
    stats = isovdb.distance_field(mask, sdf_chunk=16, output=tmp_path / "streamed.vdb", grid_name="ball")
    assert stats["distance_field"]["streamed_to_file"] is True
    isovdb.distance_field(mask, sdf_chunk=16).write(tmp_path / "memory.vdb", grid_name="ball")
    streamed = vdb.read(str(tmp_path / "streamed.vdb"), "ball")
    memory = vdb.read(str(tmp_path / "memory.vdb"), "ball")
    assert streamed.gridClass == vdb.GridClass.LEVEL_SET
    assert streamed.activeVoxelCount() == memory.activeVoxelCount() == stats["distance_field"]["active_voxels"]
    assert streamed.leafCount() == memory.leafCount() == stats["distance_field"]["leaf_nodes"]
    # every voxel of the box and a margin: band values and the signs of the rest
    shape = (56, 52, 60)
    a, b = np.zeros(shape, np.float32), np.zeros(shape, np.float32)
    streamed.copyToArray(a, ijk=(-8, -8, -8))
    memory.copyToArray(b, ijk=(-8, -8, -8))
    assert np.array_equal(a, b)
    assert (a < 0).sum() > 0 and (a > 0).sum() > 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["memory.vdb", "streamed.vdb"]


def test_streamed_distance_field_rejects_non_masks(tmp_path):
    sdf = isovdb.distance_field(isovdb.from_numpy(ball((20, 20, 20), (10, 10, 10), 6)))
    with pytest.raises(ValueError, match="made from a mask"):
        isovdb.distance_field(sdf, output=tmp_path / "s.vdb")
    assert not (tmp_path / "s.vdb").exists()


def test_a_pyopenvdb_grid_is_taken_wherever_a_volume_is():
    # extract() and distance_field() take pyopenvdb grids as they take numpy arrays (from_openvdb).
    grid = vdb.createLevelSetSphere(radius=3.0, center=(1, 2, 3), voxelSize=0.2, halfWidth=3.0)
    grid.name = "sphere"
    volume = isovdb.from_openvdb(grid)
    assert volume.kind == "distance field" and volume.spacing == pytest.approx((0.2, 0.2, 0.2))
    mesh = isovdb.extract(grid, method="adaptive")
    assert np.array_equal(mesh.triangles, isovdb.extract(volume, method="adaptive").triangles)
    assert mesh.check()["closed"] and mesh.volume == pytest.approx(4 / 3 * np.pi * 27, rel=0.03)
    array = ball((20, 22, 24), (9, 10, 11), 6)
    mask = vdb.BoolGrid()
    mask.copyFromArray(array)  # unnamed: the file's first grid
    assert isovdb.from_openvdb(mask).kind == "mask"
    assert isovdb.distance_field(mask).kind == "distance field"
    vectors = vdb.Vec3SGrid()
    vectors.name = "velocity"
    vectors.copyFromArray(np.ones((4, 4, 4, 3), np.float32))
    with pytest.raises(ValueError, match="from_openvdb: Vec3SGrid 'velocity': "):
        isovdb.from_openvdb(vectors)
