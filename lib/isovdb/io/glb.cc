// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/glb.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/io/block_writer.h"
#include "isovdb/io/little_endian.h"
#include "isovdb/io/path_util.h"
#include "isovdb/io/whole_file.h"
#include "isovdb/mesh/mesh_checks.h"

namespace isovdb::io {

namespace {

using nlohmann::json;

constexpr std::uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"
constexpr int kFloat = 5126;                      // glTF componentType codes
constexpr int kUnsignedByte = 5121;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kTriangles = 4;

/// The scene description: one node, one mesh, one triangle primitive whose arrays
/// lie back to back in the BIN chunk (positions, normals, indices).
json describe(const mesh::Mesh& mesh, std::uint64_t binBytes) {
  json gltf = {{"asset", {{"version", "2.0"}, {"generator", "isovdb"}}}, {"scene", 0}};
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

/// The parsed chunks of a .glb file and the accessor reads over them; every
/// failure names the file.
class GlbFile {
 public:
  explicit GlbFile(const std::filesystem::path& path) : path_(path), bytes_(readWholeFile(path)) {
    if (bytes_.size() < 12 || readLittleEndian<std::uint32_t>(bytes_.data()) != kMagic)
      fail("not a binary glTF file (no 'glTF' magic at the start; .gltf text files are not read)");
    const auto version = readLittleEndian<std::uint32_t>(bytes_.data() + 4);
    if (version != 2) fail("glTF version " + std::to_string(version) + ", only version 2 is read");
    const std::uint64_t length = readLittleEndian<std::uint32_t>(bytes_.data() + 8);
    if (length > bytes_.size())
      fail("the header declares " + std::to_string(length) + " bytes, the file has " + std::to_string(bytes_.size()) +
           " (truncated)");
    std::uint64_t at = 12;
    std::string_view jsonText;
    for (int chunk = 0; at < length; ++chunk) {
      if (length - at < 8) fail("a chunk header is cut off at byte " + std::to_string(at));
      const std::uint64_t size = readLittleEndian<std::uint32_t>(bytes_.data() + at);
      const auto type = readLittleEndian<std::uint32_t>(bytes_.data() + at + 4);
      if (size > length - at - 8)
        fail("chunk " + std::to_string(chunk) + " of " + std::to_string(size) + " bytes runs past the end");
      const std::string_view data(bytes_.data() + at + 8, size);
      if (chunk == 0 && type != kJsonChunk) fail("the first chunk is not JSON");
      if (chunk == 0) jsonText = data;
      if (chunk == 1 && type == kBinChunk) bin_ = data;
      at += 8 + size;
    }
    if (jsonText.empty()) fail("no JSON chunk");
    try {
      gltf_ = json::parse(jsonText);
    } catch (const json::exception& e) {
      fail(std::string("malformed JSON chunk: ") + e.what());
    }
  }

  const json& gltf() const { return gltf_; }

  /// Appends the elements of accessor `index` to `out` as `width`-component
  /// values converted by `convert(const char*)`; `types` are the accepted
  /// componentTypes and `type` the accessor type ("VEC3", "SCALAR").
  template <class T, class Convert>
  void readAccessor(std::uint64_t index, const char* type, std::initializer_list<int> types, std::size_t width,
                    std::vector<T>& out, const Convert& convert) const {
    const json& accessor = element("accessors", index);
    const std::string what = "accessor " + std::to_string(index);
    if (accessor.contains("sparse")) fail(what + " is sparse, which is not read");
    if (accessor.value("type", "") != type) fail(what + " is not of type " + type);
    const int component = accessor.value("componentType", 0);
    if (std::find(types.begin(), types.end(), component) == types.end())
      fail(what + " has componentType " + std::to_string(component) + ", not one read here");
    const std::uint64_t componentBytes = component == kUnsignedByte ? 1 : component == kUnsignedShort ? 2 : 4;
    const std::uint64_t count = number(accessor, "count", what);
    if (!accessor.contains("bufferView")) fail(what + " has no bufferView");
    const std::uint64_t viewIndex = number(accessor, "bufferView", what);
    const json& view = element("bufferViews", viewIndex);
    const std::string viewWhat = "bufferView " + std::to_string(viewIndex);
    if (number(view, "buffer", viewWhat) != 0 || element("buffers", 0).contains("uri"))
      fail(viewWhat + " is not in the file's BIN chunk (external buffers are not read)");
    const std::uint64_t elementBytes = width * componentBytes;
    const std::uint64_t stride = view.contains("byteStride") ? number(view, "byteStride", viewWhat) : elementBytes;
    const std::uint64_t viewOffset = view.contains("byteOffset") ? number(view, "byteOffset", viewWhat) : 0;
    const std::uint64_t viewLength = number(view, "byteLength", viewWhat);
    const std::uint64_t offset = accessor.contains("byteOffset") ? number(accessor, "byteOffset", what) : 0;
    if (viewOffset > bin_.size() || viewLength > bin_.size() - viewOffset)
      fail(viewWhat + " lies outside the BIN chunk (" + std::to_string(bin_.size()) + " bytes)");
    if (stride < elementBytes || (count > 0 && (offset > viewLength || elementBytes > viewLength - offset ||
                                                (count - 1) > (viewLength - offset - elementBytes) / stride)))
      fail(what + " (" + std::to_string(count) + " elements) does not fit in its bufferView");
    const char* base = bin_.data() + viewOffset + offset;
    out.reserve(out.size() + count);
    for (std::uint64_t i = 0; i < count; ++i) {
      T value{};
      for (std::size_t c = 0; c < width; ++c) convert(base + i * stride + c * componentBytes, component, value, c);
      out.push_back(value);
    }
  }

  [[noreturn]] void fail(const std::string& what) const { throw InputError(quoted(path_) + ": " + what); }

  std::uint64_t number(const json& object, const char* key, const std::string& what) const {
    const auto it = object.find(key);
    if (it == object.end() || !it->is_number_integer() || it->get<std::int64_t>() < 0)
      fail(what + ": '" + key + "' is missing or not a non-negative integer");
    return it->get<std::uint64_t>();
  }

  const json& element(const char* array, std::uint64_t index) const {
    const auto it = gltf_.find(array);
    if (it == gltf_.end() || !it->is_array() || index >= it->size() || !(*it)[index].is_object())
      fail(std::string("no ") + array + "[" + std::to_string(index) + "]");
    return (*it)[index];
  }

 private:
  const std::filesystem::path& path_;
  std::string bytes_;
  json gltf_;
  std::string_view bin_;
};

void readFloat(const char* p, int, mesh::Vec3f& value, std::size_t c) { value[c] = readLittleEndian<float>(p); }

void readIndex(const char* p, int component, std::uint64_t& value, std::size_t) {
  value = component == kUnsignedByte    ? std::uint64_t{static_cast<unsigned char>(*p)}
          : component == kUnsignedShort ? std::uint64_t{readLittleEndian<std::uint16_t>(p)}
                                        : std::uint64_t{readLittleEndian<std::uint32_t>(p)};
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

mesh::Mesh readGlb(const std::filesystem::path& path) {
  const GlbFile file(path);
  const json& gltf = file.gltf();
  mesh::Mesh m;
  bool normals = true;
  std::vector<mesh::Vec3f> normalValues;
  const auto meshes = gltf.find("meshes");
  const std::size_t meshCount = meshes != gltf.end() && meshes->is_array() ? meshes->size() : 0;
  for (std::size_t mi = 0; mi < meshCount; ++mi) {
    const json& gm = file.element("meshes", mi);
    const auto primitives = gm.find("primitives");
    if (primitives == gm.end() || !primitives->is_array())
      file.fail("meshes[" + std::to_string(mi) + "] has no primitives");
    for (std::size_t pi = 0; pi < primitives->size(); ++pi) {
      const json& primitive = (*primitives)[pi];
      const std::string what = "meshes[" + std::to_string(mi) + "].primitives[" + std::to_string(pi) + "]";
      if (!primitive.is_object() || !primitive.contains("attributes") || !primitive["attributes"].is_object())
        file.fail(what + " has no attributes");
      if (primitive.contains("mode") && file.number(primitive, "mode", what) != kTriangles)
        file.fail(what + " has mode " + primitive["mode"].dump() + "; only triangle lists (mode 4) are read");
      const json& attributes = primitive["attributes"];
      if (!attributes.contains("POSITION")) file.fail(what + " has no POSITION");
      const std::size_t base = m.positions.size();
      file.readAccessor(file.number(attributes, "POSITION", what), "VEC3", {kFloat}, 3, m.positions, readFloat);
      const std::uint64_t added = m.positions.size() - base;
      for (std::size_t v = base; v < m.positions.size(); ++v)
        for (const float c : m.positions[v])
          if (!std::isfinite(c)) file.fail(what + ": vertex " + std::to_string(v - base) + " is not finite");
      normals = normals && attributes.contains("NORMAL");
      if (normals) {
        file.readAccessor(file.number(attributes, "NORMAL", what), "VEC3", {kFloat}, 3, normalValues, readFloat);
        if (normalValues.size() != m.positions.size()) file.fail(what + ": NORMAL and POSITION counts differ");
      }
      std::vector<std::uint64_t> corners;
      if (primitive.contains("indices")) {
        file.readAccessor(file.number(primitive, "indices", what), "SCALAR",
                          {kUnsignedByte, kUnsignedShort, kUnsignedInt}, 1, corners, readIndex);
      } else {
        corners.resize(added);
        for (std::uint64_t i = 0; i < added; ++i) corners[i] = i;
      }
      if (corners.size() % 3 != 0)
        file.fail(what + ": " + std::to_string(corners.size()) + " corners, not a whole number of triangles");
      if (m.positions.size() > std::numeric_limits<std::uint32_t>::max()) file.fail("more than 2^32 - 1 vertices");
      for (std::size_t c = 0; c < corners.size(); c += 3) {
        mesh::Triangle t;
        for (std::size_t k = 0; k < 3; ++k) {
          if (corners[c + k] >= added)
            file.fail(what + ": index " + std::to_string(corners[c + k]) + " but " + std::to_string(added) +
                      " vertices");
          t[k] = static_cast<std::uint32_t>(base + corners[c + k]);
        }
        m.triangles.push_back(t);
      }
    }
  }
  if (normals && !m.positions.empty()) m.normals = std::move(normalValues);
  return m;
}

}  // namespace isovdb::io
