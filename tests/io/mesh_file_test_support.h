// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file mesh_file_test_support.h
/// @brief Helpers shared by the tests of the mesh file formats (stl_test.cc,
///        glb_test.cc, obj_test.cc): a small closed mesh, and the bad-file and
///        bad-mesh contracts every reader and writer keeps.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "isovdb/errors.h"
#include "isovdb/mesh/mesh.h"
#include "reader_test_support.h"

namespace isovdb::test {

/// A closed tetrahedron, outward: every vertex is shared by three triangles.
inline mesh::Mesh tetrahedron() {
  mesh::Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1.5f, 0, 0}, {0, 2, 0}, {0, 0, -0.25f}};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return mesh;
}

/// Writes `content` to `dir / name`, reads it with `read`, and expects an InputError
/// whose message names the file and contains `what`.
template <typename Read>
void expectFileRefused(const TempDir& dir, const std::string& name, const std::string& content, const std::string& what,
                       Read&& read) {
  writeFile(dir / name, content);
  expectError<InputError>([&] { read(dir / name); }, {name, what});
}

/// A triangle naming a missing vertex: `write` throws InputError and leaves no file.
template <typename Write>
void expectBadMeshWritesNothing(const TempDir& dir, const std::string& name, Write&& write) {
  mesh::Mesh mesh = tetrahedron();
  mesh.triangles.push_back({0, 1, 9});
  EXPECT_THROW(write(dir / name, mesh), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / name));
}

}  // namespace isovdb::test
