// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/stl.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <limits>

#include "isovdb/errors.h"
#include "isovdb/io/mesh_file.h"
#include "mesh_file_test_support.h"
#include "support/test_support.h"

namespace isovdb::io {
namespace {

using mesh::Mesh;

TEST(Stl, BinaryLayoutHasTheCountTheCornersAndUnitNormals) {
  test::TempDir dir;
  writeStl(dir / "t.stl", test::tetrahedron());
  const std::string bytes = test::readFile(dir / "t.stl");
  ASSERT_EQ(bytes.size(), 84u + 4u * 50u);
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  EXPECT_EQ(count, 4u);
  float facet[12];
  std::memcpy(facet, bytes.data() + 84, sizeof facet);  // triangle {0, 2, 1}: z = 0, facing -z
  EXPECT_FLOAT_EQ(facet[0], 0.0f);
  EXPECT_FLOAT_EQ(facet[1], 0.0f);
  EXPECT_FLOAT_EQ(facet[2], -1.0f);
  EXPECT_EQ(facet[6], 0.0f);  // the second corner, vertex 2 = (0, 2, 0)
  EXPECT_EQ(facet[7], 2.0f);
}

TEST(Stl, RoundTripWeldsTheCornersBackIntoTheIndexedMesh) {
  test::TempDir dir;
  const Mesh mesh = test::tetrahedron();
  writeMesh(dir / "t.STL", mesh);  // by extension, any case
  const Mesh back = readMesh(dir / "t.STL");
  ASSERT_EQ(back.positions.size(), mesh.positions.size());  // welded: each vertex once
  ASSERT_EQ(back.triangles.size(), mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)  // the same corners in the same winding
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_EQ(back.positions[back.triangles[t][c]], mesh.positions[mesh.triangles[t][c]]) << t << " " << c;
  EXPECT_EQ(back.positions[1], mesh.positions[2]);  // vertices in order of first appearance
  EXPECT_TRUE(back.normals.empty());
}

TEST(Stl, ReadsAsciiFiles) {
  test::TempDir dir;
  test::writeFile(dir / "a.stl",
                  "solid two triangles\n"
                  "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n"
                  "      vertex 1 1 0\n    endloop\n  endfacet\n"
                  "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 1 0\n"
                  "      vertex 0 1 0.5e-1\n    endloop\n  endfacet\n"
                  "endsolid two triangles\n");
  const Mesh mesh = readStl(dir / "a.stl");
  ASSERT_EQ(mesh.positions.size(), 4u);
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.triangles[1], (mesh::Triangle{0, 2, 3}));
  EXPECT_FLOAT_EQ(mesh.positions[3][2], 0.05f);
}

TEST(Stl, BadFilesAreRefusedByName) {
  test::TempDir dir;
  const auto expectInputError = [&](const std::string& name, const std::string& content, const std::string& what) {
    test::expectFileRefused(dir, name, content, what, [](const auto& path) { readStl(path); });
  };
  expectInputError("short.stl", "tiny", "too short");
  std::string truncated(84 + 50, '\0');
  truncated[80] = 2;  // two facets declared, one present
  expectInputError("truncated.stl", truncated, "counts 2 facets");
  expectInputError("word.stl", "solid x\n facet normal 0 0 1 outer loop vertex 0 0 zero", "expected a finite number");
  expectInputError("open.stl",
                   "solid x\n facet normal 0 0 1 outer loop vertex 0 0 0 vertex 1 0 0 vertex 1 1 0 "
                   "endloop endfacet\n",
                   "ends before 'endsolid'");
  std::string nan(84 + 50, '\0');
  nan[80] = 1;
  const float notANumber = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(nan.data() + 84 + 12, &notANumber, 4);
  expectInputError("nan.stl", nan, "non-finite");
  EXPECT_THROW(readStl(dir / "missing.stl"), IoError);
}

TEST(Stl, TriangleIndexOutOfRangeWritesNothing) {
  test::TempDir dir;
  test::expectBadMeshWritesNothing(dir, "bad.stl", [](const auto& path, const auto& mesh) { writeStl(path, mesh); });
}

}  // namespace
}  // namespace isovdb::io
