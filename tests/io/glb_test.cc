// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/glb.h"

#include <gtest/gtest.h>

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
  EXPECT_TRUE(readGlb(dir / "empty.glb").empty());
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
  const Mesh mesh = readGlb(dir / "other.glb");
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
    test::expectFileRefused(dir, name, content, what, [](const auto& path) { readGlb(path); });
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
                   "outside the BIN chunk");
  expectInputError("json.glb", glb("{\"asset\":", ""), "malformed JSON");
  EXPECT_THROW(readGlb(dir / "missing.glb"), IoError);
}

TEST(Glb, BadMeshWritesNothing) {
  test::TempDir dir;
  test::expectBadMeshWritesNothing(dir, "bad.glb", [](const auto& path, const auto& mesh) { writeGlb(path, mesh); });
}

}  // namespace
}  // namespace isovdb::io
