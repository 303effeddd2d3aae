// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/obj.h"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <limits>
#include <sstream>

#include "isovdb/errors.h"
#include "mesh_file_test_support.h"
#include "support/test_support.h"

namespace isovdb::io {
namespace {

using mesh::Mesh;

Mesh quad() {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1.5f, 0, 0}, {1.5f, 2, -0.25f}, {0, 2, 1e-7f}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

TEST(Obj, WritesVerticesAndOneBasedFaces) {
  test::TempDir dir;
  writeObj(dir / "q.obj", quad());
  EXPECT_EQ(test::readFile(dir / "q.obj"),
            "# written by isovdb: 4 vertices, 2 triangles\n"
            "v 0 0 0\nv 1.5 0 0\nv 1.5 2 -0.25\nv 0 2 1e-07\n"
            "f 1 2 3\nf 1 3 4\n");
}

TEST(Obj, WritesNormalsAndTheirIndices) {
  test::TempDir dir;
  Mesh mesh = quad();
  mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, -1, 0}, {0.5f, 0, 0}};
  writeObj(dir / "q.obj", mesh);
  EXPECT_EQ(test::readFile(dir / "q.obj"),
            "# written by isovdb: 4 vertices, 2 triangles\n"
            "v 0 0 0\nv 1.5 0 0\nv 1.5 2 -0.25\nv 0 2 1e-07\n"
            "vn 0 0 1\nvn 0 0 1\nvn 0 -1 0\nvn 0.5 0 0\n"
            "f 1//1 2//2 3//3\nf 1//1 3//3 4//4\n");
}

TEST(Obj, NumbersReadBackBitForBitOnALargeMesh) {
  // More lines than one formatting batch, so the blocks' order is checked too.
  Mesh mesh;
  const std::uint32_t n = 600000;
  for (std::uint32_t i = 0; i < n; ++i)
    mesh.positions.push_back({std::bit_cast<float>(0x3e000000u + i * 977u), -float(i) / 3.f,
                              i % 7 ? float(i) : std::numeric_limits<float>::denorm_min()});
  for (std::uint32_t i = 0; i + 2 < n; i += 3) mesh.triangles.push_back({i, i + 1, i + 2});
  test::TempDir dir;
  writeObj(dir / "big.obj", mesh);

  std::istringstream in(test::readFile(dir / "big.obj"));
  std::string line;
  std::getline(in, line);
  std::size_t v = 0, f = 0;
  while (std::getline(in, line)) {
    if (line.rfind("v ", 0) == 0) {
      ASSERT_LT(v, mesh.positions.size());
      const char* p = line.data() + 2;
      const char* end = line.data() + line.size();
      for (int k = 0; k < 3; ++k) {
        float value = 0;
        const auto r = std::from_chars(p, end, value);
        ASSERT_EQ(r.ec, std::errc()) << line;
        ASSERT_EQ(std::bit_cast<std::uint32_t>(value), std::bit_cast<std::uint32_t>(mesh.positions[v][k])) << line;
        p = r.ptr + (r.ptr < end ? 1 : 0);
      }
      ++v;
    } else {
      ASSERT_EQ(line.rfind("f ", 0), 0u) << line;
      const auto& t = mesh.triangles[f++];
      ASSERT_EQ(line,
                "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1));
    }
  }
  EXPECT_EQ(v, mesh.positions.size());
  EXPECT_EQ(f, mesh.triangles.size());
}

TEST(Obj, FailedWriteLeavesNoFile) {
  test::TempDir dir;
  EXPECT_THROW(writeObj(dir / "missing" / "q.obj", quad()), IoError);
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));

  Mesh bad = quad();
  bad.normals = {{0, 0, 1}};
  EXPECT_THROW(writeObj(dir / "bad.obj", bad), InputError);
  bad = quad();
  bad.triangles.push_back({1, 2, 4});
  EXPECT_THROW(writeObj(dir / "bad.obj", bad), InputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(Obj, ReadBackGivesTheWrittenMeshAndItsNormals) {
  test::TempDir dir;
  Mesh mesh = quad();
  writeObj(dir / "plain.obj", mesh);
  const Mesh plain = readObj(dir / "plain.obj");
  EXPECT_EQ(plain.positions, mesh.positions);  // shortest round-trip text: bit for bit
  EXPECT_EQ(plain.triangles, mesh.triangles);
  EXPECT_TRUE(plain.normals.empty());
  mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, -1, 0}, {0.5f, 0, 0}};
  writeObj(dir / "normals.obj", mesh);
  EXPECT_EQ(readObj(dir / "normals.obj").normals, mesh.normals);
}

TEST(Obj, ReadsPolygonsRelativeIndicesAndOtherExportersLines) {
  test::TempDir dir;
  test::writeFile(dir / "other.obj",
                  "# exported elsewhere\nmtllib m.mtl\no thing\n"
                  "v 0 0 0 1 0 0\nv 1 0 0\r\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
                  "g quad\nusemtl red\ns off\n"
                  "f 1/1/1 2/1/1 3/1/1 4/1/1\n"  // a quad: a fan of two triangles
                  "v 0 0 2\nv 1 0 2\nv 0 1 2\n"
                  "f -3 -2 -1  # relative to the vertices so far\n"
                  "l 1 2\n");
  const Mesh mesh = readObj(dir / "other.obj");
  ASSERT_EQ(mesh.positions.size(), 7u);
  EXPECT_EQ(mesh.positions[0], (mesh::Vec3f{0, 0, 0}));  // colours after x y z ignored
  ASSERT_EQ(mesh.triangles.size(), 3u);
  EXPECT_EQ(mesh.triangles[0], (mesh::Triangle{0, 1, 2}));
  EXPECT_EQ(mesh.triangles[1], (mesh::Triangle{0, 2, 3}));
  EXPECT_EQ(mesh.triangles[2], (mesh::Triangle{4, 5, 6}));
  EXPECT_TRUE(mesh.normals.empty());  // one normal shared by four vertices: not per vertex
}

TEST(Obj, BadFilesAreRefusedByNameAndLine) {
  test::TempDir dir;
  const auto expectInputError = [&](const std::string& name, const std::string& content, const std::string& what) {
    test::expectFileRefused(dir, name, content, what, [](const auto& path) { readObj(path); });
  };
  expectInputError("word.obj", "v 0 0 0\nv 1 zero 0\n", "word.obj':2: expected three finite numbers");
  expectInputError("nan.obj", "v 0 0 nan\n", "finite");
  expectInputError("two.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", ":3: a face with 2 corners");
  expectInputError("zero.obj", "v 0 0 0\nf 0 1 1\n", "expected a vertex index, found '0'");
  expectInputError("relative.obj", "v 0 0 0\nf -1 -2 -3\n", "relative index -2");
  expectInputError("missing.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "refers to vertex 9");
  EXPECT_THROW(readObj(dir / "absent.obj"), IoError);
}

}  // namespace
}  // namespace isovdb::io
