# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Volume: from_numpy, read_volume, to_numpy, info, write, distance_field."""
import pathlib
import re

import numpy as np
import pytest

import isovdb
from conftest import ball, torus


# --- from_numpy: kinds and values -------------------------------------------------

def test_from_numpy_mask_round_trips_through_to_numpy(sphere_mask):
    volume = isovdb.from_numpy(sphere_mask)
    assert volume.kind == "mask"
    assert volume.shape == sphere_mask.shape
    back = volume.to_numpy()
    assert back.dtype == np.bool_ and back.shape == sphere_mask.shape
    assert np.array_equal(back, sphere_mask > 0)


@pytest.mark.parametrize("dtype", [np.bool_, np.uint8, np.int8, np.uint16, np.int16, np.uint32, np.int32])
def test_integer_dtypes_become_masks(dtype, sphere_mask):
    volume = isovdb.from_numpy(sphere_mask.astype(dtype))
    assert volume.kind == "mask"
    assert volume.info()["active_voxels"] == int(sphere_mask.sum())


def test_big_endian_arrays_are_read_by_value(sphere_mask):
    values = (sphere_mask.astype(np.int32) * 300).astype(">i4")
    volume = isovdb.from_numpy(values, threshold=299)
    assert np.array_equal(volume.to_numpy(), sphere_mask > 0)


def test_threshold_selects_values_above_it():
    values = np.arange(4 * 5 * 6, dtype=np.uint16).reshape(4, 5, 6)
    volume = isovdb.from_numpy(values, threshold=100)
    assert np.array_equal(volume.to_numpy(), values > 100)


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_float_arrays_are_scalar_fields_without_threshold(dtype):
    values = np.linspace(-2, 3, 7 * 8 * 9).reshape(7, 8, 9).astype(dtype)
    volume = isovdb.from_numpy(values)
    assert volume.kind == "scalar"
    back = volume.to_numpy()
    assert back.dtype == np.float32
    assert np.allclose(back, values.astype(np.float32), atol=0)
    info = volume.info()
    assert info["min_value"] == pytest.approx(-2) and info["max_value"] == pytest.approx(3)


def test_float_array_with_threshold_is_a_mask():
    values = np.linspace(-1, 1, 6 * 6 * 6).reshape(6, 6, 6)
    volume = isovdb.from_numpy(values, threshold=0.5)
    assert volume.kind == "mask"
    assert np.array_equal(volume.to_numpy(), values > 0.5)


def test_voxel_size_and_origin_become_the_geometry(sphere_mask):
    volume = isovdb.from_numpy(sphere_mask, voxel_size=(0.5, 2.0, 3.0), origin=(10, 20, 30))
    assert volume.spacing == (0.5, 2.0, 3.0)
    assert volume.origin == (10.0, 20.0, 30.0)
    mesh = isovdb.extract(volume, method="vdb")
    lo, hi = mesh.vertices.min(axis=0), mesh.vertices.max(axis=0)
    # the ball spans x 10..32, y 6..28, z 4..26 voxels
    assert lo[0] == pytest.approx(10 + 0.5 * 10, abs=0.5) and hi[0] == pytest.approx(10 + 0.5 * 32, abs=0.5)
    assert lo[2] == pytest.approx(30 + 3.0 * 4, abs=3) and hi[2] == pytest.approx(30 + 3.0 * 26, abs=3)


# --- from_numpy: errors ---------------------------------------------------------------

@pytest.mark.parametrize("shape", [(5, 5), (5,), (2, 3, 4, 5)])
def test_not_three_dimensional_is_rejected(shape):
    with pytest.raises(ValueError, match=rf"3-D array.*{len(shape)}-D"):
        isovdb.from_numpy(np.ones(shape, np.uint8))


@pytest.mark.parametrize("dtype", [np.complex64, object, np.float128])
def test_unsupported_dtype_is_rejected(dtype):
    with pytest.raises(ValueError, match="unsupported dtype"):
        isovdb.from_numpy(np.ones((3, 3, 3), dtype))


@pytest.mark.parametrize("dtype", [np.int64, np.uint64])
def test_64_bit_labels_are_read_when_they_fit_in_int32(dtype, sphere_mask):
    labels = sphere_mask.astype(dtype) * 7  # scipy.ndimage.label hands out int64
    volume = isovdb.from_numpy(labels)
    assert volume.kind == "mask"
    assert np.array_equal(volume.to_numpy() != 0, sphere_mask != 0)
    with pytest.raises(ValueError, match="do not fit in int32"):
        isovdb.from_numpy(np.full((3, 3, 3), 2**40, np.int64))


def test_64_bit_values_beyond_int32_are_named_as_they_are():
    # A uint64 beyond int64 (negative numbers wrapped by astype) printed as -9223372036854775808 before.
    wrapped = np.zeros((3, 3, 3), np.uint64)
    wrapped[0, 0, 0] = np.uint64(2**64 - 5)
    with pytest.raises(ValueError, match=r"values in \[0, 18446744073709551611\] do not fit in int32"):
        isovdb.from_numpy(wrapped)


def test_float16_is_read_as_float32():
    field = np.linspace(-1, 1, 4 * 5 * 6).reshape(4, 5, 6)
    half = isovdb.from_numpy(field.astype(np.float16))
    single = isovdb.from_numpy(field.astype(np.float16).astype(np.float32))
    assert half.kind == single.kind == "scalar"
    assert np.array_equal(half.to_numpy(), single.to_numpy())


@pytest.mark.parametrize("make_view", [lambda a: a.T.T.copy(order="F"), lambda a: a[:, ::2, :], np.asfortranarray])
def test_any_memory_layout_reads_as_its_values(make_view, sphere_mask):
    # Fortran order (a [z, y, x] stack's transpose, x fastest like a raw file) is read in
    # place; other layouts are copied first. Either way the volume holds the array's values.
    view = make_view(sphere_mask)
    assert not view.flags.c_contiguous
    expected = isovdb.from_numpy(np.ascontiguousarray(view))
    got = isovdb.from_numpy(view)
    figures = lambda v: {k: x for k, x in v.info().items() if k != "input"}  # noqa: E731
    assert figures(got) == figures(expected)
    assert np.array_equal(got.to_numpy(), expected.to_numpy())


def test_a_transposed_stack_gives_the_same_mesh_as_its_copy():
    z, y, x = np.mgrid[0:20, 0:24, 0:28]
    stack = ((x - 13.5) ** 2 + (y - 11.2) ** 2 + (z - 9.7) ** 2 < 40).astype(np.uint8)  # indexed [z, y, x]
    assert stack.T.flags.f_contiguous
    a = isovdb.extract(stack.T, method="regular")
    b = isovdb.extract(np.ascontiguousarray(stack.T), method="regular")
    assert np.array_equal(a.vertices, b.vertices) and np.array_equal(a.triangles, b.triangles)


def test_non_finite_sample_of_a_fortran_array_is_named_by_its_index():
    field = np.zeros((4, 5, 6), np.float32, order="F")
    field[3, 1, 2] = np.nan
    with pytest.raises(ValueError, match=r"sample \[3, 1, 2\] is NaN"):
        isovdb.from_numpy(field)


def test_spacing_is_voxel_size_under_read_volumes_name(sphere_mask):
    assert isovdb.from_numpy(sphere_mask, spacing=(1, 2, 3)).spacing == (1, 2, 3)
    with pytest.raises(ValueError, match="not both"):
        isovdb.from_numpy(sphere_mask, voxel_size=2.0, spacing=(1, 2, 3))
    # Errors name the keyword given (extract takes spacing= only).
    with pytest.raises(ValueError, match="^spacing: expected finite values > 0"):
        isovdb.extract(sphere_mask, spacing=(1, -1, 1))
    with pytest.raises(ValueError, match="^voxel_size: expected finite values > 0"):
        isovdb.from_numpy(sphere_mask, voxel_size=0.0)


def test_nested_lists_are_read_as_numpy_reads_them(sphere_mask):
    # scikit-image's marching_cubes takes any array_like.
    from_list = isovdb.extract(sphere_mask.tolist())
    assert np.array_equal(from_list.vertices, isovdb.extract(sphere_mask).vertices)
    with pytest.raises(ValueError, match="expected a numpy array, got dict"):
        isovdb.from_numpy({})


@pytest.mark.parametrize("shape", [(0, 4, 4), (4, 0, 4), (4, 4, 0)])
def test_empty_array_is_rejected(shape):
    with pytest.raises(ValueError, match="empty array"):
        isovdb.from_numpy(np.zeros(shape, np.uint8))


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_samples_are_rejected(bad):
    values = np.zeros((6, 7, 8), np.float32)
    values[2, 3, 4] = bad
    with pytest.raises(ValueError, match=r"sample \[2, 3, 4\] is (NaN|infinite)"):
        isovdb.from_numpy(values)
    with pytest.raises(ValueError, match="sample"):
        isovdb.from_numpy(values, threshold=0.5)


def test_non_arrays_and_bad_voxel_sizes_are_rejected(sphere_mask):
    with pytest.raises(ValueError, match="expected a numpy array"):
        isovdb.from_numpy("[[[1]]]")
    with pytest.raises(ValueError, match="voxel_size"):
        isovdb.from_numpy(sphere_mask, voxel_size=0)
    with pytest.raises(ValueError, match="voxel_size"):
        isovdb.from_numpy(sphere_mask, voxel_size=(1, 2))


# --- to_numpy, info ----------------------------------------------------------------------

def test_to_numpy_box_is_inclusive_and_reads_outside_as_background(sphere_mask):
    volume = isovdb.from_numpy(sphere_mask)
    part = volume.to_numpy(((5, 6, 7), (20, 30, 40)))
    assert part.shape == (16, 25, 34)
    assert np.array_equal(part[:, :, :25], sphere_mask[5:21, 6:31, 7:32] > 0)
    assert not part[:, :, 25:].any()  # beyond the array: outside
    with pytest.raises(ValueError, match="empty box"):
        volume.to_numpy(((5, 5, 5), (4, 9, 9)))


def test_info_reports_the_grid(sphere_mask):
    info = isovdb.from_numpy(sphere_mask).info()
    nz = np.argwhere(sphere_mask)
    assert info["kind"] == "mask"
    assert info["active_voxels"] == len(nz)
    assert info["bbox_min"] == nz.min(axis=0).tolist() and info["bbox_max"] == nz.max(axis=0).tolist()
    assert info["sampled_min"] == [0, 0, 0] and info["sampled_max"] == [39, 35, 31]
    assert info["input"]["format"] == "numpy" and info["input"]["dims"] == [40, 36, 32]
    assert info["leaf_nodes"] > 0 and info["grid_memory_bytes"] > 0


@pytest.mark.parametrize("method", ["regular", "adaptive", "vdb"])
def test_empty_volume_has_no_active_voxels_and_no_surface(tmp_path, method):
    volume = isovdb.from_numpy(np.zeros((8, 8, 8), np.uint8))
    assert volume.info()["active_voxels"] == 0
    assert not volume.to_numpy().any()
    # scikit-image raises where it finds no surface; so does extract(), naming why.
    with pytest.raises(ValueError, match="no surface: the mask has no voxel inside"):
        isovdb.extract(volume, method=method)
    # Written to a file, the empty mesh is the result, as the CLI writes it for batch runs.
    stats = isovdb.extract(volume, method=method, output=tmp_path / "empty.ply")
    assert stats["contour"]["triangles"] == 0 and isovdb.read_mesh(tmp_path / "empty.ply").triangle_count == 0


# --- read_volume ------------------------------------------------------------------------

def test_raw_file_reads_as_from_numpy(tmp_path, sphere_mask):
    raw = tmp_path / "ball.raw"
    sphere_mask.T.tofile(raw)  # x fastest, as raw files are
    volume = isovdb.read_volume(raw, dims=sphere_mask.shape, dtype="uint8", spacing=(1, 2, 3))
    assert volume.kind == "mask" and volume.spacing == (1.0, 2.0, 3.0)
    assert np.array_equal(volume.to_numpy(), isovdb.from_numpy(sphere_mask).to_numpy())
    assert volume.info()["input"]["format"] == "dense"


def test_big_endian_raw_and_scalar_keyword(tmp_path):
    values = np.arange(3 * 4 * 5, dtype=">u2").reshape(3, 4, 5)
    raw = tmp_path / "v.raw"
    values.T.tofile(raw)
    volume = isovdb.read_volume(raw, dims=(3, 4, 5), dtype=">u2", scalar=True)
    assert volume.kind == "scalar"
    assert np.array_equal(volume.to_numpy(), values.astype(np.float32))


def test_frog_labels(data_dir):
    volume = isovdb.read_volume(data_dir / "frog" / "frogtissue.mhd", labels=[13])
    info = volume.info()
    assert volume.kind == "mask" and info["input"]["mask_rule"] == "label in {13}"
    assert volume.shape == tuple(info["input"]["dims"])
    assert 0 < info["active_voxels"] < np.prod(volume.shape)


def test_read_volume_errors(tmp_path):
    with pytest.raises(OSError, match="no such file"):
        isovdb.read_volume(tmp_path / "missing.nrrd")
    bad = tmp_path / "bad.nrrd"
    bad.write_text("NRRD0004\ntype: banana\n\n")
    with pytest.raises(ValueError, match="bad.nrrd"):
        isovdb.read_volume(bad)
    raw = tmp_path / "short.raw"
    raw.write_bytes(bytes(999))
    with pytest.raises(ValueError, match="999 bytes"):
        isovdb.read_volume(raw, dims=(10, 10, 10), dtype=np.uint8)
    with pytest.raises(ValueError, match="dims"):
        isovdb.read_volume(raw, dims=(10, 10, 10))
    with pytest.raises(ValueError, match="exclude"):
        isovdb.read_volume(raw, dims=(9, 11, 10), dtype="u1", threshold=1, mask="above 2")


def test_progress_callback_raising_stops_reading(data_dir):
    class Stop(Exception):
        pass

    def progress(stage, percent):
        raise Stop(stage)

    with pytest.raises(Stop):
        isovdb.read_volume(data_dir / "frog" / "frogtissue.mhd", labels=[13], progress=progress)


# --- write / .vdb ------------------------------------------------------------------------

def test_vdb_and_dense_files_round_trip(tmp_path, sphere_mask):
    volume = isovdb.from_numpy(sphere_mask, voxel_size=0.5)
    volume.write(tmp_path / "m.vdb")
    back = isovdb.read_volume(tmp_path / "m.vdb")
    assert back.kind == "mask" and back.spacing == (0.5, 0.5, 0.5)
    assert np.array_equal(back.to_numpy(), volume.to_numpy())

    sdf = isovdb.distance_field(volume)
    sdf.write(tmp_path / "s.vdb", grid_name="salt")
    back = isovdb.read_volume(tmp_path / "s.vdb", grid="salt")
    assert back.kind == sdf.kind
    assert np.allclose(back.to_numpy(), sdf.to_numpy(), atol=1e-5)

    volume.write(tmp_path / "m.nrrd")
    dense = isovdb.read_volume(tmp_path / "m.nrrd", threshold=0.5)
    assert np.array_equal(dense.to_numpy(), sphere_mask > 0)


def test_write_errors(tmp_path, sphere_mask):
    volume = isovdb.from_numpy(sphere_mask)
    with pytest.raises(ValueError, match="unknown volume format"):
        volume.write(tmp_path / "m.png")
    with pytest.raises(OSError):
        volume.write(tmp_path / "no" / "such" / "dir" / "m.vdb")
    volume.write(tmp_path / "m.vdb")
    with pytest.raises(ValueError, match="nope"):
        isovdb.read_volume(tmp_path / "m.vdb", grid="nope")


# --- distance_field ---------------------------------------------------------------------

def test_distance_field_is_negative_inside_and_banded(sphere_mask):
    mask = isovdb.from_numpy(sphere_mask)
    sdf = isovdb.distance_field(mask, half_width=4)
    assert sdf.kind == "distance field"
    values = sdf.to_numpy(((0, 0, 0), (39, 35, 31)))
    inside = sphere_mask > 0
    assert (values[inside] < 0).all() and (values[~inside] > 0).all()
    assert values.min() == pytest.approx(-4) and values.max() == pytest.approx(4)
    # the centre is 11 voxels deep: beyond the band, it reads -half_width
    assert values[21, 17, 15] == pytest.approx(-4)
    # next to the surface the distance is about half a voxel
    assert abs(values[21 + 10, 17, 15]) < 1.0


def test_distance_field_keeps_the_masks_index_space(sphere_mask):
    # to_numpy() of the field covers the mask's array, so the two line up voxel for voxel.
    sdf = isovdb.distance_field(isovdb.from_numpy(sphere_mask))
    values = sdf.to_numpy()
    assert values.shape == sphere_mask.shape
    assert np.array_equal(values < 0, sphere_mask != 0)


def test_distance_field_rejects_non_masks():
    scalar = isovdb.from_numpy(np.zeros((4, 4, 4), np.float32))
    with pytest.raises(ValueError):
        isovdb.distance_field(scalar)


# --- euler_characteristic ------------------------------------------------------------------

def test_euler_characteristic_of_solids_and_their_meshes():
    shape = (40, 40, 24)
    ring = torus(shape, (20, 20, 12), 12, 5)
    two_balls = ball(shape, (10, 10, 12), 6) | ball(shape, (30, 30, 12), 6)
    hollow = ball(shape, (20, 20, 12), 10) & ~ball(shape, (20, 20, 12), 5)  # a ball with a cavity: chi 2
    for array, expected in ((ring, 0), (two_balls, 2), (hollow, 2), (ball(shape, (20, 20, 12), 9), 1)):
        volume = isovdb.from_numpy(array)
        assert isovdb.euler_characteristic(volume) == expected
        assert isovdb.euler_characteristic(isovdb.distance_field(volume)) == expected
        mesh = isovdb.extract(volume, method="regular")
        assert mesh.check()["euler_characteristic"] == 2 * expected


def test_euler_characteristic_adjacency_and_errors():
    diagonal = np.zeros((4, 4, 4), np.uint8)
    diagonal[1, 1, 1] = diagonal[2, 2, 2] = 1  # two voxels touching at a corner
    volume = isovdb.from_numpy(diagonal)
    assert isovdb.euler_characteristic(volume, adjacency=26) == 1
    assert isovdb.euler_characteristic(volume, adjacency=6) == 2
    with pytest.raises(ValueError, match="adjacency"):
        isovdb.euler_characteristic(volume, adjacency=18)
    with pytest.raises(ValueError, match="scalar"):
        isovdb.euler_characteristic(isovdb.from_numpy(np.zeros((3, 3, 3), np.float32)))


def test_volumes_of_every_kind_pickle_and_deep_copy(sphere_mask, data_dir):
    import copy
    import pickle
    mask = isovdb.from_numpy(sphere_mask, voxel_size=(1, 2, 3), origin=(5, 6, 7))
    sdf = isovdb.distance_field(isovdb.from_numpy(sphere_mask, voxel_size=0.5, origin=(5, 6, 7)))
    volumes = [mask, sdf, isovdb.from_numpy(sphere_mask.astype(np.float32) - 0.5),
               isovdb.read_segy(data_dir / "seismic" / "f3.sgy", clip=1000)]
    for volume in volumes:
        for clone in (pickle.loads(pickle.dumps(volume)), copy.deepcopy(volume)):
            assert (clone.kind, clone.name, clone.spacing, clone.origin) == \
                (volume.kind, volume.name, volume.spacing, volume.origin)
            assert clone.info() == volume.info()
            assert np.array_equal(clone.to_numpy(), volume.to_numpy())
    a, b = isovdb.extract(mask, method="regular"), isovdb.extract(pickle.loads(pickle.dumps(mask)), method="regular")
    assert np.array_equal(a.vertices, b.vertices) and np.array_equal(a.triangles, b.triangles)
    # A level set needs uniform voxels: an anisotropic distance field says so.
    with pytest.raises(ValueError, match="cannot be pickled: a distance field with a non-uniform voxel size"):
        pickle.dumps(isovdb.distance_field(mask))


def test_a_wrong_keyword_is_named_without_printing_the_array(sphere_mask):
    with pytest.raises(TypeError, match="unexpected keyword argument 'level'") as raised:
        isovdb.from_numpy(sphere_mask, level=3)
    assert len(str(raised.value)) < 200


def test_kind_overrides_the_dtypes_guess():
    # An integer CT array is a mask by its dtype; kind="field" contours its values, and a
    # float array becomes a mask (value > threshold) with kind="mask".
    z, y, x = np.mgrid[0:32, 0:32, 0:32]
    inside = (x - 15.5) ** 2 + (y - 16.0) ** 2 + (z - 15.0) ** 2 < 10.0 ** 2
    ct = np.where(inside, 1200, 200).astype(np.uint16)
    assert isovdb.from_numpy(ct).kind == "mask"
    field = isovdb.from_numpy(ct, kind="field")
    assert field.kind == "scalar"
    mesh = isovdb.extract(field, iso=500.0)
    assert mesh.check()["closed"] and mesh.volume == pytest.approx(4 / 3 * np.pi * 10.0 ** 3, rel=0.06)
    as_float = isovdb.from_numpy(ct.astype(np.float32), kind="mask", threshold=700.0)
    assert as_float.kind == "mask" and np.array_equal(as_float.to_numpy(), inside)
    with pytest.raises(ValueError, match="kind: expected None"):
        isovdb.from_numpy(ct, kind="sdf")
    with pytest.raises(ValueError, match="a threshold makes a mask"):
        isovdb.from_numpy(ct, kind="field", threshold=3.0)


@pytest.mark.parametrize("method", ["adaptive", "regular", "vdb"])
def test_kind_distance_reads_a_dense_signed_distance_array(method):
    # scikit-fmm's and OpenVDB's convention: negative inside, in world units (voxel 0.5 here).
    h, radius, center = 0.5, 9.0, np.array([12.2, 11.9, 12.4])
    grid = np.indices((48, 48, 48)).transpose(1, 2, 3, 0) * h
    sdf = np.linalg.norm(grid - center, axis=-1) - radius
    volume = isovdb.from_numpy(sdf, kind="distance", voxel_size=h)
    assert volume.kind == "distance field"
    values = volume.to_numpy()
    # Values in voxels, the band cut at 3 voxels each side.
    assert values.min() >= -3.0 and values.max() <= 3.0
    near = np.abs(sdf) < 1.0
    assert np.allclose(values[near], sdf[near] / h, atol=1e-5)
    mesh = isovdb.extract(volume, method=method)
    check = mesh.check()
    assert check["closed"] and check["manifold"] and check["components"] == 1
    distance = np.linalg.norm(mesh.vertices - center, axis=1)
    # Adaptive mode's coarse cells stay within its error bound, max_error=1 voxel.
    assert np.abs(distance - radius).max() < (1.0 if method == "adaptive" else 0.1) * h
    # Positive: outward. Adaptive mode's mesh lies in the shell within max_error (1 voxel) of the
    # sphere, whose volume is 3 max_error / radius of the ball's.
    shell = 3 * 1.0 * h / radius if method == "adaptive" else 0.01
    assert mesh.volume == pytest.approx(4 / 3 * np.pi * radius ** 3, rel=shell)


def test_kind_distance_keeps_the_object_beyond_the_array_outside_and_checks_its_voxels():
    # A ball cut by the array's end: capped where the data ends, as other fields are.
    x, y, z = np.mgrid[0:24, 0:24, 0:24].astype(float)  # from_numpy's arrays are indexed [x, y, z]
    sdf = np.sqrt((x - 4.0) ** 2 + (y - 12.0) ** 2 + (z - 12.0) ** 2) - 8.0
    mesh = isovdb.extract(isovdb.from_numpy(sdf, kind="distance"))
    assert mesh.check()["closed"] and mesh.volume > 0
    assert mesh.bounds[0][0] == pytest.approx(0.0, abs=0.01) and mesh.bounds[1][0] == pytest.approx(12.0, abs=0.05)
    with pytest.raises(ValueError, match="same voxel size"):
        isovdb.from_numpy(sdf, kind="distance", voxel_size=(1, 1, 2))
    with pytest.raises(ValueError, match="a threshold makes a mask"):
        isovdb.from_numpy(sdf, kind="distance", threshold=0.0)


@pytest.mark.parametrize("finding, message", [
    ("finding_raw_chunk_overflow_topology.vdb", "damaged compressed data: a raw chunk of 70368744177664000 bytes"),
    ("finding_truncated_chunk_length.vdb", "damaged compressed data: the data ends before a chunk's length"),
    ("finding_delayed_load_count.vdb", "a delayed-load table of 1493172228 leaves"),
])
def test_damaged_vdb_files_are_refused_inside_the_module_too(finding, message):
    # The chunk guard (lib/vdb_chunk_guard) replaces OpenVDB's reading functions for calls
    # made from this shared module and from the OpenVDB library it loads: without it the
    # first file overflows the heap (fuzz_vdb findings, fuzz/README.md).
    path = pathlib.Path(__file__).resolve().parents[2] / "fuzz" / "corpus" / "vdb" / finding
    if not path.exists():
        pytest.skip(f"{path} is not in this tree")
    with pytest.raises(ValueError, match=re.escape(message)):
        isovdb.read_volume(path)


def test_read_volume_reads_nifti_in_world_space_and_names_it_once(data_dir):
    # pynrrd's ball written by ITK as NIfTI (x and y flipped into RAS) and as NRRD (LPS).
    path = str(data_dir / "nifti" / "BallBinary30x30x30.nii.gz")
    nifti = isovdb.read_volume(path)
    nrrd = isovdb.read_volume(str(data_dir / "nrrd" / "BallBinary30x30x30_gz.nrrd"))
    assert repr(nifti) == "<isovdb.Volume mask '" + path + "' shape (30, 30, 30)>"
    assert nifti.to_numpy().sum() == nrrd.to_numpy().sum() == 14328
    mesh = isovdb.extract(nifti)
    report = mesh.check()
    assert report["closed"] and report["manifold"] and report["self_intersecting_pairs"] == 0
    lo, hi = mesh.bounds
    assert lo[0] < -28.9 and hi[0] < 0.01  # x runs over world [-29, 0]
