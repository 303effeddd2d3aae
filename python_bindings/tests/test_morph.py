# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""morph_slices: sparse slice stacks completed by level-set metamorphosis, from image
folders and from volumes with labelled z-slices, then contoured."""
import numpy as np
import pytest

import isovdb
from conftest import ball

plt = pytest.importorskip("matplotlib.pyplot")


def disc_image(size, centre, radius):
    y, x = np.indices((size, size))
    return ((x - centre[0]) ** 2 + (y - centre[1]) ** 2 < radius ** 2)


def write_slices(folder, images, heights=None):
    for i, image in enumerate(images):
        # White object on black: the background is the class covering most of the border.
        plt.imsave(folder / f"slice{i}.png", image.astype(np.uint8) * 255, cmap="gray", vmin=0, vmax=255)
    if heights is not None:
        (folder / "heights.txt").write_text("\n".join(str(h) for h in heights) + "\n")


def test_folder_of_discs_becomes_one_closed_genus0_surface(tmp_path):
    write_slices(tmp_path, [disc_image(48, (20, 22), 8), disc_image(48, (26, 24), 14), disc_image(48, (24, 24), 6)],
                 heights=[0, 8, 14])
    sdf = isovdb.morph_slices(tmp_path, heights=tmp_path / "heights.txt")
    assert sdf.kind == "distance field"
    info = sdf.info()["input"]
    assert info["slices"] == 3
    assert info["morph"]["original_slices"] == 3
    assert info["morph"]["intermediate_slices"] == 14 + 1 - 3
    report = isovdb.extract(sdf, method="regular").check()
    assert report["closed"] and report["manifold"]
    assert report["components"] == 1 and report["euler_characteristic"] == 2


def test_volume_with_every_fourth_slice_labelled(tmp_path):
    mask = ball((40, 40, 33), (20, 19, 16), 13)
    sparse = np.zeros_like(mask)
    sparse[:, :, 4::4] = mask[:, :, 4::4]
    volume = isovdb.from_numpy(np.ascontiguousarray(sparse))
    sdf = isovdb.morph_slices(volume, slice_step=4, slice_offset=4, threads=1)
    again = isovdb.morph_slices(volume, slice_step=4, slice_offset=4, threads=2)
    a, b = sdf.to_numpy(), again.to_numpy()
    assert np.array_equal(a, b), "the result must not depend on the thread count"
    # The morphed stack covers the labelled range; the ball's middle slice is inside.
    inside = a < 0
    assert inside[20, 19, 16] and not inside[2, 2, 16]
    report = isovdb.extract(sdf, method="adaptive").check()
    assert report["closed"] and report["components"] == 1
    # A morphed stack meshes outward in every method, like any other distance field.
    for method in ("vdb", "regular", "adaptive"):
        assert isovdb.extract(sdf, method=method).check()["signed_volume"] > 0, method


@pytest.mark.parametrize("interpolate", ["nearest", "linear"])
def test_other_interpolations(tmp_path, interpolate):
    write_slices(tmp_path, [disc_image(32, (16, 16), 6), disc_image(32, (16, 16), 10)])
    sdf = isovdb.morph_slices(tmp_path, spacing=6, interpolate=interpolate)
    assert sdf.info()["input"]["morph"]["interpolation"] == interpolate


def test_bad_input(tmp_path):
    with pytest.raises(OSError):
        isovdb.morph_slices(tmp_path / "missing", spacing=4)
    write_slices(tmp_path, [disc_image(32, (16, 16), 6), disc_image(32, (16, 16), 10)], heights=[0, 4, 8])
    with pytest.raises(ValueError, match="heights"):
        isovdb.morph_slices(tmp_path, heights=tmp_path / "heights.txt")
    with pytest.raises(ValueError, match="interpolate"):
        isovdb.morph_slices(tmp_path, spacing=4, interpolate="cubic")
    with pytest.raises(ValueError, match="progress_mode"):
        isovdb.morph_slices(tmp_path, spacing=4, progress_mode="fast")
    with pytest.raises(ValueError, match="pls"):
        isovdb.morph_slices(tmp_path, spacing=4, interpolate="nearest", pls=True)
    volume = isovdb.from_numpy(np.zeros((8, 8, 8), dtype=np.uint8) + 1, threshold=0)
    with pytest.raises(ValueError, match="heights"):
        isovdb.morph_slices(volume, spacing=4)


def test_area_match_and_centring_switches(tmp_path):
    write_slices(tmp_path, [disc_image(40, (14, 20), 6), disc_image(40, (26, 20), 6)])
    matched = isovdb.morph_slices(tmp_path, spacing=8)
    plain = isovdb.morph_slices(tmp_path, spacing=8, area_match=False, centring=False)
    morph, morph_plain = matched.info()["input"]["morph"], plain.info()["input"]["morph"]
    assert morph["area_match"] and not morph_plain["area_match"]
    # One disc that moves: centring registers it (they overlap more centred).
    assert morph["pairs_centred"] == 1 and morph_plain["pairs_centred"] == 0
    # Two equal discs: the matched middle plane keeps the discs' area, the plain
    # morph in place shrinks it (the sections move sideways).
    area = lambda sdf: int((sdf.to_numpy(bbox=((0, 0, 4), (39, 39, 4))) < 0).sum())
    assert area(matched) > area(plain)
