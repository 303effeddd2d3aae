// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/glb.h"
#include "isovdb/io/gltf_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "isovdb/errors.h"
#include "isovdb/io/mesh_file.h"
#include "mesh_file_test_support.h"
#include "support/test_support.h"

namespace isovdb::io {
namespace {

using mesh::Mesh;

template <class T>
void append(std::string& bytes, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));  // the tests run on little-endian machines
  bytes.append(raw, sizeof(T));
}

/// A .glb file of `json` and `bin`, built the way other exporters lay it out.
std::string glb(std::string json, const std::string& bin) {
  json.resize((json.size() + 3) / 4 * 4, ' ');
  std::string bytes = "glTF";
  append(bytes, std::uint32_t{2});
  append(bytes, static_cast<std::uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
  append(bytes, static_cast<std::uint32_t>(json.size()));
  bytes += "JSON" + json;
  if (!bin.empty()) {
    append(bytes, static_cast<std::uint32_t>(bin.size()));
    bytes += std::string("BIN\0", 4) + bin;
  }
  return bytes;
}

TEST(Glb, LayoutIsBinaryGltf2WithBoundsAndUint32Indices) {
  test::TempDir dir;
  writeGlb(dir / "t.glb", test::tetrahedron());
  const std::string bytes = test::readFile(dir / "t.glb");
  ASSERT_GE(bytes.size(), 20u);
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  std::uint32_t header[5];
  std::memcpy(header, bytes.data(), sizeof header);
  EXPECT_EQ(header[1], 2u);
  EXPECT_EQ(header[2], bytes.size());
  EXPECT_EQ(header[3] % 4, 0u);
  const auto gltf = nlohmann::json::parse(bytes.substr(20, header[3]));
  EXPECT_EQ(gltf["asset"]["version"], "2.0");
  const auto& primitive = gltf["meshes"][0]["primitives"][0];
  EXPECT_EQ(primitive["mode"], 4);
  const auto& position = gltf["accessors"][primitive["attributes"]["POSITION"].get<int>()];
  EXPECT_EQ(position["count"], 4);
  EXPECT_EQ(position["min"], nlohmann::json::parse("[0.0, 0.0, -0.25]"));
  EXPECT_EQ(position["max"], nlohmann::json::parse("[1.5, 2.0, 0.0]"));
  EXPECT_EQ(gltf["accessors"][primitive["indices"].get<int>()]["componentType"], 5125);
  EXPECT_FALSE(primitive["attributes"].contains("NORMAL"));
  const std::size_t binAt = 20 + header[3];
  std::uint32_t binLength = 0;
  std::memcpy(&binLength, bytes.data() + binAt, 4);
  EXPECT_EQ(binLength, 4u * 12 + 4u * 12);  // positions, then 12 indices
  EXPECT_EQ(bytes.substr(binAt + 4, 4), std::string("BIN\0", 4));
  EXPECT_EQ(gltf["buffers"][0]["byteLength"], binLength);
}

TEST(Glb, RoundTripKeepsVerticesTrianglesAndNormalsBitForBit) {
  test::TempDir dir;
  Mesh mesh = test::tetrahedron();
  mesh.normals = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0.6f, 0, -0.8f}};
  writeMesh(dir / "t.GLB", mesh);  // by extension, any case
  const Mesh back = readMesh(dir / "t.GLB");
  EXPECT_EQ(back.positions, mesh.positions);
  EXPECT_EQ(back.triangles, mesh.triangles);
  EXPECT_EQ(back.normals, mesh.normals);
  writeGlb(dir / "empty.glb", Mesh{});
  EXPECT_TRUE(readGltf(dir / "empty.glb").empty());
}

TEST(Glb, ReadsOtherExportersLayouts) {
  // Two primitives: one with uint16 indices in an interleaved view (stride 24, a
  // position and a colour per vertex), one without indices (consecutive corners).
  std::string bin;
  const float quad[4][6] = {{0, 0, 0, 9, 9, 9}, {1, 0, 0, 9, 9, 9}, {1, 1, 0, 9, 9, 9}, {0, 1, 0, 9, 9, 9}};
  for (const auto& vertex : quad)
    for (const float c : vertex) append(bin, c);
  for (const std::uint16_t i : {0, 1, 2, 0, 2, 3}) append(bin, i);                              // 96 + 12 bytes
  for (const float c : {0.0f, 0.0f, 5.0f, 1.0f, 0.0f, 5.0f, 0.0f, 1.0f, 5.0f}) append(bin, c);  // at 108
  const std::string json = R"({"asset":{"version":"2.0"},
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1},{"attributes":{"POSITION":2}}]}],
    "accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},
                 {"bufferView":1,"componentType":5123,"count":6,"type":"SCALAR"},
                 {"bufferView":2,"componentType":5126,"count":3,"type":"VEC3"}],
    "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":96,"byteStride":24},
                   {"buffer":0,"byteOffset":96,"byteLength":12},
                   {"buffer":0,"byteOffset":108,"byteLength":36}],
    "buffers":[{"byteLength":144}]})";
  test::TempDir dir;
  test::writeFile(dir / "other.glb", glb(json, bin));
  const Mesh mesh = readGltf(dir / "other.glb");
  ASSERT_EQ(mesh.positions.size(), 7u);
  EXPECT_EQ(mesh.positions[2], (mesh::Vec3f{1, 1, 0}));
  EXPECT_EQ(mesh.positions[6], (mesh::Vec3f{0, 1, 5}));
  ASSERT_EQ(mesh.triangles.size(), 3u);
  EXPECT_EQ(mesh.triangles[1], (mesh::Triangle{0, 2, 3}));
  EXPECT_EQ(mesh.triangles[2], (mesh::Triangle{4, 5, 6}));
  EXPECT_TRUE(mesh.normals.empty());
}

TEST(Glb, BadFilesAreRefusedByName) {
  test::TempDir dir;
  const auto expectInputError = [&](const std::string& name, const std::string& content, const std::string& what) {
    test::expectFileRefused(dir, name, content, what, [](const auto& path) { readGltf(path); });
  };
  expectInputError("text.glb", R"({"asset":{"version":"2.0"}})", "no 'glTF' magic");
  std::string good = test::readFile([&] {
    writeGlb(dir / "t.glb", test::tetrahedron());
    return dir / "t.glb";
  }());
  expectInputError("truncated.glb", good.substr(0, good.size() - 8), "truncated");
  std::string v1 = good;
  v1[4] = 1;
  expectInputError("v1.glb", v1, "version 1");
  const std::string positions(48, '\0');
  const auto oneTriangle = [](const std::string& primitive, const std::string& indexType) {
    return R"({"asset":{"version":"2.0"},"meshes":[{"primitives":[)" + primitive + R"(]}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},
                   {"bufferView":1,"componentType":)" +
           indexType + R"(,"count":3,"type":"SCALAR"}],
      "bufferViews":[{"buffer":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":12}],
      "buffers":[{"byteLength":60}]})";
  };
  std::string indices;
  for (const std::uint32_t i : {0u, 1u, 7u}) append(indices, i);
  expectInputError("index.glb",
                   glb(oneTriangle(R"({"attributes":{"POSITION":0},"indices":1})", "5125"), positions + indices),
                   "index 7 but 4 vertices");
  expectInputError("lines.glb",
                   glb(oneTriangle(R"({"attributes":{"POSITION":0},"mode":1})", "5125"), positions + indices),
                   "only triangle lists");
  expectInputError("signed.glb",
                   glb(oneTriangle(R"({"attributes":{"POSITION":0},"indices":1})", "5124"), positions + indices),
                   "componentType 5124");
  expectInputError("short.glb", glb(oneTriangle(R"({"attributes":{"POSITION":0},"indices":1})", "5125"), positions),
                   "buffers[0] declares 60 bytes but holds 48");
  expectInputError("json.glb", glb("{\"asset\":", ""), "malformed JSON");
  EXPECT_THROW(readGltf(dir / "missing.glb"), IoError);
}

/// A triangle (0,0,0) (1,0,0) (0,1,0) with +z normals as a glTF buffer: positions, normals, indices.
std::string triangleBuffer() {
  std::string bin;
  for (const float c : {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f}) append(bin, c);
  for (int v = 0; v < 3; ++v)
    for (const float c : {0.0f, 0.0f, 1.0f}) append(bin, c);
  for (const std::uint32_t i : {0u, 1u, 2u}) append(bin, i);
  return bin;  // 84 bytes
}

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t bits = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) bits |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) bits |= static_cast<unsigned char>(bytes[i + 2]);
    const std::size_t present = std::min<std::size_t>(3, bytes.size() - i);  // bytes in this group
    for (std::size_t k = 0; k < 4; ++k) out += k <= present ? digits[(bits >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

/// glTF JSON for the triangle mesh, used by `nodes` (a JSON array) in scene 0 of `roots`.
std::string triangleScene(const std::string& nodes, const std::string& roots, const std::string& uri) {
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":)" + roots + R"(}],"nodes":)" + nodes + R"(,
    "meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1},"indices":2}]}],
    "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},
                 {"bufferView":1,"componentType":5126,"count":3,"type":"VEC3"},
                 {"bufferView":2,"componentType":5125,"count":3,"type":"SCALAR"}],
    "bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":36},
                   {"buffer":0,"byteOffset":72,"byteLength":12}],
    "buffers":[{"byteLength":84)" +
         (uri.empty() ? "" : R"(,"uri":")" + uri + "\"") + "}]}";
}

TEST(Gltf, NodeTransformsPlaceEachInstanceAndMirrorsKeepTheWinding) {
  test::TempDir dir;
  // Node 0 moves its child (node 1, the mesh, scaled by 2) by (10, 0, 0); node 2 is the
  // mesh mirrored in x by a matrix (column-major); node 3 turns it 90 degrees about z.
  const std::string nodes = R"([{"translation":[10,0,0],"children":[1]},{"mesh":0,"scale":[2,2,2]},
    {"mesh":0,"matrix":[-1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,5,1]},
    {"mesh":0,"rotation":[0,0,0.7071067811865476,0.7071067811865476]}])";
  test::writeFile(dir / "scene.gltf",
                  triangleScene(nodes, "[0,2,3]", "data:application/octet-stream;base64," + base64(triangleBuffer())));
  const Mesh mesh = readMesh(dir / "scene.gltf");
  ASSERT_EQ(mesh.positions.size(), 9u);
  ASSERT_EQ(mesh.triangles.size(), 3u);
  EXPECT_EQ(mesh.positions[1], (mesh::Vec3f{12, 0, 0}));  // 2 x (1,0,0) + (10,0,0)
  EXPECT_EQ(mesh.positions[2], (mesh::Vec3f{10, 2, 0}));
  EXPECT_EQ(mesh.positions[4], (mesh::Vec3f{-1, 0, 5}));
  EXPECT_NEAR(mesh.positions[7][1], 1.0f, 1e-6f);  // (1,0,0) turned to (0,1,0)
  EXPECT_NEAR(mesh.positions[7][0], 0.0f, 1e-6f);
  EXPECT_EQ(mesh.triangles[0], (mesh::Triangle{0, 1, 2}));
  EXPECT_EQ(mesh.triangles[1], (mesh::Triangle{3, 5, 4}));  // mirrored: the winding turned back
  ASSERT_EQ(mesh.normals.size(), 9u);
  EXPECT_EQ(mesh.normals[4], (mesh::Vec3f{0, 0, 1}));  // a mirror in x keeps +z, unit length
  EXPECT_EQ(mesh.normals[1], (mesh::Vec3f{0, 0, 1}));  // a uniform scale leaves unit normals unit
}

TEST(Gltf, ExternalBuffersBesideTheFileAndGlbBinChunksGiveTheSameMesh) {
  test::TempDir dir;
  const std::string nodes = R"([{"mesh":0,"translation":[0,0,1]}])";
  test::writeFile(dir / "tri mesh.bin", triangleBuffer());
  test::writeFile(dir / "a.gltf", triangleScene(nodes, "[0]", "tri%20mesh.bin"));
  test::writeFile(dir / "b.glb", glb(triangleScene(nodes, "[0]", ""), triangleBuffer()));
  const Mesh a = readMesh(dir / "a.gltf");
  const Mesh b = readMesh(dir / "b.glb");
  ASSERT_EQ(a.positions.size(), 3u);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.positions[1], (mesh::Vec3f{1, 0, 1}));
}

TEST(Gltf, KhronosSampleBoxIsPlacedByItsNodes) {
  // glTF-Sample-Models' Box (data/meshes/PROVENANCE.md): its root node's matrix maps
  // (x, y, z) to (x, z, -y); the first face's normal (0, 0, 1) becomes (0, 1, 0).
  const Mesh box = readMesh(test::dataDir() / "meshes" / "Box-embedded.gltf");
  ASSERT_EQ(box.positions.size(), 24u);
  ASSERT_EQ(box.triangles.size(), 12u);
  ASSERT_EQ(box.normals.size(), 24u);
  EXPECT_EQ(box.positions[0], (mesh::Vec3f{-0.5f, 0.5f, 0.5f}));
  EXPECT_EQ(box.normals[0], (mesh::Vec3f{0, 1, 0}));
  // Every triangle faces the way its vertex normals point: positions and normals were
  // turned by the same transform, and the winding kept.
  for (const mesh::Triangle& t : box.triangles) {
    const mesh::Vec3f &a = box.positions[t[0]], &b = box.positions[t[1]], &c = box.positions[t[2]];
    const mesh::Vec3f u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const mesh::Vec3f n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    for (const std::uint32_t corner : t) {
      const mesh::Vec3f& m = box.normals[corner];
      EXPECT_GT(n[0] * m[0] + n[1] * m[1] + n[2] * m[2], 0.0f);
    }
  }
}

TEST(Gltf, BadScenesAndBuffersAreRefusedByName) {
  test::TempDir dir;
  const std::string data = "data:application/octet-stream;base64," + base64(triangleBuffer());
  const auto expectInputError = [&](const std::string& name, const std::string& content, const std::string& what) {
    test::expectFileRefused(dir, name, content, what, [](const auto& path) { readMesh(path); });
  };
  expectInputError("parents.gltf", triangleScene(R"([{"children":[2]},{"children":[2]},{"mesh":0}])", "[0,1]", data),
                   "nodes[2] has two parents");
  expectInputError("cycle.gltf", triangleScene(R"([{"children":[1]},{"children":[0]}])", "[0]", data),
                   "nodes[0] is not a root node");
  expectInputError("self.gltf", triangleScene(R"([{"children":[0]}])", "[0]", data), "not another node");
  expectInputError("singular.gltf", triangleScene(R"([{"mesh":0,"scale":[1,0,1]}])", "[0]", data),
                   "singular transform");
  expectInputError("projective.gltf",
                   triangleScene(R"([{"mesh":0,"matrix":[1,0,0,1, 0,1,0,0, 0,0,1,0, 0,0,0,1]}])", "[0]", data),
                   "not affine");
  expectInputError("nan.gltf", triangleScene(R"([{"mesh":0,"translation":[0,"x",0]}])", "[0]", data),
                   "nodes[0].translation holds \"x\"");
  // 400 instances of a 99,999-vertex mesh: 40 M vertices from a 1.2 MB buffer.
  test::writeFile(dir / "soup.bin", std::string(1'200'000, '\0'));
  std::string many = "[", roots = "[";
  for (int i = 0; i < 400; ++i) {
    many += std::string(i ? "," : "") + R"({"mesh":0})";
    roots += (i ? "," : "") + std::to_string(i);
  }
  expectInputError("instances.gltf",
                   R"({"asset":{"version":"2.0"},"scenes":[{"nodes":)" + roots + R"(]}],"nodes":)" + many +
                       R"(],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":99999,"type":"VEC3"}],
      "bufferViews":[{"buffer":0,"byteLength":1199988}],"buffers":[{"byteLength":1200000,"uri":"soup.bin"}]})",
                   "16 times the vertices");
  expectInputError("missing.gltf", triangleScene(R"([{"mesh":0}])", "[0]", "nowhere.bin"),
                   "nowhere.bin' is not a readable file");
  expectInputError("base64.gltf", triangleScene(R"([{"mesh":0}])", "[0]", "data:application/octet-stream;base64,@@"),
                   "not valid base64");
  expectInputError("short.gltf", triangleScene(R"([{"mesh":0}])", "[0]", "data:;base64,AAAA"),
                   "declares 84 bytes but holds 3");
  expectInputError("http.gltf", triangleScene(R"([{"mesh":0}])", "[0]", "https://example.com/a.bin"),
                   "not a file beside the .gltf");
  expectInputError("text.gltf", "solid cube\n", "neither glTF JSON text nor binary glTF");
}

TEST(Glb, BadMeshWritesNothing) {
  test::TempDir dir;
  test::expectBadMeshWritesNothing(dir, "bad.glb", [](const auto& path, const auto& mesh) { writeGlb(path, mesh); });
}

}  // namespace
}  // namespace isovdb::io
