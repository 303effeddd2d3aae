// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/ply.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "isovdb/errors.h"
#include "isovdb/io/ply_stream_writer.h"
#include "support/test_support.h"

namespace isovdb::io {
namespace {

using mesh::Mesh;
using mesh::Triangle;
using mesh::Vec3f;

Mesh tetrahedron() {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return mesh;
}

/// Floats that a careless writer or reader would change.
Mesh awkwardMesh(bool normals) {
  Mesh mesh;
  const float values[] = {0.1f,
                          -0.f,
                          std::numeric_limits<float>::denorm_min(),
                          std::numeric_limits<float>::max(),
                          -std::numeric_limits<float>::min(),
                          1.f / 3.f,
                          16777217.f,
                          -123456.789f,
                          3.4e-20f};
  for (std::size_t i = 0; i < 300; ++i) {
    mesh.positions.push_back({values[i % 9], values[(i + 1) % 9] * (i % 2 ? 1.f : -1.f), float(i) * 0.7f});
    if (normals) mesh.normals.push_back({values[(i + 4) % 9], float(i) / 7.f, -0.f});
  }
  for (std::uint32_t i = 0; i + 2 < 300; ++i) mesh.triangles.push_back({i, i + 2, 299 - i});
  return mesh;
}

void expectBitIdentical(const std::vector<Vec3f>& a, const std::vector<Vec3f>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(std::bit_cast<std::uint32_t>(a[i][k]), std::bit_cast<std::uint32_t>(b[i][k])) << i << "," << k;
}

void expectMessage(const std::function<void()>& call, const std::string& a, const std::string& b = "") {
  try {
    call();
    FAIL() << "expected InputError containing '" << a << "'";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(a), std::string::npos) << what;
    EXPECT_NE(what.find(b), std::string::npos) << what;
  }
}

TEST(Ply, RoundTripIsExactWithoutNormals) {
  test::TempDir dir;
  const Mesh mesh = awkwardMesh(false);
  writePly(dir / "m.ply", mesh);
  const Mesh back = readPly(dir / "m.ply");
  expectBitIdentical(back.positions, mesh.positions);
  EXPECT_TRUE(back.normals.empty());
  EXPECT_EQ(back.triangles, mesh.triangles);
}

TEST(Ply, RoundTripIsExactWithNormals) {
  test::TempDir dir;
  const Mesh mesh = awkwardMesh(true);
  writePly(dir / "m.ply", mesh);
  const Mesh back = readPly(dir / "m.ply");
  expectBitIdentical(back.positions, mesh.positions);
  expectBitIdentical(back.normals, mesh.normals);
  EXPECT_EQ(back.triangles, mesh.triangles);
}

TEST(Ply, WritesTheDocumentedLayout) {
  test::TempDir dir;
  writePly(dir / "t.ply", tetrahedron());
  const std::string bytes = test::readFile(dir / "t.ply");
  const std::string header = "ply\nformat binary_little_endian 1.0\ncomment written by isovdb\ncomment " +
                             std::string(40, ' ') +
                             "\nelement vertex 4\n"
                             "property float x\nproperty float y\nproperty float z\nelement face 4\n"
                             "property list uchar uint vertex_indices\nend_header\n";
  ASSERT_EQ(bytes.substr(0, header.size()), header);
  ASSERT_EQ(bytes.size(), header.size() + 4 * 12 + 4 * 13);
  // Second vertex's x (1.0f, little-endian) and the last face {1, 2, 3}.
  EXPECT_EQ(bytes.substr(header.size() + 12, 4), std::string("\x00\x00\x80\x3f", 4));
  EXPECT_EQ(bytes.substr(bytes.size() - 13), std::string("\x03\x01\0\0\0\x02\0\0\0\x03\0\0\0", 13));
}

TEST(Ply, ReadsAsciiWithPolygonsExtraPropertiesAndElements) {
  test::TempDir dir;
  test::writeFile(dir / "a.ply",
                  "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\n"
                  "element vertex 5\r\nproperty double x\r\nproperty uchar red\r\nproperty float y\r\n"
                  "property int z\r\nproperty float nx\r\nproperty float ny\r\nproperty float nz\r\n"
                  "element face 2\r\nproperty uchar flags\r\nproperty list uchar int vertex_indices\r\n"
                  "element edge 1\r\nproperty list ushort float stuff\r\nproperty int v1\r\nend_header\r\n"
                  "0.5 255 -1.25 3 0 0 1\r\n1 0 2 4 0 1 0\n2 0 0 0 1 0 0\n3 0 1e-3 -7 0 0 -1\n4 1 2 3 1 1 1\n"
                  "7 4 0 1 2 3\n0 3 4 2 1\n"
                  "2 1.5 2.5 9\n");
  const Mesh mesh = readPly(dir / "a.ply");
  ASSERT_EQ(mesh.positions.size(), 5u);
  EXPECT_EQ(mesh.positions[0], (Vec3f{0.5f, -1.25f, 3.f}));
  EXPECT_EQ(mesh.positions[3], (Vec3f{3.f, 1e-3f, -7.f}));
  ASSERT_EQ(mesh.normals.size(), 5u);
  EXPECT_EQ(mesh.normals[1], (Vec3f{0, 1, 0}));
  EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}, {4, 2, 1}}));
}

std::string bigEndian(const void* value, std::size_t size) {
  std::string bytes(static_cast<const char*>(value), size);
  if constexpr (std::endian::native == std::endian::little) std::reverse(bytes.begin(), bytes.end());
  return bytes;
}
template <typename T>
std::string be(T value) {
  return bigEndian(&value, sizeof value);
}

TEST(Ply, ReadsBigEndianWithOtherTypes) {
  test::TempDir dir;
  std::string bytes =
      "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty double x\nproperty short y\n"
      "property float z\nproperty float nx\nelement face 1\nproperty list int ushort vertex_indices\n"
      "property float quality\nend_header\n";
  const double xs[] = {0.1, -2, 1e10, 0};
  for (int i = 0; i < 4; ++i) bytes += be(xs[i]) + be(std::int16_t(-i)) + be(float(i) * 0.5f) + be(7.f);
  bytes += be(std::int32_t(4)) + be(std::uint16_t(3)) + be(std::uint16_t(2)) + be(std::uint16_t(1)) +
           be(std::uint16_t(0)) + be(1.f);
  test::writeFile(dir / "b.ply", bytes);
  const Mesh mesh = readPly(dir / "b.ply");
  ASSERT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(mesh.positions[0], (Vec3f{0.1f, 0.f, 0.f}));
  EXPECT_EQ(mesh.positions[2], (Vec3f{1e10f, -2.f, 1.f}));
  EXPECT_TRUE(mesh.normals.empty());  // only nx: normals need all three
  EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{3, 2, 1}, {3, 1, 0}}));
}

TEST(Ply, ReadsAPointCloudWithoutFaces) {
  test::TempDir dir;
  test::writeFile(dir / "p.ply",
                  "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                  "property float z\nend_header\n1 2 3\n4 5 6\n");
  const Mesh mesh = readPly(dir / "p.ply");
  EXPECT_EQ(mesh.positions.size(), 2u);
  EXPECT_TRUE(mesh.triangles.empty());
}

TEST(Ply, RejectsTruncatedBinaryData) {
  test::TempDir dir;
  writePly(dir / "t.ply", tetrahedron());
  const std::string bytes = test::readFile(dir / "t.ply");
  test::writeFile(dir / "cut.ply", bytes.substr(0, bytes.size() - 5));
  expectMessage([&] { readPly(dir / "cut.ply"); }, "'" + (dir / "cut.ply").string() + "'", "ends early");
  test::writeFile(dir / "cut2.ply", bytes.substr(0, bytes.size() - 4 * 13 - 30));
  expectMessage([&] { readPly(dir / "cut2.ply"); }, "cut2.ply", "element 'vertex' 1 of 4");
}

TEST(Ply, RejectsTruncatedAscii) {
  test::TempDir dir;
  test::writeFile(dir / "a.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                  "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                  "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n");
  expectMessage([&] { readPly(dir / "a.ply"); }, "a.ply", "ends early, in element 'face' 0 of 1");
}

TEST(Ply, RejectsOutOfRangeIndices) {
  test::TempDir dir;
  test::writeFile(dir / "a.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                  "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
                  "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 9\n");
  expectMessage([&] { readPly(dir / "a.ply"); },
                "'" + (dir / "a.ply").string() + "': face 1 references vertex 9 but the file has 3 vertices");

  Mesh mesh = tetrahedron();
  writePly(dir / "t.ply", mesh);
  std::string bytes = test::readFile(dir / "t.ply");
  bytes[bytes.size() - 4] = '\x05';  // last face: {1, 2, 5}
  test::writeFile(dir / "t.ply", bytes);
  expectMessage([&] { readPly(dir / "t.ply"); }, "t.ply", "face 3 references vertex 5 but the file has 4 vertices");

  test::writeFile(dir / "neg.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                  "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                  "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n");
  expectMessage([&] { readPly(dir / "neg.ply"); }, "neg.ply", "face 0 references vertex -1");
}

TEST(Ply, RejectsBadHeaders) {
  test::TempDir dir;
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  auto check = [&](const std::string& name, const std::string& text, const std::string& expected) {
    test::writeFile(dir / name, text);
    expectMessage([&] { readPly(dir / name); }, "'" + (dir / name).string() + "'", expected);
  };
  check("magic.ply", "plx\nformat ascii 1.0\nend_header\n", "not a PLY file");
  check("format.ply", "ply\nformat binary_middle_endian 1.0\nelement vertex 0\n" + xyz + "end_header\n",
        "unknown format 'binary_middle_endian'");
  check("version.ply", "ply\nformat ascii 2.0\nend_header\n", "unsupported version '2.0'");
  check("noformat.ply", "ply\nelement vertex 0\n" + xyz + "end_header\n", "no format line");
  check("noend.ply", "ply\nformat ascii 1.0\nelement vertex 0\n" + xyz, "no end_header");
  check("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n",
        "header line 4: unknown property type 'float128'");
  check("noz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n",
        "the vertex element has no 'z' property");
  check("novertex.ply", "ply\nformat ascii 1.0\nend_header\n", "no vertex element");
  check("nolist.ply",
        "ply\nformat ascii 1.0\nelement vertex 0\n" + xyz +
            "element face 0\nproperty list uchar int indices\nend_header\n",
        "no 'vertex_indices' list");
  check("orphan.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n", "property before any element");
  check("count.ply", "ply\nformat ascii 1.0\nelement vertex -3\nend_header\n", "bad count '-3'");
  check("value.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz + "end_header\n1 zwei 3\n",
        "bad value 'zwei' in element 'vertex' 0 of 1, property 'y'");
  check("small.ply",
        "ply\nformat ascii 1.0\nelement vertex 2\n" + xyz +
            "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 1 1\n2 0 1\n",
        "face 0 has 2 vertices");
  check("nan.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz + "end_header\n1 nan 3\n",
        "vertex 0 has a non-finite coordinate");
}

TEST(Ply, MissingFileIsAnIoError) {
  test::TempDir dir;
  EXPECT_THROW(readPly(dir / "missing.ply"), IoError);
}

TEST(Ply, FailedWriteLeavesNoFile) {
  test::TempDir dir;
  EXPECT_THROW(writePly(dir / "no" / "such" / "dir.ply", tetrahedron()), IoError);
  EXPECT_FALSE(std::filesystem::exists(dir / "no"));

  Mesh bad = tetrahedron();
  bad.triangles.push_back({0, 1, 4});
  EXPECT_THROW(writePly(dir / "bad.ply", bad), InputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(PlyStreamWriter, PiecesMakeTheSameBytesAsWritePly) {
  test::TempDir dir;
  const Mesh mesh = tetrahedron();
  {
    PlyStreamWriter writer(dir / "streamed.ply", {2, 2, 2}, {1, 0, 0});
    writer.addVertices(std::span(mesh.positions).first(2));
    writer.addTriangles({});  // an empty piece is fine
    writer.addVertices(std::span(mesh.positions).subspan(2));
    writer.addTriangles(std::span(mesh.triangles).first(1));
    writer.addTriangles(std::span(mesh.triangles).subspan(1));
    EXPECT_EQ(writer.vertexCount(), mesh.positions.size());
    EXPECT_EQ(writer.triangleCount(), mesh.triangles.size());
    EXPECT_FALSE(std::filesystem::exists(dir / "streamed.ply"));  // nothing before commit
    writer.commit();
  }
  const Mesh back = readPly(dir / "streamed.ply");
  ASSERT_EQ(back.positions.size(), mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    for (int a = 0; a < 3; ++a) EXPECT_EQ(back.positions[i][a], (a == 0 ? 1.0f : 0.0f) + 2.0f * mesh.positions[i][a]);
  EXPECT_EQ(back.triangles, mesh.triangles);
  // Only the temporaries' names hold the output's name: none is left behind.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
  // Without a scale, streamed and whole are the same bytes (a run's output does not
  // depend on which writer the method uses), whether the triangles wait in memory or
  // spill to a temporary file before it (a budget of none, or of two triangles' bytes:
  // the first piece waits, the rest spill).
  writePly(dir / "whole.ply", mesh);
  for (const std::size_t budget : {PlyStreamWriter::kDefaultTriangleBytesInMemory, std::size_t{0}, std::size_t{26}}) {
    SCOPED_TRACE(budget);
    {
      PlyStreamWriter writer(dir / "identity.ply", {1, 1, 1}, {0, 0, 0}, budget);
      writer.addVertices(mesh.positions);
      writer.addTriangles(std::span(mesh.triangles).first(2));
      writer.addTriangles(std::span(mesh.triangles).subspan(2));
      writer.commit();
    }
    EXPECT_EQ(test::readFile(dir / "identity.ply"), test::readFile(dir / "whole.ply"));
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 3);  // no spill file left
  }
}

TEST(PlyStreamWriter, ABadTriangleOrAnAbandonedWriterLeavesNoFile) {
  test::TempDir dir;
  const Mesh mesh = tetrahedron();
  {
    PlyStreamWriter writer(dir / "bad.ply");
    writer.addVertices(mesh.positions);
    const std::array<mesh::Triangle, 1> bad{mesh::Triangle{0, 1, 4}};
    EXPECT_THROW(writer.addTriangles(bad), InputError);
  }
  {
    PlyStreamWriter writer(dir / "abandoned.ply");  // an interrupted run never commits
    writer.addVertices(mesh.positions);
  }
  {
    PlyStreamWriter writer(dir / "spilled.ply", {1, 1, 1}, {0, 0, 0}, 0);  // nor its spilled triangles
    writer.addVertices(mesh.positions);
    writer.addTriangles(mesh.triangles);
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
  EXPECT_THROW(PlyStreamWriter(dir / "no" / "dir.ply"), IoError);
}

}  // namespace
}  // namespace isovdb::io
