// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file measures.h
/// @brief A mesh's area, signed volume and vertex normals: the validator sums the volume per
///        component, the Python Mesh reports them for the whole mesh.
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

/// Area-weighted vertex normals (the sum of the unnormalised normals of the triangles around
/// each vertex, normalised; zero for a vertex no triangle with area uses). They face the way
/// the triangles' winding does: outward on isovdb's meshes. Sums in triangle order, so the
/// result does not depend on anything but the mesh.
/// @pre every triangle references a vertex of `mesh`
std::vector<Vec3f> areaWeightedNormals(const Mesh& mesh);

}  // namespace isovdb::mesh
