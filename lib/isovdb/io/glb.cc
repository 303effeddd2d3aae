// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/glb.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/io/block_writer.h"
#include "isovdb/io/gltf_codes.h"
#include "isovdb/io/path_util.h"
#include "isovdb/mesh/mesh_checks.h"

namespace isovdb::io {

namespace {

using nlohmann::json;

using gltf::kBinChunk;
using gltf::kFloat;
using gltf::kJsonChunk;
using gltf::kMagic;
using gltf::kTriangles;
using gltf::kUnsignedInt;

/// The scene description: one node, one mesh, one triangle primitive whose arrays
/// lie back to back in the BIN chunk (positions, normals, indices).
json describe(const mesh::Mesh& mesh, std::uint64_t binBytes) {
  json gltf = {{"asset", {{"version", "2.0"}, {"generator", "isovdb"}}}, {"scene", 0}};
  if (!mesh.comments.empty()) gltf["asset"]["extras"] = {{"comments", mesh.comments}};
  if (mesh.triangles.empty()) {
    gltf["scenes"] = json::array({json::object()});
    return gltf;
  }
  std::array<float, 3> low{}, high{};
  for (std::size_t a = 0; a < 3; ++a) {
    low[a] = std::numeric_limits<float>::max();
    high[a] = std::numeric_limits<float>::lowest();
  }
  for (const mesh::Vec3f& p : mesh.positions)
    for (std::size_t a = 0; a < 3; ++a) {
      low[a] = std::min(low[a], p[a]);
      high[a] = std::max(high[a], p[a]);
    }
  const std::uint64_t vertexBytes = 12 * std::uint64_t{mesh.positions.size()};
  json views = json::array();
  json accessors = json::array();
  json attributes = json::object();
  std::uint64_t offset = 0;
  auto addVec3 = [&](const char* name, bool bounds) {
    views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", vertexBytes}, {"target", 34962}});
    json accessor = {{"bufferView", views.size() - 1},
                     {"componentType", kFloat},
                     {"count", mesh.positions.size()},
                     {"type", "VEC3"}};
    if (bounds) {
      accessor["min"] = low;
      accessor["max"] = high;
    }
    attributes[name] = accessors.size();
    accessors.push_back(accessor);
    offset += vertexBytes;
  };
  addVec3("POSITION", true);
  if (!mesh.normals.empty()) addVec3("NORMAL", false);
  views.push_back(
      {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", 12 * mesh.triangles.size()}, {"target", 34963}});
  accessors.push_back({{"bufferView", views.size() - 1},
                       {"componentType", kUnsignedInt},
                       {"count", 3 * mesh.triangles.size()},
                       {"type", "SCALAR"}});
  json primitive = {{"attributes", attributes}, {"indices", accessors.size() - 1}, {"mode", kTriangles}};
  json scene = json::object();
  json node = json::object();
  json gltfMesh = json::object();
  scene["nodes"] = json::array({0});
  node["mesh"] = 0;
  gltfMesh["primitives"] = json::array({primitive});
  gltf["scenes"] = json::array({scene});
  gltf["nodes"] = json::array({node});
  gltf["meshes"] = json::array({gltfMesh});
  gltf["accessors"] = accessors;
  gltf["bufferViews"] = views;
  json buffer = json::object();
  buffer["byteLength"] = binBytes;
  gltf["buffers"] = json::array({buffer});
  return gltf;
}

}  // namespace

void writeGlb(const std::filesystem::path& path, const mesh::Mesh& mesh) {
  mesh::detail::checkIndices(mesh, "cannot write " + quoted(path));
  const bool empty = mesh.triangles.empty();
  const std::uint64_t binBytes =
      empty ? 0 : 12 * (std::uint64_t{mesh.positions.size()} * (mesh.normals.empty() ? 1 : 2) + mesh.triangles.size());
  std::string text = describe(mesh, binBytes).dump();
  text.resize((text.size() + 3) / 4 * 4, ' ');  // chunks are 4-byte aligned; JSON pads with spaces
  const std::uint64_t total = 12 + 8 + text.size() + (empty ? 0 : 8 + binBytes);
  if (total > std::numeric_limits<std::uint32_t>::max())
    throw InputError("cannot write " + quoted(path) + ": " + std::to_string(total) +
                     " bytes, more than a GLB file can hold (4 GiB); write .ply instead");

  AtomicFile file(path);
  BlockWriter out(file);
  out.putLittleEndian(kMagic);
  out.putLittleEndian(std::uint32_t{2});
  out.putLittleEndian(static_cast<std::uint32_t>(total));
  out.putLittleEndian(static_cast<std::uint32_t>(text.size()));
  out.putLittleEndian(kJsonChunk);
  out.put(text.data(), text.size());
  if (!empty) {
    out.putLittleEndian(static_cast<std::uint32_t>(binBytes));
    out.putLittleEndian(kBinChunk);
    for (const mesh::Vec3f& p : mesh.positions)
      for (const float c : p) out.putLittleEndian(c);
    for (const mesh::Vec3f& n : mesh.normals)
      for (const float c : n) out.putLittleEndian(c);
    for (const mesh::Triangle& t : mesh.triangles)
      for (const std::uint32_t v : t) out.putLittleEndian(v);
  }
  out.flush();
  file.commit();
}

}  // namespace isovdb::io
