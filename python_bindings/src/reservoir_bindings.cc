// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// extract_reservoir: the reservoir front end (GRDECL corner-point grids, Marching Cubes on
// hexahedra, PN triangles).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "bindings.h"
#include "progress_callback.h"
#include "isovdb/pipeline/reservoir_extract.h"

namespace isovdb::python {

namespace {

PyMesh extractReservoir(const std::variant<std::filesystem::path, std::vector<std::filesystem::path>>& grid,
                        const std::string& property, double iso, int tessellate, long long maxValues,
                        std::optional<int> threads, const py::object& progress) {
  pipeline::ReservoirOptions options;
  if (const auto* one = std::get_if<std::filesystem::path>(&grid))
    options.inputs = {*one};
  else
    options.inputs = std::get<std::vector<std::filesystem::path>>(grid);
  options.property = property;
  options.iso = iso;
  options.maxTessellation = tessellate;
  options.limits.maxValues = maxValues;
  options.threads = threads.value_or(0);
  pipeline::Statistics stats;
  PyMesh result;
  CallbackProgress callback(progress);
  callback.run([&] { result.mesh = pipeline::extractReservoir(options, stats, &callback); });
  result.statistics = std::move(stats.json());
  return result;
}

}  // namespace

void bindReservoir(py::module_& m) {
  const pipeline::ReservoirOptions defaults;
  m.def("extract_reservoir", &extractReservoir, py::arg("grid"), py::kw_only(), py::arg("property"), py::arg("iso"),
        py::arg("tessellate") = defaults.maxTessellation, py::arg("max_values") = defaults.limits.maxValues,
        py::arg("threads") = py::none(), py::arg("progress") = py::none(), R"doc(
Isosurface of a cell property of an Eclipse corner-point grid (the `isovdb reservoir` job,
paper 003): GRDECL deck -> corner-point grid -> cell values averaged to the cell corners
over the active cells -> Marching Cubes on each hexahedron (asymptotic decider on faces),
with per-vertex normals from the inverse Jacobian of the trilinear map -> the loops of cells
whose triangles cross others fanned again (exact predicates; statistics reservoir.untangle).

grid: the .grdecl file, or a list: the grid file first, then files with more properties
  (INCLUDE inside a deck is followed too).
property: the cell property keyword (PORO, PERMX, FACIES, SOIL, ...). iso: its isovalue.
tessellate: 0 keeps the flat triangles; K > 0 refines them as PN triangles (cubic geometry,
  envelope normals) with per-edge factors up to K, crack-free; the edges of patches that
  cross others are kept straight (reservoir.tessellation_straightened).
max_values: most values the deck's keywords may hold together, n*value repeats counted (a
  guard against hostile decks; each array is also bounded by the grid's size).
threads: worker threads (None = every core); the mesh is the same.
progress: callable(stage: str, percent: int) per stage (read grdecl, corner-point grid,
  marching cubes, untangle loops, pn triangles); if it raises, the work stops and its exception propagates
  (Ctrl-C too).

Returns a Mesh in the grid's coordinates with normals; mesh.statistics holds the figures
(cells, active, inverted and pinched cells, handedness, triangles before and after tessellation,
warnings, timings). Raises OSError for a missing file and ValueError for a bad deck (the
message names the file and the line).)doc");
}

}  // namespace isovdb::python
