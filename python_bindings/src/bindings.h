// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file bindings.h
/// @brief What the binding files share: the Python-side Volume and Mesh, JSON → Python,
///        and one registration function per topic (each in its own .cc file).
///
/// No OpenVDB header here or in any binding .cc: volumes cross this boundary as
/// isovdb::volume::Volume (which forward-declares the grid) and numpy arrays.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "isovdb/mesh/mesh.h"
#include "isovdb/pipeline/statistics.h"
#include "isovdb/volume/distance_field.h"
#include "isovdb/volume/volume.h"

namespace isovdb::python {

namespace py = pybind11;
using Json = pipeline::Statistics::Json;

/// A volume as Python sees it: the sparse grid and what reading it recorded.
struct PyVolume {
  volume::Volume volume;
  Json input = Json::object();  ///< figures of the reading (format, dims, SEG-Y geometry, ...)
};

/// A mesh as Python sees it: the triangles and the figures of the run that made it.
struct PyMesh {
  mesh::Mesh mesh;
  Json statistics = Json::object();
};

/// Converts JSON (the library's statistics) to Python dicts, lists and scalars.
py::object toPython(const Json& json);

/// The (x, y, z) tuple of a 3-vector.
template <typename T>
py::tuple toTuple(const std::array<T, 3>& v) {
  return py::make_tuple(v[0], v[1], v[2]);
}

/// A float, or a sequence of three, as three floats (`name` is used in messages).
std::array<double, 3> threeDoubles(const py::object& value, const char* name);

void bindVolume(py::module_& m);       // volume_bindings.cc: Volume, from_numpy, read_volume, distance_field
void bindSeismic(py::module_& m);      // seismic_bindings.cc: read_segy
void bindMesh(py::module_& m);         // mesh_bindings.cc: Mesh, read_mesh
void bindExtract(py::module_& m);      // extract_bindings.cc: extract
void bindMorph(py::module_& m);        // morph_bindings.cc: morph_slices
void bindReservoir(py::module_& m);    // reservoir_bindings.cc: extract_reservoir
void bindDistributed(py::module_& m);  // distributed_bindings.cc: the tasks and client of isovdb.distributed
/// Wraps every public function so that a wrong keyword or argument type is named in
/// Python terms (argument_errors.cc); called last, once the module holds them all.
void nameWrongArguments(py::module_& m);

}  // namespace isovdb::python
