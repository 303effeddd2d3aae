// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/gltf_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "isovdb/errors.h"
#include "isovdb/io/gltf_codes.h"
#include "isovdb/io/little_endian.h"
#include "isovdb/io/path_util.h"
#include "isovdb/io/whole_file.h"

namespace isovdb::io {

namespace {

using gltf::kBinChunk;
using gltf::kFloat;
using gltf::kJsonChunk;
using gltf::kMagic;
using gltf::kTriangles;
using gltf::kUnsignedByte;
using gltf::kUnsignedShort;
using nlohmann::json;

/// How many times the vertices the file could hold (12 bytes each, at least 2^16) a scene
/// may place by instancing its meshes: beyond, a few nodes could ask for gigabytes.
constexpr std::uint64_t kInstancingLimit = 16;

/// A base64 digit's value, or -1.
int base64Digit(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

/// `text` decoded from base64 ('=' padding optional); std::nullopt-like empty flag in `ok`.
std::string decodeBase64(std::string_view text, bool& ok) {
  std::string out;
  out.reserve(text.size() / 4 * 3);
  std::uint32_t bits = 0;
  int count = 0;
  ok = true;
  for (const char c : text) {
    if (c == '=') break;
    const int digit = base64Digit(c);
    if (digit < 0) {
      ok = false;
      return out;
    }
    bits = (bits << 6) | static_cast<std::uint32_t>(digit);
    if (++count == 4) {
      out.push_back(static_cast<char>((bits >> 16) & 0xFF));
      out.push_back(static_cast<char>((bits >> 8) & 0xFF));
      out.push_back(static_cast<char>(bits & 0xFF));
      bits = 0;
      count = 0;
    }
  }
  if (count == 1) ok = false;
  if (count >= 2) out.push_back(static_cast<char>((bits >> (6 * count - 8)) & 0xFF));
  if (count == 3) out.push_back(static_cast<char>((bits >> 2) & 0xFF));
  return out;
}

/// A relative URI's %XX escapes decoded (glTF's URIs are RFC 3986).
std::string decodePercent(std::string_view uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out.push_back(static_cast<char>(std::stoi(std::string(uri.substr(i + 1, 2)), nullptr, 16)));
      i += 2;
    } else {
      out.push_back(uri[i]);
    }
  }
  return out;
}

/// The JSON and the buffers of a .glb or .gltf file, and the accessor reads over them;
/// every failure names the file.
class GltfFile {
 public:
  explicit GltfFile(const std::filesystem::path& path) : path_(path), bytes_(readWholeFile(path)) {
    std::string_view jsonText = bytes_;
    std::string_view binChunk;
    const bool binary = bytes_.size() >= 4 && readLittleEndian<std::uint32_t>(bytes_.data()) == kMagic;
    if (binary) {
      readChunks(jsonText, binChunk);
    } else if (lowerExtension(path) == ".glb") {
      fail("not a binary glTF file (no 'glTF' magic at the start; glTF text is read from .gltf files)");
    } else if (jsonText.find_first_not_of(" \t\r\n") == std::string_view::npos ||
               jsonText[jsonText.find_first_not_of(" \t\r\n")] != '{') {
      fail("neither glTF JSON text nor binary glTF");
    }
    try {
      gltf_ = json::parse(jsonText);
    } catch (const json::exception& e) {
      fail(std::string("malformed JSON") + (binary ? " chunk: " : ": ") + e.what());
    }
    if (!gltf_.is_object()) fail("the JSON is not an object");
    if (const auto asset = gltf_.find("asset");
        asset != gltf_.end() && asset->is_object() && asset->contains("version") &&
        (!(*asset)["version"].is_string() || (*asset)["version"].get<std::string>().rfind("2.", 0) != 0))
      fail("glTF version " + (*asset)["version"].dump() + ", only version 2 is read");
    loadBuffers(binary, binChunk);
  }

  const json& gltf() const { return gltf_; }
  /// Bytes of the file and of its buffers: what the scene may instance is bounded by it.
  std::uint64_t dataBytes() const {
    std::uint64_t total = bytes_.size();
    for (const std::string& b : external_) total += b.size();
    return total;
  }

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
    const std::uint64_t bufferIndex = number(view, "buffer", viewWhat);
    if (bufferIndex >= buffers_.size()) fail(viewWhat + ": no buffers[" + std::to_string(bufferIndex) + "]");
    const std::string_view buffer = buffers_[bufferIndex];
    const std::uint64_t elementBytes = width * componentBytes;
    const std::uint64_t stride = view.contains("byteStride") ? number(view, "byteStride", viewWhat) : elementBytes;
    const std::uint64_t viewOffset = view.contains("byteOffset") ? number(view, "byteOffset", viewWhat) : 0;
    const std::uint64_t viewLength = number(view, "byteLength", viewWhat);
    const std::uint64_t offset = accessor.contains("byteOffset") ? number(accessor, "byteOffset", what) : 0;
    if (viewOffset > buffer.size() || viewLength > buffer.size() - viewOffset)
      fail(viewWhat + " lies outside buffers[" + std::to_string(bufferIndex) + "] (" + std::to_string(buffer.size()) +
           " bytes)");
    if (stride < elementBytes || (count > 0 && (offset > viewLength || elementBytes > viewLength - offset ||
                                                (count - 1) > (viewLength - offset - elementBytes) / stride)))
      fail(what + " (" + std::to_string(count) + " elements) does not fit in its bufferView");
    const char* base = buffer.data() + viewOffset + offset;
    out.reserve(out.size() + count);
    for (std::uint64_t i = 0; i < count; ++i) {
      T value{};
      for (std::size_t c = 0; c < width; ++c) convert(base + i * stride + c * componentBytes, component, value, c);
      out.push_back(value);
    }
  }

  /// `count` finite numbers from the array `value` (a node's matrix, translation, ...).
  std::vector<double> numbers(const json& value, std::size_t count, const std::string& what) const {
    if (!value.is_array() || value.size() != count) fail(what + " is not an array of " + std::to_string(count));
    std::vector<double> out;
    for (const json& v : value) {
      if (!v.is_number() || !std::isfinite(v.get<double>())) fail(what + " holds " + v.dump() + ", not a number");
      out.push_back(v.get<double>());
    }
    return out;
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

  std::size_t count(const char* array) const {
    const auto it = gltf_.find(array);
    return it != gltf_.end() && it->is_array() ? it->size() : 0;
  }

 private:
  /// A .glb file's chunks: JSON first, then an optional BIN.
  void readChunks(std::string_view& jsonText, std::string_view& binChunk) const {
    if (bytes_.size() < 12) fail("the 12-byte binary glTF header is cut off");
    const auto version = readLittleEndian<std::uint32_t>(bytes_.data() + 4);
    if (version != 2) fail("glTF version " + std::to_string(version) + ", only version 2 is read");
    const std::uint64_t length = readLittleEndian<std::uint32_t>(bytes_.data() + 8);
    if (length > bytes_.size())
      fail("the header declares " + std::to_string(length) + " bytes, the file has " + std::to_string(bytes_.size()) +
           " (truncated)");
    std::uint64_t at = 12;
    jsonText = {};
    for (int chunk = 0; at < length; ++chunk) {
      if (length - at < 8) fail("a chunk header is cut off at byte " + std::to_string(at));
      const std::uint64_t size = readLittleEndian<std::uint32_t>(bytes_.data() + at);
      const auto type = readLittleEndian<std::uint32_t>(bytes_.data() + at + 4);
      if (size > length - at - 8)
        fail("chunk " + std::to_string(chunk) + " of " + std::to_string(size) + " bytes runs past the end");
      const std::string_view data(bytes_.data() + at + 8, size);
      if (chunk == 0 && type != kJsonChunk) fail("the first chunk is not JSON");
      if (chunk == 0) jsonText = data;
      if (chunk == 1 && type == kBinChunk) binChunk = data;
      at += 8 + size;
    }
    if (jsonText.empty()) fail("no JSON chunk");
  }

  /// Each of `buffers`: the BIN chunk (a .glb's buffer 0 without uri), a data: URI or a
  /// file beside this one, at least `byteLength` bytes.
  void loadBuffers(bool binary, std::string_view binChunk) {
    const std::size_t n = count("buffers");
    external_.reserve(n);  // the views below point into it: no reallocation
    for (std::size_t i = 0; i < n; ++i) {
      const json& buffer = element("buffers", i);
      const std::string what = "buffers[" + std::to_string(i) + "]";
      const std::uint64_t length = number(buffer, "byteLength", what);
      std::string_view data;
      const auto uri = buffer.find("uri");
      if (uri == buffer.end()) {
        if (!binary || i != 0) fail(what + " has no uri (only a .glb file's first buffer is its BIN chunk)");
        data = binChunk;
      } else {
        if (!uri->is_string()) fail(what + ": the uri is not a string");
        external_.push_back(bufferFromUri(uri->get<std::string>(), what));
        data = external_.back();
      }
      if (data.size() < length)
        fail(what + " declares " + std::to_string(length) + " bytes but holds " + std::to_string(data.size()));
      buffers_.push_back(data.substr(0, length));
    }
  }

  std::string bufferFromUri(const std::string& uri, const std::string& what) const {
    if (uri.rfind("data:", 0) == 0) {
      const std::size_t comma = uri.find(',');
      if (comma == std::string::npos || uri.rfind(";base64", comma) == std::string::npos)
        fail(what + ": a data: URI without base64 data");
      bool ok = false;
      std::string decoded = decodeBase64(std::string_view(uri).substr(comma + 1), ok);
      if (!ok) fail(what + ": the data: URI is not valid base64");
      return decoded;
    }
    if (uri.find("://") != std::string::npos) fail(what + ": '" + uri + "' is not a file beside the .gltf");
    const std::filesystem::path file = path_.parent_path() / decodePercent(uri);
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error)) fail(what + ": " + quoted(file) + " is not a readable file");
    return readWholeFile(file);
  }

  const std::filesystem::path& path_;
  std::string bytes_;
  json gltf_;
  std::vector<std::string> external_;      ///< decoded or read buffers
  std::vector<std::string_view> buffers_;  ///< each buffer's bytes (into bytes_ or external_)
};

void readFloat(const char* p, int, mesh::Vec3f& value, std::size_t c) { value[c] = readLittleEndian<float>(p); }

void readIndex(const char* p, int component, std::uint64_t& value, std::size_t) {
  value = component == kUnsignedByte    ? std::uint64_t{static_cast<unsigned char>(*p)}
          : component == kUnsignedShort ? std::uint64_t{readLittleEndian<std::uint16_t>(p)}
                                        : std::uint64_t{readLittleEndian<std::uint32_t>(p)};
}

/// The scene's meshes gathered into one, each primitive placed by its node's transform.
class SceneReader {
 public:
  explicit SceneReader(const GltfFile& file) : file_(file) {}

  mesh::Mesh read() {
    const json& gltf = file_.gltf();
    const std::size_t nodeCount = file_.count("nodes");
    if (nodeCount == 0) {  // meshes without a scene graph: as stored
      for (std::size_t mi = 0; mi < file_.count("meshes"); ++mi) addMesh(mi, Eigen::Matrix4d::Identity());
    } else {
      parent_.assign(nodeCount, -1);
      children_.resize(nodeCount);
      for (std::size_t n = 0; n < nodeCount; ++n) {
        children_[n] = children(n);
        for (const std::uint64_t child : children_[n]) {
          if (parent_[child] >= 0)
            file_.fail("nodes[" + std::to_string(child) + "] has two parents (a glTF node graph is a forest)");
          parent_[child] = static_cast<std::int64_t>(n);
        }
      }
      for (const std::uint64_t root : roots(gltf, nodeCount)) {
        if (parent_[root] >= 0) file_.fail("the scene's nodes[" + std::to_string(root) + "] is not a root node");
        addNode(root, Eigen::Matrix4d::Identity(), 0);
      }
    }
    if (normals_ && !mesh_.positions.empty()) mesh_.normals = std::move(normalValues_);
    return std::move(mesh_);
  }

 private:
  std::vector<std::uint64_t> children(std::size_t node) const {
    const json& n = file_.element("nodes", node);
    std::vector<std::uint64_t> out;
    if (const auto it = n.find("children"); it != n.end()) {
      if (!it->is_array()) file_.fail("nodes[" + std::to_string(node) + "].children is not an array");
      for (const json& c : *it) {
        if (!c.is_number_integer() || c.get<std::int64_t>() < 0 || c.get<std::uint64_t>() >= file_.count("nodes") ||
            c.get<std::uint64_t>() == node)
          file_.fail("nodes[" + std::to_string(node) + "].children holds " + c.dump() + ", not another node");
        out.push_back(c.get<std::uint64_t>());
      }
    }
    return out;
  }

  /// The default scene's root nodes; without scenes, every node without a parent.
  std::vector<std::uint64_t> roots(const json& gltf, std::size_t nodeCount) const {
    std::vector<std::uint64_t> out;
    if (file_.count("scenes") == 0) {
      for (std::size_t n = 0; n < nodeCount; ++n)
        if (parent_[n] < 0) out.push_back(n);
      return out;
    }
    const std::uint64_t scene = gltf.contains("scene") ? file_.number(gltf, "scene", "the default scene") : 0;
    const json& s = file_.element("scenes", scene);
    if (const auto nodes = s.find("nodes"); nodes != s.end()) {
      if (!nodes->is_array()) file_.fail("scenes[" + std::to_string(scene) + "].nodes is not an array");
      for (const json& n : *nodes) {
        if (!n.is_number_integer() || n.get<std::int64_t>() < 0 || n.get<std::uint64_t>() >= nodeCount)
          file_.fail("scenes[" + std::to_string(scene) + "].nodes holds " + n.dump() + ", not a node");
        out.push_back(n.get<std::uint64_t>());
      }
    }
    return out;
  }

  /// A node's local transform: `matrix` (column-major), else T * R * S.
  Eigen::Matrix4d localTransform(const json& node, const std::string& what) const {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    if (node.contains("matrix")) {
      const std::vector<double> v = file_.numbers(node["matrix"], 16, what + ".matrix");
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m(r, c) = v[static_cast<std::size_t>(4 * c + r)];
      if (m(3, 0) != 0 || m(3, 1) != 0 || m(3, 2) != 0 || m(3, 3) != 1)
        file_.fail(what + ".matrix is not affine (its last row is not 0 0 0 1)");
      return m;
    }
    if (node.contains("scale")) {
      const std::vector<double> s = file_.numbers(node["scale"], 3, what + ".scale");
      m.topLeftCorner<3, 3>() = Eigen::Vector3d(s[0], s[1], s[2]).asDiagonal();
    }
    if (node.contains("rotation")) {
      const std::vector<double> q = file_.numbers(node["rotation"], 4, what + ".rotation");
      const Eigen::Quaterniond rotation(q[3], q[0], q[1], q[2]);  // glTF stores x, y, z, w
      if (!(rotation.norm() > 0.5)) file_.fail(what + ".rotation is not a unit quaternion");
      m.topLeftCorner<3, 3>() = rotation.normalized().toRotationMatrix() * m.topLeftCorner<3, 3>();
    }
    if (node.contains("translation")) {
      const std::vector<double> t = file_.numbers(node["translation"], 3, what + ".translation");
      m.topRightCorner<3, 1>() = Eigen::Vector3d(t[0], t[1], t[2]);
    }
    return m;
  }

  void addNode(std::uint64_t index, const Eigen::Matrix4d& parent, int depth) {
    const std::string what = "nodes[" + std::to_string(index) + "]";
    // A forest (checked) cannot be deeper than its node count; the bound keeps recursion small.
    if (depth > 256) file_.fail(what + " lies more than 256 nodes deep");
    const json& node = file_.element("nodes", index);
    const Eigen::Matrix4d transform = parent * localTransform(node, what);
    if (node.contains("mesh")) addMesh(file_.number(node, "mesh", what), transform);
    for (const std::uint64_t child : children_[index]) addNode(child, transform, depth + 1);
  }

  void addMesh(std::uint64_t meshIndex, const Eigen::Matrix4d& transform) {
    const json& gm = file_.element("meshes", meshIndex);
    const auto primitives = gm.find("primitives");
    if (primitives == gm.end() || !primitives->is_array())
      file_.fail("meshes[" + std::to_string(meshIndex) + "] has no primitives");
    const Eigen::Matrix3d linear = transform.topLeftCorner<3, 3>();
    const double determinant = linear.determinant();
    if (!(std::abs(determinant) > 0) || !std::isfinite(determinant))
      file_.fail("meshes[" + std::to_string(meshIndex) + "] is placed by a singular transform");
    const Eigen::Matrix3d normalMatrix = linear.inverse().transpose();
    const bool mirrored = determinant < 0;
    for (std::size_t pi = 0; pi < primitives->size(); ++pi) {
      const json& primitive = (*primitives)[pi];
      const std::string what = "meshes[" + std::to_string(meshIndex) + "].primitives[" + std::to_string(pi) + "]";
      if (!primitive.is_object() || !primitive.contains("attributes") || !primitive["attributes"].is_object())
        file_.fail(what + " has no attributes");
      if (primitive.contains("mode") && file_.number(primitive, "mode", what) != kTriangles)
        file_.fail(what + " has mode " + primitive["mode"].dump() + "; only triangle lists (mode 4) are read");
      const json& attributes = primitive["attributes"];
      if (!attributes.contains("POSITION")) file_.fail(what + " has no POSITION");
      const std::uint64_t positionAccessor = file_.number(attributes, "POSITION", what);
      const std::uint64_t declared = file_.number(file_.element("accessors", positionAccessor), "count", what);
      if (mesh_.positions.size() + declared >
          kInstancingLimit * std::max<std::uint64_t>(file_.dataBytes() / 12, 1 << 16))
        file_.fail("the scene places more than " + std::to_string(kInstancingLimit) +
                   " times the vertices the file holds (instanced meshes)");
      const std::size_t base = mesh_.positions.size();
      file_.readAccessor(positionAccessor, "VEC3", {kFloat}, 3, mesh_.positions, readFloat);
      const std::uint64_t added = mesh_.positions.size() - base;
      for (std::size_t v = base; v < mesh_.positions.size(); ++v) {
        mesh::Vec3f& p = mesh_.positions[v];
        const Eigen::Vector3d placed = (transform * Eigen::Vector4d(p[0], p[1], p[2], 1.0)).head<3>();
        for (int c = 0; c < 3; ++c) {
          p[static_cast<std::size_t>(c)] = static_cast<float>(placed[c]);
          if (!std::isfinite(p[static_cast<std::size_t>(c)]))
            file_.fail(what + ": vertex " + std::to_string(v - base) + " is not finite");
        }
      }
      normals_ = normals_ && attributes.contains("NORMAL");
      if (normals_) {  // turned only by a transform that is not the identity: isovdb's own files read back as written
        const std::size_t normalBase = normalValues_.size();
        file_.readAccessor(file_.number(attributes, "NORMAL", what), "VEC3", {kFloat}, 3, normalValues_, readFloat);
        if (normalValues_.size() != mesh_.positions.size()) file_.fail(what + ": NORMAL and POSITION counts differ");
        for (std::size_t v = normalBase; v < normalValues_.size() && !linear.isIdentity(0.0); ++v) {
          mesh::Vec3f& n = normalValues_[v];
          const Eigen::Vector3d turned = (normalMatrix * Eigen::Vector3d(n[0], n[1], n[2])).normalized();
          for (int c = 0; c < 3; ++c) n[static_cast<std::size_t>(c)] = static_cast<float>(turned[c]);
        }
      }
      std::vector<std::uint64_t> corners;
      if (primitive.contains("indices")) {
        file_.readAccessor(file_.number(primitive, "indices", what), "SCALAR",
                           {kUnsignedByte, kUnsignedShort, gltf::kUnsignedInt}, 1, corners, readIndex);
      } else {
        corners.resize(added);
        for (std::uint64_t i = 0; i < added; ++i) corners[i] = i;
      }
      if (corners.size() % 3 != 0)
        file_.fail(what + ": " + std::to_string(corners.size()) + " corners, not a whole number of triangles");
      if (mesh_.positions.size() > std::numeric_limits<std::uint32_t>::max()) file_.fail("more than 2^32 - 1 vertices");
      for (std::size_t c = 0; c < corners.size(); c += 3) {
        mesh::Triangle t;
        for (std::size_t k = 0; k < 3; ++k) {
          if (corners[c + k] >= added)
            file_.fail(what + ": index " + std::to_string(corners[c + k]) + " but " + std::to_string(added) +
                       " vertices");
          t[k] = static_cast<std::uint32_t>(base + corners[c + k]);
        }
        if (mirrored) std::swap(t[1], t[2]);  // a mirror turns the winding; renderers turn it back
        mesh_.triangles.push_back(t);
      }
    }
  }

  const GltfFile& file_;
  std::vector<std::int64_t> parent_;                  ///< each node's parent, -1 for a root
  std::vector<std::vector<std::uint64_t>> children_;  ///< each node's children, read once
  mesh::Mesh mesh_;
  bool normals_ = true;
  std::vector<mesh::Vec3f> normalValues_;
};

}  // namespace

mesh::Mesh readGltf(const std::filesystem::path& path) {
  const GltfFile file(path);
  return SceneReader(file).read();
}

}  // namespace isovdb::io
