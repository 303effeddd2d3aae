# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""extract: methods, options, guarantees, threads, progress, GIL."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import isovdb
from conftest import ball, torus


@pytest.fixture(scope="module")
def torus_volume():
    return isovdb.from_numpy(torus((48, 48, 24), (24, 24, 12), 14, 6))


@pytest.mark.parametrize("method", ["adaptive", "regular", "vdb"])
def test_every_method_gives_a_closed_genus_one_torus(method, torus_volume):
    mesh = isovdb.extract(torus_volume, method=method, meta_cell=16)
    report = mesh.check()
    assert report["closed"] and report["manifold"]
    assert report["components"] == 1 and report["euler_characteristic"] == 0
    assert report["largest_components"][0]["genus"] == 1
    assert mesh.statistics["contour"]["triangles"] == mesh.triangle_count


@pytest.mark.parametrize("method", ["adaptive", "regular", "vdb"])
def test_every_method_faces_outward_on_masks_and_scalars(method, torus_volume):
    # Counter-clockwise seen from outside: a body's signed volume is positive, a cavity's negative.
    assert isovdb.extract(torus_volume, method=method).check()["signed_volume"] > 0
    z, y, x = np.mgrid[0:40, 0:40, 0:40]
    r = np.sqrt((x - 19.6) ** 2 + (y - 20.3) ** 2 + (z - 19.8) ** 2).astype(np.float32)
    body = isovdb.extract(isovdb.from_numpy(12.0 - r), method=method, iso=0.5).check()
    assert body["closed"] and body["signed_volume"] > 0
    # High outside: the inside (value > iso) surrounds the ball, whose surface faces into it.
    cavity = isovdb.extract(isovdb.from_numpy(r), method=method, iso=12.0, boundary="open").check()
    assert cavity["closed"] and cavity["signed_volume"] < 0


def test_render_draws_the_mesh(torus_volume, tmp_path):
    mesh = isovdb.extract(torus_volume, method="adaptive")
    picture = mesh.render(tmp_path / "torus.png", width=320, height=240)
    assert picture.shape == (240, 320, 3) and picture.dtype == np.uint8
    drawn = (picture != picture[0, 0]).any(axis=2)
    assert 0.05 < drawn.mean() < 0.9  # the torus, fitted into the picture
    assert (tmp_path / "torus.png").read_bytes().startswith(b"\x89PNG")


def test_adaptive_uses_far_fewer_triangles_than_regular(torus_volume):
    regular = isovdb.extract(torus_volume, method="regular")
    adaptive = isovdb.extract(torus_volume, method="adaptive")
    assert adaptive.triangle_count * 2 < regular.triangle_count
    assert adaptive.check()["self_intersecting_pairs"] == 0


def test_octree_levels_change_the_mesh(torus_volume):
    fine = isovdb.extract(torus_volume, method="regular")
    coarse = isovdb.extract(torus_volume, method="regular", finest_size=2)
    assert coarse.triangle_count < fine.triangle_count
    # Without the error bound, which on this thin torus refines to 2 voxels either way.
    capped = isovdb.extract(torus_volume, method="adaptive", max_cell_size=2, max_error=0)
    loose = isovdb.extract(torus_volume, method="adaptive", max_cell_size=16, max_error=0)
    assert capped.triangle_count > loose.triangle_count
    plain = isovdb.extract(torus_volume, method="adaptive", intersection_free=False, max_error=0)
    assert plain.triangle_count <= loose.triangle_count


def test_meta_cells_and_threads_do_not_change_the_mesh(torus_volume):
    one = isovdb.extract(torus_volume, method="adaptive", meta_cell=16, threads=1)
    many = isovdb.extract(torus_volume, method="adaptive", meta_cell=16, threads=None)
    assert np.array_equal(one.vertices, many.vertices)
    assert np.array_equal(one.triangles, many.triangles)
    assert one.statistics["meta_cells"]["contoured"] > 1


def test_sharp_features_reach_the_octree_and_keep_the_guarantees(torus_volume):
    one = isovdb.extract(torus_volume, method="adaptive", sharp_features=True, meta_cell=16, threads=1)
    many = isovdb.extract(torus_volume, method="adaptive", sharp_features=True, meta_cell=16, threads=None)
    assert one.statistics["meta_cells"]["sharp_features"]
    assert np.array_equal(one.vertices, many.vertices)
    assert np.array_equal(one.triangles, many.triangles)
    report = one.check()
    assert report["closed"]
    assert report["self_intersecting_pairs"] == 0


def test_iso_grows_the_surface(torus_volume):
    base = isovdb.extract(torus_volume, method="vdb")
    grown = isovdb.extract(torus_volume, method="vdb", iso=1.5)
    assert np.ptp(grown.vertices[:, 0]) > np.ptp(base.vertices[:, 0]) + 2


def test_scalar_field_is_contoured_at_iso():
    x, y, z = np.indices((32, 32, 32)).astype(np.float32)
    field = 10.0 - np.sqrt((x - 16) ** 2 + (y - 16) ** 2 + (z - 16) ** 2)  # inside: >= iso
    mesh = isovdb.extract(isovdb.from_numpy(field), method="regular", iso=2.0)
    radii = np.linalg.norm(mesh.vertices - 16, axis=1)
    assert np.allclose(radii, 8.0, atol=0.1)
    assert mesh.check()["closed"]


def test_sdf_input_gives_the_same_mesh_as_its_mask():
    mask = isovdb.from_numpy(ball((30, 30, 30), (15, 15, 15), 9))
    direct = isovdb.extract(mask, method="regular")
    via_sdf = isovdb.extract(isovdb.distance_field(mask), method="regular")
    assert np.array_equal(direct.vertices, via_sdf.vertices)


def test_regular_topology_follows_the_voxels_of_a_mask():
    # Random voxels: face-diagonal bridges and vertex contacts everywhere.
    rng = np.random.default_rng(7)
    voxels = np.zeros((20, 20, 20), np.uint8)
    voxels[1:-1, 1:-1, 1:-1] = rng.random((18, 18, 18)) < 0.35
    mask = isovdb.from_numpy(voxels)
    solid = isovdb.euler_characteristic(mask)
    assert isovdb.euler_characteristic(voxels) == solid  # an array, as extract() takes it
    assert isovdb.euler_characteristic(voxels.astype(np.float32), threshold=0.5) == solid
    meshes = {t: isovdb.extract(mask, method="regular", topology=t) for t in ("auto", "voxels", "mdmc")}
    for topology, mesh in meshes.items():
        report = mesh.check(self_intersections=False)
        assert report["closed"] and report["manifold"], topology
    assert meshes["voxels"].check(self_intersections=False)["euler_characteristic"] == 2 * solid
    assert meshes["mdmc"].check(self_intersections=False)["euler_characteristic"] != 2 * solid
    assert np.array_equal(meshes["auto"].triangles, meshes["voxels"].triangles)  # auto: voxels for a mask
    assert meshes["voxels"].statistics["meta_cells"]["topology"] == "voxels"
    assert meshes["voxels"].statistics["meta_cells"]["tube_cells"] > 0


def test_boundary_open_leaves_the_mesh_open_on_the_sampled_box():
    cut = np.zeros((20, 20, 20), np.uint8)
    cut[:8, 5:15, 5:15] = 1  # touches the x = 0 face
    capped = isovdb.extract(isovdb.from_numpy(cut), method="regular")
    opened = isovdb.extract(isovdb.from_numpy(cut), method="regular", boundary="open")
    assert capped.check()["closed"]
    report = opened.check()
    assert not report["closed"] and report["boundary_edges"] > 0
    # The cap lies on the face x = 0, made while contouring within 2e-3 voxel beyond it.
    x = capped.vertices[:, 0]
    assert np.count_nonzero(x < 0.0) > 0 and x.min() >= -2.001e-3
    # The cap's triangles are gone; the open rim runs through its vertices, beside the face.
    assert not np.any(np.all(opened.vertices[opened.triangles][:, :, 0] < 0.0, axis=1))
    assert opened.vertices[:, 0].min() >= -2.001e-3 and len(opened.triangles) < len(capped.triangles)


@pytest.mark.parametrize("kwargs, message", [
    ({"method": "marching"}, "unknown method"),
    ({"boundary": "wrap"}, "unknown mode"),
    ({"topology": "digital"}, "unknown reading"),
    ({"meta_cell": 100}, "meta"),
    ({"threads": -2}, "threads"),
    ({"inside": "sideways"}, "inside: unknown side 'sideways', expected above or below"),
])
def test_invalid_options_raise_value_error(kwargs, message, torus_volume):
    with pytest.raises(ValueError, match=message) as raised:
        isovdb.extract(torus_volume, **kwargs)
    assert "--" not in str(raised.value), "messages name keywords, not CLI flags"


def test_messages_name_keywords_not_flags(torus_volume, tmp_path):
    with pytest.raises(ValueError, match=r"^meta_cell: expected a power of two"):
        isovdb.extract(torus_volume, meta_cell=3)
    (tmp_path / "volume.raw").write_bytes(bytes(64))
    with pytest.raises(ValueError, match=r"\bdims\b.*\bdtype\b") as raised:
        isovdb.read_volume(tmp_path / "volume.raw")
    assert "--" not in str(raised.value)


def test_a_numpy_array_is_read_by_from_numpy():
    mask = ball((24, 24, 24), (12, 12, 12), 8)
    a = isovdb.extract(mask, method="regular")
    b = isovdb.extract(isovdb.from_numpy(mask), method="regular")
    assert np.array_equal(a.vertices, b.vertices) and np.array_equal(a.triangles, b.triangles)


@pytest.mark.parametrize("iso", [float("nan"), float("inf")])
def test_a_non_finite_iso_is_refused(iso, torus_volume):
    with pytest.raises(ValueError, match="iso: expected a finite number"):
        isovdb.extract(torus_volume, iso=iso)


def test_an_iso_outside_a_scalar_fields_values_is_refused():
    z, y, x = np.mgrid[0:32, 0:32, 0:32]
    field = (12.0 - np.sqrt((x - 16) ** 2 + (y - 16) ** 2 + (z - 16) ** 2)).astype(np.float32)
    assert isovdb.extract(field, iso=0.0).triangle_count > 0
    with pytest.raises(ValueError, match=r"iso 500 lies outside the values' range \[-15\.7.*, 12\]"):
        isovdb.extract(field, iso=500.0)


@pytest.mark.parametrize("method", ["adaptive", "regular", "vdb"])
def test_a_field_whose_background_is_inside_gives_its_body_not_a_box(method):
    # 20 - r at iso 0: the background (0, beyond the array) counts as inside, and read as it
    # is it closed a box around the array (2 components, inside out); beyond the data is
    # outside, so the ball comes back alone, and a ball leaving the array gets flat caps.
    z, y, x = np.mgrid[0:48, 0:48, 0:48]
    r = np.sqrt((x - 24.0) ** 2 + (y - 24.0) ** 2 + (z - 24.0) ** 2)
    for radius, box in ((20.0, False), (28.0, True)):
        mesh = isovdb.extract((radius - r).astype(np.float32), method=method, iso=0.0)
        report = mesh.check(self_intersections=False)
        assert report["closed"] and report["manifold"] and report["components"] == 1
        assert mesh.volume > 0
        lo, hi = mesh.bounds
        if box:
            # Caps within 2e-3 voxel beyond the box: the float nearest it, 9.5e-11 more.
            beside = 2e-3 + 1e-9
            assert min(lo) == pytest.approx(0, abs=beside) and max(hi) == pytest.approx(47, abs=beside)
        else:
            assert mesh.volume == pytest.approx(4 / 3 * np.pi * radius ** 3, rel=0.02)


@pytest.mark.parametrize("method", ["adaptive", "regular", "vdb"])
def test_inside_below_meshes_a_signed_distance_array_outward(method):
    # OpenVDB's and scikit-fmm's convention, negative inside: read with the default side
    # (inside above, like a density) it is a box around a cavity.
    z, y, x = np.mgrid[0:40, 0:40, 0:40]
    sdf = (np.sqrt((x - 19.5) ** 2 + (y - 20.0) ** 2 + (z - 19.0) ** 2) - 12.0).astype(np.float32)
    below = isovdb.extract(sdf, method=method, inside="below", iso=0.0)
    mirrored = isovdb.extract(-sdf, method=method, iso=0.0)
    assert np.array_equal(below.vertices, mirrored.vertices) and np.array_equal(below.triangles, mirrored.triangles)
    assert below.statistics["contour"]["inside"] == "below"
    report = below.check()
    assert report["closed"] and report["components"] == 1 and report["self_intersecting_pairs"] == 0
    assert below.volume == pytest.approx(4 / 3 * np.pi * 12.0 ** 3, rel=0.02)
    assert isovdb.extract(sdf, method=method, iso=0.0).check(self_intersections=False)["components"] == 2


def test_without_iso_a_field_is_contoured_at_the_middle_of_its_values():
    # scikit-image's rule: a CT-like field of 200 outside and 1200 inside, given no iso, meets
    # its surface at 700 (at 0, the old default, it had none); level= is iso's other name.
    z, y, x = np.mgrid[0:40, 0:40, 0:40]
    ct = (200.0 + 1000.0 * (np.sqrt((x - 19.5) ** 2 + (y - 20.0) ** 2 + (z - 19.0) ** 2) < 12.0)).astype(np.float32)
    mesh = isovdb.extract(ct)
    assert mesh.statistics["contour"]["iso"] == 700.0
    assert mesh.statistics["contour"]["iso_rule"] == "middle of the values' range"
    assert mesh.check()["closed"] and mesh.volume == pytest.approx(4 / 3 * np.pi * 12.0 ** 3, rel=0.05)
    at = isovdb.extract(ct, iso=700.0)
    assert np.array_equal(mesh.triangles, at.triangles) and "iso_rule" not in at.statistics["contour"]
    assert np.array_equal(isovdb.extract(ct, level=700.0).triangles, at.triangles)
    with pytest.raises(ValueError, match="iso= or level="):
        isovdb.extract(ct, iso=700.0, level=700.0)
    # Its errors name the keyword the caller wrote.
    with pytest.raises(ValueError, match=r"level 5000 lies outside the values' range \[200, 1200\]"):
        isovdb.extract(ct, level=5000.0)
    with pytest.raises(ValueError, match=r"iso 5000 lies outside"):
        isovdb.extract(ct, iso=5000.0)
    with pytest.raises(ValueError, match=r"^level: expected a finite number"):
        isovdb.extract(ct, level=float("nan"))
    # A mask and a distance field keep 0: their boundary.
    assert isovdb.extract(ct > 700).statistics["contour"]["iso"] == 0.0
    # A constant field has no middle: refused, naming its value, as scikit-image refuses it.
    with pytest.raises(ValueError, match=r"every value is 3, so no isovalue meets a surface \(give iso"):
        isovdb.extract(np.full((8, 8, 8), 3.0, np.float32))


def test_a_masks_iso_beyond_its_band_points_to_scalar_fields():
    # An integer CT array is a mask (value > 0): iso is then a distance in voxels, not a
    # sample value, and 500 voxels meets no distance field.
    ct = (ball((24, 24, 24), (12, 12, 12), 8) * 1000).astype(np.uint16)
    with pytest.raises(ValueError, match=r"is a mask, so iso 500 is a distance in voxels.*scalar field"):
        isovdb.extract(ct, iso=500)
    assert isovdb.extract(ct.astype(np.float32), iso=500).triangle_count > 0


def test_progress_reports_stages_and_percentages(torus_volume):
    seen = []
    isovdb.extract(torus_volume, method="adaptive", meta_cell=16, progress=lambda s, p: seen.append((s, p)))
    stages = {stage for stage, _ in seen}
    assert "contouring meta-cells" in stages
    percents = [p for s, p in seen if s == "contouring meta-cells"]
    assert percents == sorted(percents) and 0 <= percents[0] and percents[-1] == 100


def test_raising_progress_cancels_and_propagates(torus_volume):
    class Cancel(Exception):
        pass

    calls = []

    def progress(stage, percent):
        calls.append(stage)
        if stage == "contouring meta-cells":
            raise Cancel("enough")

    with pytest.raises(Cancel, match="enough"):
        isovdb.extract(torus_volume, method="regular", meta_cell=16, progress=progress)
    assert calls.count("contouring meta-cells") == 1  # nothing called after the exception
    # the module is still usable afterwards
    assert isovdb.extract(torus_volume, method="regular", meta_cell=16).check()["closed"]


@pytest.fixture(scope="module")
def big_ball():
    """A volume whose regular contouring on one thread takes a fifth of a second or more."""
    return isovdb.from_numpy(ball((256, 256, 256), (128, 128, 128), 110))


def test_gil_is_released_while_contouring(big_ball):
    ticks = []
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    thread = threading.Thread(target=ticker)
    thread.start()
    time.sleep(0.01)
    start = time.perf_counter()
    isovdb.extract(big_ball, method="regular", threads=1)
    end = time.perf_counter()
    stop.set()
    thread.join()
    during = [t for t in ticks if start < t < end]
    assert end - start > 0.1  # long enough for the ticker to tick many times
    # a thread holding the GIL would leave no tick between start and end
    assert len(during) >= 20, (end - start, len(during))


def test_ctrl_c_stops_the_work_with_keyboard_interrupt(big_ball):
    start = time.perf_counter()
    isovdb.extract(big_ball, method="regular", meta_cell=32, threads=1)
    full_run = time.perf_counter() - start
    # A process started in the background (CI runners, `cmd &`) inherits SIGINT ignored,
    # and then Python installs no handler: install the one an interactive session has.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    # The signal comes early in the run, whatever the machine's speed.
    delay = 0.2 * full_run
    timer = threading.Timer(delay, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    start = time.perf_counter()
    try:
        with pytest.raises(KeyboardInterrupt):
            isovdb.extract(big_ball, method="regular", meta_cell=32, threads=1)  # no progress callback needed
    finally:
        timer.join()
        signal.signal(signal.SIGINT, previous)
    # Stopped early: compared with a full run in the same moment, so a loaded machine
    # (ctest -j, CI) slows both alike.
    assert time.perf_counter() - start < delay + 0.5 * full_run, full_run


def test_max_error_bounds_how_far_adaptive_vertices_stray_from_a_smooth_surface():
    # The field: exp(-(r/30)^2) at 0.5 is a sphere of radius 30 sqrt(ln 2).
    # Without a bound, adaptive mode put vertices 2.9 voxels off it.
    n = 80
    x, y, z = np.mgrid[0:n, 0:n, 0:n]  # from_numpy: the first axis is x
    centre = np.array([39.3, 40.1, 38.7])
    r = np.sqrt((x - centre[0]) ** 2 + (y - centre[1]) ** 2 + (z - centre[2]) ** 2)
    field = isovdb.from_numpy(np.exp(-(r / 30.0) ** 2).astype(np.float32))
    radius = 30.0 * np.sqrt(np.log(2.0))
    counts = []
    for bound in (1.0, 0.5, 0.25):
        mesh = isovdb.extract(field, method="adaptive", iso=0.5, max_error=bound)
        assert mesh.check()["closed"]
        off = np.abs(np.linalg.norm(mesh.vertices - centre, axis=1) - radius)
        # The regular mesh itself lies within a few hundredths of the sphere.
        assert off.max() <= bound + 0.05, (bound, off.max())
        counts.append(len(mesh.triangles))
    assert counts[0] < counts[1] < counts[2]
    with pytest.raises(TypeError):
        isovdb.extract(field, method="adaptive", iso=0.5, max_error="tight")
    # NaN compares false everywhere: it would have turned the bound off without a word.
    with pytest.raises(ValueError, match="max_error: expected a number of voxels"):
        isovdb.extract(field, method="adaptive", iso=0.5, max_error=float("nan"))
    with pytest.raises(ValueError, match="qef_tolerance: expected a number of voxels"):
        isovdb.extract(field, method="adaptive", iso=0.5, qef_tolerance=float("nan"))


@pytest.mark.parametrize("method", ["regular", "adaptive"])
def test_smooth_fields_mesh_with_every_guarantee_in_both_octree_modes(method):
    # Issue #22: regular mode's quads crossed each other on smooth fields. A Gaussian
    # bump and two nearly touching ones (a thin neck), cut by meta-cells of 16.
    n = 48
    x, y, z = np.mgrid[0:n, 0:n, 0:n].astype(np.float64)
    def bump(cx, cy, cz, width):
        return np.exp(-((x - cx) ** 2 + (y - cy) ** 2 + (z - cz) ** 2) / (2.0 * width ** 2))
    fields = {
        "gaussian": bump(23.3, 24.1, 22.7, 9.0),
        "neck": bump(15.2, 24.0, 23.6, 6.0) + bump(32.1, 23.4, 24.3, 6.5),
    }
    # Six random bumps (seed 12): regular mode's plain quads (intersection_free=False)
    # cross each other there at 0.35 (2 pairs, beside the box's face z = 31).
    rng = np.random.default_rng(12)
    u, v, w = np.mgrid[0:32, 0:32, 0:32].astype(np.float64)
    bumps = np.zeros((32, 32, 32))
    for _ in range(6):
        c, width, height = rng.uniform(0, 32, 3), rng.uniform(2, 7), rng.uniform(0.5, 1.5)
        bumps += height * np.exp(-((u - c[0]) ** 2 + (v - c[1]) ** 2 + (w - c[2]) ** 2) / (2.0 * width ** 2))
    fields["random bumps"] = bumps
    for name, values in fields.items():
        field = isovdb.from_numpy(values.astype(np.float32))
        for iso in (0.3, 0.35, 0.4, 0.5):
            report = isovdb.extract(field, method=method, iso=iso, meta_cell=16).check()
            assert report["closed"] and report["manifold"], (name, iso, report)
            assert report["self_intersecting_pairs"] == 0, (name, iso, report)
    plain = isovdb.extract(isovdb.from_numpy(bumps.astype(np.float32)), method=method, iso=0.35, meta_cell=16,
                           intersection_free=False).check()
    if method == "regular":
        assert plain["self_intersecting_pairs"] > 0  # what the fans prevent


def test_array_keywords_are_from_numpys():
    mask = ball((20, 18, 16), (9, 8, 7), 5)
    placed = isovdb.extract(mask, spacing=(0.5, 0.5, 2.0), origin=(100.0, 0.0, -3.0))
    reference = isovdb.extract(isovdb.from_numpy(mask, spacing=(0.5, 0.5, 2.0), origin=(100.0, 0.0, -3.0)))
    assert np.array_equal(placed.vertices, reference.vertices)
    assert np.array_equal(placed.triangles, reference.triangles)
    plain = isovdb.extract(mask)
    assert np.allclose(placed.vertices, plain.vertices * [0.5, 0.5, 2.0] + [100.0, 0.0, -3.0], atol=1e-4)

    x, y, z = np.indices((24, 24, 24), dtype=np.float32)
    sdf = np.sqrt((x - 11.5) ** 2 + (y - 11.5) ** 2 + (z - 11.5) ** 2) - 7.0
    as_distance = isovdb.extract(sdf, kind="distance")
    assert np.array_equal(as_distance.vertices, isovdb.extract(isovdb.from_numpy(sdf, kind="distance")).vertices)
    # The same floats read by dtype are a scalar field, meshed at the middle of their range.
    assert not np.array_equal(as_distance.vertices, isovdb.extract(sdf).vertices)

    grey = (mask * 200).astype(np.uint8)
    thresholded = isovdb.extract(grey, threshold=100)
    assert np.array_equal(thresholded.vertices, isovdb.extract(isovdb.from_numpy(grey, threshold=100)).vertices)
    volume = isovdb.distance_field(mask, spacing=2.0)
    assert volume.kind == "distance field" and volume.spacing == (2.0, 2.0, 2.0)


def test_array_keywords_with_a_volume_are_refused():
    volume = isovdb.from_numpy(ball((12, 12, 12), (6, 6, 6), 4))
    with pytest.raises(ValueError, match=r"extract: spacing, origin apply to a numpy array; a Volume keeps its own"):
        isovdb.extract(volume, spacing=2.0, origin=(1, 2, 3))
    with pytest.raises(ValueError, match=r"distance_field: kind applies to a numpy array"):
        isovdb.distance_field(volume, kind="mask")
    with pytest.raises(ValueError, match="kind"):
        isovdb.extract(np.zeros((4, 4, 4), np.float32), kind="surface")
