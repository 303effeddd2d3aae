// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file test_meshes.h
/// @brief Closed test meshes shared by the mesh-stage tests
///        (validate_test.cc, self_intersection_test.cc).
#pragma once

#include <cstdint>

#include "isovdb/mesh/mesh.h"

namespace isovdb::test {

/// Octahedron with corners `radius` from `centre` on the axes, outward oriented.
mesh::Mesh octahedron(mesh::Vec3f centre = {0, 0, 0}, float radius = 1);

/// Octahedron subdivided `levels` times, vertices pushed onto the unit sphere.
mesh::Mesh sphere(int levels);

/// Torus with n x m quads, each split into two triangles, outward oriented.
mesh::Mesh torus(std::uint32_t n, std::uint32_t m, float major = 3, float minor = 1, mesh::Vec3f offset = {0, 0, 0});

}  // namespace isovdb::test
