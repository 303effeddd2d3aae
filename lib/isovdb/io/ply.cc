// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/ply.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/io/block_writer.h"
#include "isovdb/io/header_text.h"
#include "isovdb/io/little_endian.h"
#include "isovdb/mesh/mesh_checks.h"
#include "isovdb/io/sample_type.h"
#include "isovdb/io/whole_file.h"

namespace isovdb::io {

namespace {

using mesh::Mesh;

constexpr bool kNativeLittle = std::endian::native == std::endian::little;

// ---------------------------------------------------------------------------
// Writing

void checkMesh(const std::filesystem::path& path, const Mesh& mesh) {
  if (mesh.positions.size() > std::numeric_limits<std::uint32_t>::max())
    throw InputError("cannot write '" + path.string() + "': more than 2^32 - 1 vertices");
  mesh::detail::checkIndices(mesh, "cannot write '" + path.string() + "'");
}

// ---------------------------------------------------------------------------
// Header

enum class Format { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct Property {
  std::string name;
  SampleType type = SampleType::Float32;  ///< value type (of the items, for a list)
  bool isList = false;
  SampleType countType = SampleType::UInt8;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  std::size_t bodyOffset = 0;
};

class PlyFile {
 public:
  explicit PlyFile(const std::filesystem::path& path) : name_(path.string()) {}

  [[noreturn]] void fail(const std::string& what) const { throw InputError("'" + name_ + "': " + what); }

  const std::string& name() const { return name_; }

 private:
  std::string name_;
};

std::vector<std::string_view> splitWords(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

SampleType parseType(const PlyFile& file, std::size_t lineNumber, std::string_view word) {
  if (const auto type = parseSampleType(word)) return *type;
  file.fail("header line " + std::to_string(lineNumber) + ": unknown property type '" + std::string(word) +
            "' (expected char, uchar, short, ushort, int, uint, float, double or their int8...float64 names)");
}

Header parseHeader(const PlyFile& file, std::string_view data) {
  Header header;
  std::size_t pos = 0, lineNumber = 0;
  bool haveFormat = false, ended = false;
  while (pos < data.size() && !ended) {
    const std::size_t eol = data.find('\n', pos);
    if (eol == std::string_view::npos) break;
    std::string_view line = data.substr(pos, eol - pos);
    pos = eol + 1;
    ++lineNumber;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::vector<std::string_view> words = splitWords(line);
    const std::string where = "header line " + std::to_string(lineNumber) + ": ";
    if (lineNumber == 1) {
      if (line != "ply") file.fail("not a PLY file (the first line is not 'ply')");
      continue;
    }
    if (words.empty()) continue;
    const std::string_view key = words[0];
    if (key == "comment" || key == "obj_info") continue;
    if (key == "end_header") {
      ended = true;
    } else if (key == "format") {
      if (words.size() != 3) file.fail(where + "expected 'format <type> 1.0'");
      if (words[1] == "ascii")
        header.format = Format::Ascii;
      else if (words[1] == "binary_little_endian")
        header.format = Format::BinaryLittleEndian;
      else if (words[1] == "binary_big_endian")
        header.format = Format::BinaryBigEndian;
      else
        file.fail(where + "unknown format '" + std::string(words[1]) +
                  "' (expected ascii, binary_little_endian or binary_big_endian)");
      if (words[2] != "1.0") file.fail(where + "unsupported version '" + std::string(words[2]) + "' (expected 1.0)");
      haveFormat = true;
    } else if (key == "element") {
      Element element;
      if (words.size() != 3) file.fail(where + "expected 'element <name> <count>'");
      element.name = words[1];
      const auto [end, ec] = std::from_chars(words[2].data(), words[2].data() + words[2].size(), element.count);
      if (ec != std::errc() || end != words[2].data() + words[2].size())
        file.fail(where + "bad count '" + std::string(words[2]) + "' for element '" + element.name + "'");
      header.elements.push_back(std::move(element));
    } else if (key == "property") {
      if (header.elements.empty()) file.fail(where + "property before any element");
      Property property;
      if (words.size() == 5 && words[1] == "list") {
        property.isList = true;
        property.countType = parseType(file, lineNumber, words[2]);
        property.type = parseType(file, lineNumber, words[3]);
        property.name = words[4];
        if (isFloatingPoint(property.countType))
          file.fail(where + "list '" + property.name + "' has a floating-point count type");
      } else if (words.size() == 3 && words[1] != "list") {
        property.type = parseType(file, lineNumber, words[1]);
        property.name = words[2];
      } else {
        file.fail(where + "expected 'property <type> <name>' or 'property list <count type> <type> <name>'");
      }
      header.elements.back().properties.push_back(std::move(property));
    } else {
      file.fail(where + "unknown keyword '" + std::string(key) + "'");
    }
  }
  if (lineNumber == 0) file.fail("not a PLY file (empty or no complete first line)");
  if (!ended) file.fail("the header has no end_header line");
  if (!haveFormat) file.fail("the header has no format line");
  header.bodyOffset = pos;
  return header;
}

// ---------------------------------------------------------------------------
// Body sources: one value at a time, as a double (any type) or an integer.

enum class Status { Ok, End, Malformed };

class BinarySource {
 public:
  BinarySource(const char* begin, const char* end, bool bigEndian)
      : p_(begin), end_(end), swap_(bigEndian == kNativeLittle) {}

  Status readDouble(SampleType type, double& out) { return read(type, out); }

  Status readInteger(SampleType type, std::int64_t& out) {
    if (isFloatingPoint(type)) return Status::Malformed;
    return read(type, out);
  }

  std::string lastToken() const { return {}; }
  std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }

 private:
  /// Reads one sample stored as `type` into `out`.
  template <typename Out>
  Status read(SampleType type, Out& out) {
    switch (type) {
      case SampleType::Int8:
        return load<std::int8_t>(out);
      case SampleType::UInt8:
        return load<std::uint8_t>(out);
      case SampleType::Int16:
        return load<std::int16_t>(out);
      case SampleType::UInt16:
        return load<std::uint16_t>(out);
      case SampleType::Int32:
        return load<std::int32_t>(out);
      case SampleType::UInt32:
        return load<std::uint32_t>(out);
      case SampleType::Float32:
        return load<float>(out);
      case SampleType::Float64:
        return load<double>(out);
    }
    return Status::Malformed;
  }

  template <typename T, typename Out>
  Status load(Out& out) {
    if (static_cast<std::size_t>(end_ - p_) < sizeof(T)) return Status::End;
    std::array<char, sizeof(T)> raw;
    std::memcpy(raw.data(), p_, sizeof(T));
    if (swap_) std::reverse(raw.begin(), raw.end());
    T value;
    std::memcpy(&value, raw.data(), sizeof(T));
    out = static_cast<Out>(value);
    p_ += sizeof(T);
    return Status::Ok;
  }

  const char* p_;
  const char* end_;
  bool swap_;
};

class AsciiSource {
 public:
  AsciiSource(const char* begin, const char* end) : p_(begin), end_(end) {}

  Status readDouble(SampleType type, double& out) {
    if (!next()) return Status::End;
    if (!isFloatingPoint(type)) {
      std::int64_t value = 0;
      if (!parse(value)) return Status::Malformed;
      out = static_cast<double>(value);
      return inRange(type, value) ? Status::Ok : Status::Malformed;
    }
    return parse(out) ? Status::Ok : Status::Malformed;
  }

  Status readInteger(SampleType type, std::int64_t& out) {
    if (!next()) return Status::End;
    if (isFloatingPoint(type) || !parse(out)) return Status::Malformed;
    return inRange(type, out) ? Status::Ok : Status::Malformed;
  }

  std::string lastToken() const { return std::string(token_); }
  std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }

 private:
  bool next() {
    while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\n' || *p_ == '\r')) ++p_;
    const char* start = p_;
    while (p_ < end_ && !(*p_ == ' ' || *p_ == '\t' || *p_ == '\n' || *p_ == '\r')) ++p_;
    token_ = std::string_view(start, static_cast<std::size_t>(p_ - start));
    return !token_.empty();
  }

  template <typename T>
  bool parse(T& out) const {
    const char* first = token_.data();
    if (!token_.empty() && token_[0] == '+') ++first;
    const auto [end, ec] = std::from_chars(first, token_.data() + token_.size(), out);
    return ec == std::errc() && end == token_.data() + token_.size();
  }

  static bool inRange(SampleType type, std::int64_t v) {
    switch (type) {
      case SampleType::Int8:
        return v >= -128 && v <= 127;
      case SampleType::UInt8:
        return v >= 0 && v <= 255;
      case SampleType::Int16:
        return v >= -32768 && v <= 32767;
      case SampleType::UInt16:
        return v >= 0 && v <= 65535;
      case SampleType::Int32:
        return v >= std::numeric_limits<std::int32_t>::min() && v <= std::numeric_limits<std::int32_t>::max();
      case SampleType::UInt32:
        return v >= 0 && v <= std::numeric_limits<std::uint32_t>::max();
      default:
        return true;
    }
  }

  const char* p_;
  const char* end_;
  std::string_view token_;
};

// ---------------------------------------------------------------------------
// Body

/// Where the values of the vertex properties go: slot 0-2 position, 3-5 normal, -1 skipped.
std::vector<int> vertexSlots(const PlyFile& file, const Element& vertex, bool& hasNormals) {
  static constexpr std::string_view kNames[6] = {"x", "y", "z", "nx", "ny", "nz"};
  std::vector<int> slots(vertex.properties.size(), -1);
  bool found[6] = {};
  for (std::size_t i = 0; i < vertex.properties.size(); ++i) {
    const Property& p = vertex.properties[i];
    for (int s = 0; s < 6; ++s)
      if (p.name == kNames[s] && !p.isList && !found[s]) {
        slots[i] = s;
        found[s] = true;
      }
  }
  for (int s = 0; s < 3; ++s)
    if (!found[s]) file.fail("the vertex element has no '" + std::string(kNames[s]) + "' property");
  hasNormals = found[3] && found[4] && found[5];
  if (!hasNormals)
    for (int& s : slots)
      if (s >= 3) s = -1;
  return slots;
}

template <class Source>
class BodyReader {
 public:
  BodyReader(const PlyFile& file, const Header& header, Source source)
      : file_(file), header_(header), src_(std::move(source)) {}

  Mesh read() {
    const Element* vertex = nullptr;
    for (const Element& e : header_.elements)
      if (e.name == "vertex") vertex = &e;
    if (!vertex) file_.fail("the header has no vertex element");
    if (vertex->count > std::numeric_limits<std::uint32_t>::max())
      file_.fail("the file has " + std::to_string(vertex->count) + " vertices; at most 2^32 - 1 are supported");
    vertexCount_ = vertex->count;

    Mesh mesh;
    for (const Element& e : header_.elements) {
      if (e.name == "vertex")
        readVertices(e, mesh);
      else if (e.name == "face")
        readFaces(e, mesh);
      else
        skipElement(e);
    }
    return mesh;
  }

 private:
  [[noreturn]] void failValue(Status status, const Element& e, std::uint64_t item, const Property& p) const {
    const std::string where = "element '" + e.name + "' " + std::to_string(item) + " of " + std::to_string(e.count) +
                              ", property '" + p.name + "'";
    if (status == Status::End) file_.fail("the file ends early, in " + where + " (truncated?)");
    file_.fail("bad value '" + src_.lastToken() + "' in " + where + " (expected " +
               std::string(sampleTypeName(p.type)) + ")");
  }

  double value(const Element& e, std::uint64_t item, const Property& p, SampleType type) {
    double v = 0;
    if (const Status s = src_.readDouble(type, v); s != Status::Ok) failValue(s, e, item, p);
    return v;
  }

  std::int64_t integer(const Element& e, std::uint64_t item, const Property& p, SampleType type) {
    std::int64_t v = 0;
    if (const Status s = src_.readInteger(type, v); s != Status::Ok) failValue(s, e, item, p);
    return v;
  }

  std::int64_t listCount(const Element& e, std::uint64_t item, const Property& p) {
    const std::int64_t n = integer(e, item, p, p.countType);
    if (n < 0)
      file_.fail("element '" + e.name + "' " + std::to_string(item) + ": negative list length in '" + p.name + "'");
    return n;
  }

  void skipProperty(const Element& e, std::uint64_t item, const Property& p) {
    const std::int64_t n = p.isList ? listCount(e, item, p) : 1;
    for (std::int64_t i = 0; i < n; ++i) value(e, item, p, p.type);
  }

  /// Upper bound on the items the rest of the file can hold, to reserve no more than that.
  std::size_t plausible(std::uint64_t count) const {
    return static_cast<std::size_t>(std::min<std::uint64_t>(count, src_.remaining() / 2));
  }

  void readVertices(const Element& e, Mesh& mesh) {
    bool hasNormals = false;
    const std::vector<int> slots = vertexSlots(file_, e, hasNormals);
    mesh.positions.reserve(plausible(e.count));
    if (hasNormals) mesh.normals.reserve(plausible(e.count));
    for (std::uint64_t item = 0; item < e.count; ++item) {
      float v[6] = {};
      for (std::size_t i = 0; i < e.properties.size(); ++i) {
        const Property& p = e.properties[i];
        if (slots[i] < 0) {
          skipProperty(e, item, p);
          continue;
        }
        v[slots[i]] = static_cast<float>(value(e, item, p, p.type));
      }
      for (int k = 0; k < (hasNormals ? 6 : 3); ++k)
        if (!std::isfinite(v[k])) file_.fail("vertex " + std::to_string(item) + " has a non-finite coordinate");
      mesh.positions.push_back({v[0], v[1], v[2]});
      if (hasNormals) mesh.normals.push_back({v[3], v[4], v[5]});
    }
  }

  void readFaces(const Element& e, Mesh& mesh) {
    int listIndex = -1;
    for (std::size_t i = 0; i < e.properties.size() && listIndex < 0; ++i) {
      const Property& p = e.properties[i];
      if (p.isList && (p.name == "vertex_indices" || p.name == "vertex_index")) listIndex = static_cast<int>(i);
    }
    if (listIndex < 0) file_.fail("the face element has no 'vertex_indices' list property");
    const Property& list = e.properties[static_cast<std::size_t>(listIndex)];
    if (isFloatingPoint(list.type)) file_.fail("the face list '" + list.name + "' has a floating-point index type");
    mesh.triangles.reserve(plausible(e.count));
    std::vector<std::uint32_t> corners;
    for (std::uint64_t item = 0; item < e.count; ++item) {
      for (std::size_t i = 0; i < e.properties.size(); ++i) {
        const Property& p = e.properties[i];
        if (static_cast<int>(i) != listIndex) {
          skipProperty(e, item, p);
          continue;
        }
        const std::int64_t n = listCount(e, item, p);
        if (n < 3)
          file_.fail("face " + std::to_string(item) + " has " + std::to_string(n) + " vertices (at least 3 expected)");
        corners.clear();
        for (std::int64_t k = 0; k < n; ++k) {
          const std::int64_t index = integer(e, item, p, p.type);
          if (index < 0 || static_cast<std::uint64_t>(index) >= vertexCount_)
            file_.fail("face " + std::to_string(item) + " references vertex " + std::to_string(index) +
                       " but the file has " + std::to_string(vertexCount_) + " vertices");
          corners.push_back(static_cast<std::uint32_t>(index));
        }
        for (std::size_t k = 1; k + 1 < corners.size(); ++k)
          mesh.triangles.push_back({corners[0], corners[k], corners[k + 1]});
      }
    }
  }

  void skipElement(const Element& e) {
    for (std::uint64_t item = 0; item < e.count; ++item)
      for (const Property& p : e.properties) skipProperty(e, item, p);
  }

  const PlyFile& file_;
  const Header& header_;
  Source src_;
  std::uint64_t vertexCount_ = 0;
};

}  // namespace

namespace detail {

std::string binaryPlyHeader(std::uint64_t vertices, std::uint64_t triangles, bool normals,
                            const std::vector<std::string>& comments) {
  constexpr std::size_t kCountRoom = 2 * 20;  // the largest counts: 20 digits each
  const std::size_t digits = std::to_string(vertices).size() + std::to_string(triangles).size();
  std::string header = "ply\nformat binary_little_endian 1.0\ncomment written by isovdb\n";
  for (const std::string& line : comments) header += "comment " + oneLine(line) + "\n";
  header += "comment " + std::string(kCountRoom + 2 - digits, ' ') + "\n";
  header += "element vertex " + std::to_string(vertices) + "\n";
  header += "property float x\nproperty float y\nproperty float z\n";
  if (normals) header += "property float nx\nproperty float ny\nproperty float nz\n";
  header += "element face " + std::to_string(triangles) + "\n";
  header += "property list uchar uint vertex_indices\nend_header\n";
  return header;
}

}  // namespace detail

void writePly(const std::filesystem::path& path, const Mesh& mesh) {
  checkMesh(path, mesh);
  const bool normals = !mesh.normals.empty();
  const std::string header =
      detail::binaryPlyHeader(mesh.positions.size(), mesh.triangles.size(), normals, mesh.comments);

  AtomicFile file(path);
  BlockWriter out(file);
  out.put(header.data(), header.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    for (const float c : mesh.positions[i]) out.putLittleEndian(c);
    if (normals)
      for (const float c : mesh.normals[i]) out.putLittleEndian(c);
  }
  for (const mesh::Triangle& t : mesh.triangles) {
    out.putLittleEndian(std::uint8_t{3});
    for (const std::uint32_t v : t) out.putLittleEndian(v);
  }
  out.flush();
  file.commit();
}

Mesh readPly(const std::filesystem::path& path) {
  const PlyFile file(path);
  const std::string data = readWholeFile(path);
  const Header header = parseHeader(file, data);
  const char* begin = data.data() + header.bodyOffset;
  const char* end = data.data() + data.size();
  if (header.format == Format::Ascii) return BodyReader(file, header, AsciiSource(begin, end)).read();
  return BodyReader(file, header, BinarySource(begin, end, header.format == Format::BinaryBigEndian)).read();
}

}  // namespace isovdb::io
