// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file measures.h
/// @brief A mesh's area and signed volume: the validator sums the volume per component,
///        the Python Mesh reports both for the whole mesh.
#pragma once

#include "isovdb/mesh/mesh.h"

namespace isovdb::mesh {

/// Signed volume of the tetrahedron (origin, a, b, c) of triangle `tri`, in double: summed over
/// a closed surface, the volume it encloses (positive when the triangles face outward).
double signedVolumeTerm(const Mesh& mesh, const Triangle& tri);

/// Area of triangle `tri`, in double.
double triangleArea(const Mesh& mesh, const Triangle& tri);

struct MeshMeasures {
  double area = 0.0;
  double signedVolume = 0.0;  ///< meaningful for a closed mesh
};

/// Sums of the triangles' areas and signed volume terms.
/// @pre every triangle references a vertex of `mesh`
MeshMeasures measure(const Mesh& mesh);

}  // namespace isovdb::mesh
