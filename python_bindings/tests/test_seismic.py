# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Seismic front end: read_segy / read_volume on the bundled SEG-Y samples, checked against segyio."""
import numpy as np
import pytest

import isovdb

segyio = pytest.importorskip("segyio")


@pytest.fixture(scope="module")
def f3(data_dir):
    return data_dir / "seismic" / "f3.sgy"


@pytest.mark.parametrize("name", ["f3.sgy", "f3-lsb.sgy", "f3_format1_ibm_msb.sgy", "f3_format5_ieee_msb.sgy"])
def test_amplitudes_equal_segyio(data_dir, name):
    path = data_dir / "seismic" / name
    volume = isovdb.read_segy(path)
    assert volume.kind == "scalar"
    expected = segyio.tools.cube(str(path)) if "lsb" not in name else None
    if expected is None:  # segyio needs endian="little" for the byte-swapped copy
        with segyio.open(str(path), endian="little") as f:
            expected = segyio.tools.cube(f)
    assert volume.shape == expected.shape
    assert np.array_equal(volume.to_numpy(), expected.astype(np.float32))


def test_geometry_is_reported(f3):
    volume = isovdb.read_segy(f3)
    segy = volume.info()["input"]["segy"]
    with segyio.open(str(f3)) as f:
        assert segy["inlines"]["first"] == f.ilines[0] and segy["inlines"]["count"] == len(f.ilines)
        assert segy["crosslines"]["count"] == len(f.xlines) and segy["samples"] == len(f.samples)
        assert volume.spacing[2] == pytest.approx(f.samples[1] - f.samples[0])
    samples = volume.info()["input"]["samples"]
    assert samples["min"] < 0 < samples["max"]


def test_read_volume_reads_sgy_the_same_way(f3):
    a, b = isovdb.read_segy(f3), isovdb.read_volume(f3)
    assert b.kind == "scalar" and np.array_equal(a.to_numpy(), b.to_numpy())


def test_clip_leaves_quiet_samples_inactive(f3):
    full = isovdb.read_segy(f3).to_numpy()
    clipped = isovdb.read_segy(f3, clip=3000)
    values = clipped.to_numpy()
    loud = np.abs(full) >= 3000
    assert np.array_equal(values[loud], full[loud])
    assert (values[~loud] == 3000).all()  # background = clip
    assert clipped.info()["active_voxels"] == int(loud.sum())


def test_amplitude_isosurface_and_boundary_modes(f3):
    volume = isovdb.read_segy(f3, clip=1000)
    capped = isovdb.extract(volume, method="regular", iso=3000)
    assert capped.triangle_count > 0 and capped.check()["closed"]
    opened = isovdb.extract(volume, method="regular", iso=3000, boundary="open")
    assert opened.check()["boundary_edges"] > 0
    with pytest.raises(ValueError, match="clip"):
        isovdb.extract(volume, iso=500)


def test_masks(f3):
    full = isovdb.read_segy(f3).to_numpy()
    above = isovdb.read_segy(f3, mask="above 3000")
    assert above.kind == "mask" and np.array_equal(above.to_numpy(), full > 3000)
    band = isovdb.read_segy(f3, mask_range=(-2000, 2000))
    assert np.array_equal(band.to_numpy(), (full >= -2000) & (full <= 2000))
    below = isovdb.read_volume(f3, mask="below -3000")
    assert np.array_equal(below.to_numpy(), full < -3000)


def test_segy_errors(tmp_path, f3):
    with pytest.raises(OSError, match="no such file"):
        isovdb.read_segy(tmp_path / "none.sgy")
    bad = tmp_path / "bad.sgy"
    bad.write_bytes(b"C 1 not a seismic file" * 10)
    with pytest.raises(ValueError, match="bad.sgy"):
        isovdb.read_segy(bad)
    with pytest.raises(ValueError, match="exclude"):
        isovdb.read_segy(f3, mask="above 1", mask_range=(0, 1))
    with pytest.raises(ValueError, match="mask"):
        isovdb.read_segy(f3, mask="sideways 3")
    with pytest.raises(ValueError):
        isovdb.read_segy(f3, inline_byte=1)
