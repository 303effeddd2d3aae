# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
"""Mesh: numpy views, construction, check, write, read_mesh."""
import gc

import numpy as np
import pytest

import isovdb
from conftest import ROOT, ball

TETRAHEDRON = (np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], np.float32),
               np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], np.uint32))


@pytest.fixture(scope="module")
def mesh():
    return isovdb.extract(isovdb.from_numpy(ball((24, 24, 24), (12, 12, 12), 8)), method="vdb")


def test_arrays_have_the_documented_shapes_and_types(mesh):
    assert mesh.vertices.dtype == np.float32 and mesh.vertices.shape == (mesh.vertex_count, 3)
    assert mesh.triangles.dtype == np.uint32 and mesh.triangles.shape == (mesh.triangle_count, 3)
    assert mesh.triangles.max() < mesh.vertex_count
    assert mesh.normals.dtype == np.float32 and mesh.normals.shape == mesh.vertices.shape


def test_vertices_are_views_onto_the_mesh_and_keep_it_alive():
    mesh = isovdb.Mesh(*TETRAHEDRON)
    first, second = mesh.vertices, mesh.vertices
    assert np.shares_memory(first, second)
    assert first.base is not None and not first.flags.owndata
    first[0, 0] = 5.0
    assert mesh.vertices[0, 0] == 5.0
    triangles = mesh.triangles
    del mesh, first
    gc.collect()
    assert second[0, 0] == 5.0 and triangles[3].tolist() == [1, 2, 3]


def test_check_reports_a_closed_tetrahedron():
    report = isovdb.Mesh(*TETRAHEDRON).check()
    assert report["closed"] and report["manifold"]
    assert (report["vertices"], report["edges"], report["triangles"]) == (4, 6, 4)
    assert report["euler_characteristic"] == 2 and report["self_intersecting_pairs"] == 0
    assert report["largest_components"][0]["genus"] == 0


def test_check_finds_holes_and_skips_self_intersections_on_request():
    vertices, triangles = TETRAHEDRON
    report = isovdb.Mesh(vertices, triangles[:3]).check(self_intersections=False)
    assert not report["closed"] and report["boundary_edges"] == 3
    assert report["self_intersecting_pairs"] == -1


def test_normals_travel_through_ply_files(tmp_path):
    vertices, triangles = TETRAHEDRON
    normals = vertices - vertices.mean(axis=0)
    mesh = isovdb.Mesh(vertices, triangles, normals=normals)
    assert np.array_equal(mesh.normals, normals) and np.shares_memory(mesh.normals, mesh.normals)
    mesh.write(tmp_path / "n.ply")
    back = isovdb.read_mesh(tmp_path / "n.ply")
    assert np.array_equal(back.normals, normals)
    with pytest.raises(ValueError, match="3 normals for 4 vertices"):
        isovdb.Mesh(vertices, triangles, normals=normals[:3])


@pytest.mark.parametrize("method", ["adaptive", "regular", "vdb"])
def test_every_method_gives_outward_unit_normals(method):
    mesh = isovdb.extract(ball((32, 32, 32), (16, 16, 16), 10), method=method)
    normals = mesh.normals
    assert np.allclose(np.linalg.norm(normals, axis=1), 1, atol=1e-5)
    outward = np.einsum("ij,ij->i", normals, mesh.vertices - np.float32(16))
    assert (outward > 0).all(), f"{(outward <= 0).sum()} of {len(outward)} normals point inward"


def test_computed_normals_are_area_weighted():
    vertices, triangles = TETRAHEDRON
    normals = isovdb.Mesh(vertices, triangles).normals
    assert not np.shares_memory(normals, isovdb.Mesh(vertices, triangles).normals)
    assert np.allclose(normals[0], -np.ones(3) / np.sqrt(3))  # three unit right triangles around the origin
    assert np.allclose(normals[3], [0, 0, 1])  # -y and -x faces (area 1/2) and the (1, 1, 1) face (area 3^0.5/2)
    assert np.array_equal(isovdb.Mesh(vertices[:4], triangles[:0]).normals, np.zeros((4, 3), np.float32))


def test_stl_round_trip_keeps_the_surface(mesh, tmp_path):
    mesh.write(tmp_path / "m.stl")
    back = isovdb.read_mesh(tmp_path / "m.stl")
    assert (back.vertex_count, back.triangle_count) == (mesh.vertex_count, mesh.triangle_count)
    assert back.check()["closed"] and back.volume == pytest.approx(mesh.volume, rel=1e-6)
    def corners(m):  # each triangle's corners in winding order, as a sorted list
        return sorted(map(tuple, m.vertices[m.triangles].reshape(-1, 9).tolist()))
    assert corners(back) == corners(mesh)


@pytest.mark.parametrize("suffix", [".obj", ".glb"])
def test_obj_and_glb_round_trips_are_exact(mesh, tmp_path, suffix):
    mesh.write(tmp_path / ("m" + suffix))
    back = isovdb.read_mesh(tmp_path / ("m" + suffix))
    assert np.array_equal(back.vertices, mesh.vertices) and np.array_equal(back.triangles, mesh.triangles)


def test_glb_opens_in_vtks_gltf_reader(mesh, tmp_path):
    pytest.importorskip("vtkmodules")
    from vtkmodules.vtkIOGeometry import vtkGLTFReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    mesh.write(tmp_path / "m.glb")
    reader = vtkGLTFReader()
    reader.SetFileName(str(tmp_path / "m.glb"))
    reader.Update()
    poly = reader.GetOutput()
    while not hasattr(poly, "GetPoints"):  # the scene's blocks: node, mesh, primitive
        poly = poly.GetBlock(0)
    assert (poly.GetNumberOfPoints(), poly.GetNumberOfCells()) == (mesh.vertex_count, mesh.triangle_count)
    assert np.array_equal(vtk_to_numpy(poly.GetPoints().GetData()), mesh.vertices)


def test_to_vtk_hands_over_points_triangles_and_normals(mesh):
    pytest.importorskip("vtkmodules")
    from vtkmodules.util.numpy_support import vtk_to_numpy
    poly = mesh.to_vtk()
    assert (poly.GetNumberOfPoints(), poly.GetNumberOfPolys()) == (mesh.vertex_count, mesh.triangle_count)
    assert np.array_equal(vtk_to_numpy(poly.GetPoints().GetData()), mesh.vertices)
    connectivity = vtk_to_numpy(poly.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    assert np.array_equal(connectivity, mesh.triangles)
    assert np.array_equal(vtk_to_numpy(poly.GetPointData().GetNormals()), mesh.normals)


def test_missing_packages_are_named(mesh):
    for method, package in (("to_pyvista", "pyvista"), ("to_trimesh", "trimesh")):
        try:
            __import__(package)
        except ImportError:
            with pytest.raises(ImportError, match=package):
                getattr(mesh, method)()


def test_components_split_the_mesh_in_first_triangle_order():
    two = isovdb.extract(ball((40, 24, 24), (10, 12, 12), 6) | ball((40, 24, 24), (29, 12, 12), 7))
    parts = two.components()
    assert len(parts) == two.check()["components"] == 2
    assert sum(p.triangle_count for p in parts) == two.triangle_count
    assert sum(p.vertex_count for p in parts) == two.vertex_count
    first = two.triangles[0]
    assert np.array_equal(parts[0].vertices[parts[0].triangles[0]], two.vertices[first])
    for part, radius in zip(sorted(parts, key=lambda p: p.vertices.mean(axis=0)[0]), (6, 7)):
        report = part.check()
        assert report["closed"] and report["components"] == 1 and report["euler_characteristic"] == 2
        assert part.volume == pytest.approx(4 / 3 * np.pi * radius ** 3, rel=0.15)
    assert isovdb.Mesh(np.zeros((3, 3), np.float32), np.zeros((0, 3), np.uint32)).components() == []


def test_mesh_constructor_rejects_bad_arrays():
    vertices, triangles = TETRAHEDRON
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        isovdb.Mesh(vertices[:, :2], triangles)
    with pytest.raises(ValueError, match="index 7"):
        isovdb.Mesh(vertices, np.array([[0, 1, 7]]))
    with pytest.raises(ValueError, match="integers"):
        isovdb.Mesh(vertices, triangles.astype(np.float32))


@pytest.mark.parametrize("suffix", [".ply", ".obj"])
def test_write_and_read_back(tmp_path, mesh, suffix):
    path = tmp_path / ("m" + suffix)
    mesh.write(path)
    assert path.stat().st_size > 0
    if suffix == ".ply":
        back = isovdb.read_mesh(path)
        assert np.array_equal(back.vertices, mesh.vertices)
        assert np.array_equal(back.triangles, mesh.triangles)
        assert back.check() == mesh.check()


def test_write_and_read_errors(tmp_path, mesh):
    with pytest.raises(ValueError, match="gltf"):
        mesh.write(tmp_path / "m.gltf")
    (tmp_path / "m.gltf").write_text("solid tetra\n")  # .gltf is read, glTF JSON only
    with pytest.raises(ValueError, match="m.gltf.*neither glTF JSON text nor binary glTF"):
        isovdb.read_mesh(tmp_path / "m.gltf")
    with pytest.raises(OSError):
        mesh.write(tmp_path / "missing" / "m.ply")
    with pytest.raises(OSError, match="(?i)no such file"):
        isovdb.read_mesh(tmp_path / "none.ply")
    (tmp_path / "bad.ply").write_text("ply\nformat ascii 9.9\nend_header\n")
    with pytest.raises(ValueError, match="bad.ply"):
        isovdb.read_mesh(tmp_path / "bad.ply")


def test_help_is_useful():
    doc = isovdb.extract.__doc__
    for word in ("adaptive", "regular", "vdb", "meta_cell", "finest_size", "max_cell_size", "progress", "threads"):
        assert word in doc
    assert "numpy" in isovdb.from_numpy.__doc__ and "Fortran-ordered" in isovdb.from_numpy.__doc__
    assert "pickles" in isovdb.Mesh.__doc__


def test_pickle_and_deepcopy_give_an_independent_equal_mesh(mesh):
    import copy
    import pickle
    for clone in (pickle.loads(pickle.dumps(mesh)), copy.deepcopy(mesh)):
        assert np.array_equal(clone.vertices, mesh.vertices)
        assert np.array_equal(clone.triangles, mesh.triangles)
        assert clone.statistics == mesh.statistics
        clone.vertices[0, 0] += 1.0  # its own buffers
        assert clone.vertices[0, 0] != mesh.vertices[0, 0]
    with_normals = isovdb.Mesh(*TETRAHEDRON, normals=np.eye(4, 3, dtype=np.float32))
    assert np.array_equal(pickle.loads(pickle.dumps(with_normals)).normals, with_normals.normals)


def test_faces_area_volume_and_bounds_of_a_tetrahedron():
    tetrahedron = isovdb.Mesh(*TETRAHEDRON)
    assert tetrahedron.faces is not None and np.array_equal(tetrahedron.faces, tetrahedron.triangles)
    assert tetrahedron.area == pytest.approx(1.5 + np.sqrt(3) / 2)
    assert tetrahedron.volume == pytest.approx(1 / 6)  # outward: positive
    assert isovdb.Mesh(TETRAHEDRON[0], TETRAHEDRON[1][:, ::-1]).volume == pytest.approx(-1 / 6)
    assert tetrahedron.bounds == ((0, 0, 0), (1, 1, 1))
    assert isovdb.Mesh(np.zeros((0, 3), np.float32), np.zeros((0, 3), np.uint32)).bounds is None


def test_a_ball_mesh_encloses_about_the_masks_voxels(mesh):
    voxels = np.count_nonzero(ball((24, 24, 24), (12, 12, 12), 8))
    assert mesh.volume == pytest.approx(voxels, rel=0.1)


def test_read_mesh_places_gltf_nodes(data_dir):
    # The fuzz seed's tetrahedron under a parent scaled (1, 2, -1) (a mirror) and a child
    # scaled 2: the volume grows by |det| = 16 and stays positive (the winding turned back).
    plain = isovdb.read_mesh(ROOT / "fuzz" / "corpus" / "glb" / "tetra.glb")
    placed = isovdb.read_mesh(ROOT / "fuzz" / "corpus" / "gltf" / "tetra_nodes.gltf")
    assert placed.triangle_count == plain.triangle_count
    assert placed.volume == pytest.approx(16 * plain.volume)
    box = isovdb.read_mesh(data_dir / "meshes" / "Box-embedded.gltf")  # glTF-Sample-Models' Box
    assert box.triangle_count == 12 and box.volume == pytest.approx(1.0)
