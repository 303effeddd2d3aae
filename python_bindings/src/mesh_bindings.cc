// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Mesh (numpy views of the C++ buffers), its validation and files.
#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <optional>

#include "bindings.h"
#include "isovdb/io/mesh_file.h"
#include "isovdb/io/png_file.h"
#include "isovdb/mesh/components.h"
#include "isovdb/mesh/measures.h"
#include "isovdb/mesh/preview.h"
#include "isovdb/mesh/validate.h"
#include "isovdb/pipeline/mesh_report.h"

namespace isovdb::python {

namespace {

/// An (n, 3) numpy view of a vector of 3-arrays, kept alive by `owner` (the Python Mesh).
template <typename T>
py::array view(const std::vector<std::array<T, 3>>& values, py::handle owner) {
  static_assert(sizeof(std::array<T, 3>) == 3 * sizeof(T));
  const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(values.size()), 3};
  const std::vector<py::ssize_t> strides{3 * sizeof(T), sizeof(T)};
  if (values.empty()) return py::array_t<T>(shape);  // no buffer to point at
  return py::array_t<T>(shape, strides, values.front().data(), owner);
}

/// Copies an (n, 3) array-like into a vector of 3-arrays.
template <typename T>
std::vector<std::array<T, 3>> rows(const py::object& object, const char* name) {
  const auto array = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(object);
  if (!array || array.ndim() != 2 || array.shape(1) != 3)
    throw py::value_error(std::string("Mesh: ") + name + " must be an (n, 3) array");
  std::vector<std::array<T, 3>> out(static_cast<std::size_t>(array.shape(0)));
  std::copy_n(array.data(), array.size(), out.empty() ? nullptr : out.front().data());
  return out;
}

PyMesh makeMesh(const py::object& vertices, const py::object& triangles, const py::object& normals) {
  PyMesh result;
  result.mesh.positions = rows<float>(vertices, "vertices");
  if (!normals.is_none()) {
    result.mesh.normals = rows<float>(normals, "normals");
    if (result.mesh.normals.size() != result.mesh.positions.size())
      throw py::value_error("Mesh: " + std::to_string(result.mesh.normals.size()) + " normals for " +
                            std::to_string(result.mesh.positions.size()) + " vertices");
  }
  const auto indices = py::array::ensure(triangles);
  if (indices && indices.dtype().kind() != 'i' && indices.dtype().kind() != 'u')
    throw py::value_error("Mesh: triangles must hold integers");
  result.mesh.triangles = rows<std::uint32_t>(triangles, "triangles");
  for (const auto& triangle : result.mesh.triangles)
    for (std::uint32_t index : triangle)
      if (index >= result.mesh.positions.size())
        throw py::value_error("Mesh: triangle index " + std::to_string(index) +
                              " >= " + std::to_string(result.mesh.positions.size()) + " vertices");
  return result;
}

py::dict check(const PyMesh& self, bool selfIntersections) {
  Json report;
  {
    py::gil_scoped_release release;
    report = pipeline::toJson(mesh::validateMesh(self.mesh, {.selfIntersections = selfIntersections}));
  }
  return toPython(report);
}

PyMesh readMesh(const std::filesystem::path& path) {
  PyMesh result;
  py::gil_scoped_release release;
  result.mesh = io::readMesh(path);
  return result;
}

/// The state pickle and copy.deepcopy keep: copies of the arrays and the statistics as JSON text.
py::tuple meshState(py::object self) {
  const PyMesh& m = self.cast<const PyMesh&>();
  const py::object normals =
      m.mesh.normals.empty() ? py::none() : py::object(view(m.mesh.normals, self).attr("copy")());
  return py::make_tuple(view(m.mesh.positions, self).attr("copy")(), view(m.mesh.triangles, self).attr("copy")(),
                        normals, m.statistics.dump());
}

PyMesh meshFromState(const py::tuple& state) {
  if (state.size() != 4)
    throw py::value_error("Mesh: cannot unpickle a state of " + std::to_string(state.size()) + " items");
  PyMesh result = makeMesh(state[0], state[1], state[2]);
  result.statistics = Json::parse(state[3].cast<std::string>());
  return result;
}

}  // namespace

void bindMesh(py::module_& m) {
  py::class_<PyMesh>(m, "Mesh", R"doc(
An indexed triangle mesh in world space (as extract() returns it, or read_mesh() reads it).

vertices, triangles and normals are numpy views onto the mesh's own buffers (no copy):
writing into them changes the mesh; they stay valid as long as any of them or the Mesh lives.
A Mesh pickles (process pools, Dask) and copy.deepcopy()s: the copy owns its own arrays and
statistics.)doc")
      .def(py::init(&makeMesh), py::arg("vertices"), py::arg("triangles"), py::arg("normals") = py::none(),
           "Mesh from an (n, 3) array of positions, an (m, 3) array of vertex indices and optionally (n, 3) "
           "normals (copied, as float32 and uint32).")
      .def_property_readonly(
          "vertices", [](py::object self) { return view(self.cast<const PyMesh&>().mesh.positions, self); },
          "(n, 3) float32 positions, world units.")
      .def_property_readonly(
          "triangles", [](py::object self) { return view(self.cast<const PyMesh&>().mesh.triangles, self); },
          "(m, 3) uint32 vertex indices, counter-clockwise seen from outside (outward orientation).")
      .def_property_readonly(
          "faces", [](py::object self) { return view(self.cast<const PyMesh&>().mesh.triangles, self); },
          "The triangles under the name trimesh, PyVista and Open3D use: (m, 3) uint32 vertex indices.")
      .def_property_readonly(
          "normals",
          [](py::object self) -> py::object {
            const PyMesh& mesh = self.cast<const PyMesh&>();
            if (!mesh.mesh.normals.empty()) return view(mesh.mesh.normals, self);
            std::vector<mesh::Vec3f> normals;
            {
              py::gil_scoped_release release;
              normals = mesh::areaWeightedNormals(mesh.mesh);
            }
            py::array_t<float> out({static_cast<py::ssize_t>(normals.size()), py::ssize_t{3}});
            if (!normals.empty()) std::copy_n(normals.front().data(), 3 * normals.size(), out.mutable_data());
            return out;
          },
          "(n, 3) float32 unit vertex normals, facing outward: the mesh's own (reservoir meshes carry the "
          "field's gradient, PLY files and Mesh(normals=...) may carry some; a view), else area-weighted "
          "normals of the triangles around each vertex, computed on each access (a new array; zero for a "
          "vertex no triangle uses).")
      .def_property_readonly("vertex_count", [](const PyMesh& m) { return m.mesh.vertexCount(); })
      .def_property_readonly(
          "area", [](const PyMesh& m) { return mesh::measure(m.mesh).area; }, "Surface area, world units squared.")
      .def_property_readonly(
          "volume", [](const PyMesh& m) { return mesh::measure(m.mesh).signedVolume; },
          "Signed enclosed volume, world units cubed (divergence theorem): positive when a closed mesh's "
          "triangles face outward, meaningless for an open one (check()['closed']).")
      .def_property_readonly(
          "bounds",
          [](const PyMesh& m) -> py::object {
            if (m.mesh.positions.empty()) return py::none();
            std::array<float, 3> lo = m.mesh.positions.front(), hi = lo;
            for (const auto& p : m.mesh.positions)
              for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], p[a]);
                hi[a] = std::max(hi[a], p[a]);
              }
            return py::make_tuple(toTuple(lo), toTuple(hi));
          },
          "((xmin, ymin, zmin), (xmax, ymax, zmax)) of the vertices, or None for an empty mesh.")
      .def_property_readonly("triangle_count", [](const PyMesh& m) { return m.mesh.triangleCount(); })
      .def_property_readonly(
          "statistics", [](const PyMesh& m) { return toPython(m.statistics); },
          "Figures of the run that made the mesh (as `isovdb extract --stats` writes them): timings_s per "
          "stage, grid and mesh counts, meta-cells contoured/skipped, seams stitched. Empty for read_mesh().")
      .def(
          "components",
          [](const PyMesh& self) {
            std::vector<mesh::Mesh> parts;
            {
              py::gil_scoped_release release;
              parts = mesh::splitComponents(self.mesh);
            }
            py::list out;
            for (mesh::Mesh& part : parts) {
              PyMesh piece;
              piece.mesh = std::move(part);
              out.append(py::cast(std::move(piece)));
            }
            return out;
          },
          R"doc(
The connected components (triangles connected through shared vertices) as a list of Mesh,
in the order of each one's first triangle (check()['largest_components'] sorts them by
size instead). Each keeps its triangles and vertices (and normals, if stored) in their order,
renumbered; unused vertices are dropped. Copies.)doc")
      .def("check", &check, py::arg("self_intersections") = true, R"doc(
Validates the mesh and returns the figures `isovdb check` reports under "mesh": vertices,
referenced_vertices, triangles, edges, boundary_edges, non_manifold_edges,
non_manifold_vertices, inconsistently_oriented_edges, degenerate_triangles, components,
euler_characteristic, signed_volume (positive when the triangles face outward),
self_intersecting_pairs (-1 when self_intersections=False), closed, manifold, and per
component its triangles, vertices, Euler characteristic, closed, genus and signed_volume
(negative for a cavity). Exact (CGAL predicates); parallel.)doc")
      .def(
          "write",
          [](const PyMesh& self, const std::filesystem::path& path) {
            py::gil_scoped_release release;
            io::writeMesh(path, self.mesh);
          },
          py::arg("path"), R"doc(
Writes the mesh by extension: .ply (binary little-endian, the same bytes as the CLI writes),
.obj, .stl (binary; no vertex normals) or .glb (binary glTF 2.0), through a temporary file. Raises ValueError for
another extension, OSError when the path is not writable.)doc")
      .def(
          "render",
          [](const PyMesh& self, const std::optional<std::filesystem::path>& path, int width, int height) {
            mesh::PreviewImage image;
            {
              py::gil_scoped_release release;
              image = mesh::renderPreview(self.mesh, {.width = width, .height = height});
              if (path) io::writePng(*path, image.width, image.height, 3, image.rgb);
            }
            py::array_t<std::uint8_t> pixels({image.height, image.width, 3});
            std::copy(image.rgb.begin(), image.rgb.end(), pixels.mutable_data());
            return pixels;
          },
          py::arg("path") = py::none(), py::arg("width") = 800, py::arg("height") = 600, R"doc(
A shaded picture of the mesh, as `isovdb extract --preview` draws it: an oblique view from
the front, right and above, faces seen from outside bone-coloured, faces seen from behind
red. Returns a (height, width, 3) uint8 array (display it with matplotlib's imshow or
IPython); writes it as a PNG too when `path` is given.)doc")
      .def(py::pickle(&meshState, &meshFromState))
      .def("__repr__", [](const PyMesh& m) {
        return "<isovdb.Mesh " + std::to_string(m.mesh.vertexCount()) + " vertices, " +
               std::to_string(m.mesh.triangleCount()) + " triangles>";
      });

  // Hand-offs to the packages notebooks draw and analyse meshes with, imported only when called.
  py::exec(R"py(
def _mesh_to_vtk(self):
    """The mesh as a vtkPolyData (python3-vtk9): points float32, triangles as polygons, normals as
point normals. A copy; raises ImportError when VTK is not installed."""
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(self.vertices), deep=True))
    cells = vtkCellArray()
    offsets = np.arange(0, 3 * self.triangle_count + 1, 3, dtype=np.int64)
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(self.triangles.astype(np.int64).ravel(), deep=True))
    poly = vtkPolyData()
    poly.SetPoints(points)
    poly.SetPolys(cells)
    normals = numpy_to_vtk(np.ascontiguousarray(self.normals), deep=True)
    normals.SetName("Normals")
    poly.GetPointData().SetNormals(normals)
    return poly

def _mesh_to_pyvista(self):
    """The mesh as a pyvista.PolyData (a copy). Raises ImportError when PyVista is not installed."""
    try:
        import pyvista
    except ImportError as e:
        raise ImportError("Mesh.to_pyvista() needs the pyvista package (Mesh.to_vtk() needs only VTK)") from e
    return pyvista.wrap(self.to_vtk())

def _mesh_to_trimesh(self):
    """The mesh as a trimesh.Trimesh (copies, no merging or repair). Raises ImportError when trimesh
is not installed."""
    try:
        import trimesh
    except ImportError as e:
        raise ImportError("Mesh.to_trimesh() needs the trimesh package") from e
    return trimesh.Trimesh(vertices=self.vertices.copy(), faces=self.triangles.copy(),
                           vertex_normals=self.normals.copy(), process=False)

Mesh.to_vtk = _mesh_to_vtk
Mesh.to_pyvista = _mesh_to_pyvista
Mesh.to_trimesh = _mesh_to_trimesh
del _mesh_to_vtk, _mesh_to_pyvista, _mesh_to_trimesh
)py",
           m.attr("__dict__"));

  m.def("read_mesh", &readMesh, py::arg("path"),
        "Reads a .ply, .obj (polygons as fans), .stl (binary or ASCII; corners welded by exact "
        "position), .glb or .gltf (glTF 2.0; every triangle primitive of the default scene, placed by "
        "its nodes' transforms) mesh. Raises OSError "
        "for a missing file, ValueError for a malformed one or another extension.");
}

}  // namespace isovdb::python
