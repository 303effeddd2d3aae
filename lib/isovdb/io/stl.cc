// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/stl.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/io/block_writer.h"
#include "isovdb/io/little_endian.h"
#include "isovdb/io/path_util.h"
#include "isovdb/io/whole_file.h"
#include "isovdb/mesh/mesh_checks.h"
#include "isovdb/mesh/weld.h"

namespace isovdb::io {

namespace {

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kFacetBytes = 50;  // normal, 3 corners (12 float32) and a uint16

mesh::Vec3f facetNormal(const mesh::Vec3f& a, const mesh::Vec3f& b, const mesh::Vec3f& c) {
  const double u[3] = {double{b[0]} - a[0], double{b[1]} - a[1], double{b[2]} - a[2]};
  const double v[3] = {double{c[0]} - a[0], double{c[1]} - a[1], double{c[2]} - a[2]};
  const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(length > 0) || !std::isfinite(length)) return {0.0f, 0.0f, 0.0f};
  return {static_cast<float>(n[0] / length), static_cast<float>(n[1] / length), static_cast<float>(n[2] / length)};
}

/// Corners in facet order, three per triangle: the unwelded mesh.
mesh::Mesh soup(std::vector<mesh::Vec3f> corners) {
  mesh::Mesh m;
  m.positions = std::move(corners);
  m.triangles.resize(m.positions.size() / 3);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto first = static_cast<std::uint32_t>(3 * t);
    m.triangles[t] = {first, first + 1, first + 2};
  }
  return m;
}

std::vector<mesh::Vec3f> binaryCorners(const std::filesystem::path& path, const std::string& bytes,
                                       std::uint32_t facets) {
  std::vector<mesh::Vec3f> corners(std::size_t{facets} * 3);
  for (std::size_t f = 0; f < facets; ++f) {
    const char* facet = bytes.data() + kHeaderBytes + 4 + f * kFacetBytes;
    for (std::size_t c = 0; c < 3; ++c)
      for (std::size_t a = 0; a < 3; ++a) {
        const float value = readLittleEndian<float>(facet + 12 + 12 * c + 4 * a);
        if (!std::isfinite(value))
          throw InputError(quoted(path) + ": facet " + std::to_string(f) + " has a non-finite coordinate");
        corners[3 * f + c][a] = value;
      }
  }
  return corners;
}

/// ASCII STL as whitespace-separated words.
class AsciiWords {
 public:
  AsciiWords(const std::filesystem::path& path, std::string_view text) : path_(path), text_(text) {}

  bool atEnd() {
    skipSpace();
    return pos_ >= text_.size();
  }
  std::string_view next() {
    skipSpace();
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    return text_.substr(start, pos_ - start);
  }
  /// Skips the rest of the current line (the solid's name).
  void skipLine() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }
  void expect(std::string_view word) {
    const std::string_view got = next();
    if (got != word) fail("expected '" + std::string(word) + "', found '" + std::string(got.substr(0, 40)) + "'");
  }
  float number() {
    const std::string_view word = next();
    float value = 0.0f;
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (ec != std::errc() || end != word.data() + word.size() || !std::isfinite(value))
      fail("expected a finite number, found '" + std::string(word.substr(0, 40)) + "'");
    return value;
  }
  [[noreturn]] void fail(const std::string& what) const {
    const auto line = 1 + std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(pos_), '\n');
    throw InputError(quoted(path_) + ":" + std::to_string(line) + ": " + what + " (an ASCII STL file)");
  }

 private:
  void skipSpace() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  const std::filesystem::path& path_;
  std::string_view text_;
  std::size_t pos_ = 0;
};

std::vector<mesh::Vec3f> asciiCorners(const std::filesystem::path& path, std::string_view text) {
  AsciiWords words(path, text);
  words.expect("solid");
  words.skipLine();
  std::vector<mesh::Vec3f> corners;
  for (;;) {
    if (words.atEnd()) words.fail("the file ends before 'endsolid'");
    const std::string_view word = words.next();
    if (word == "endsolid") break;
    if (word != "facet") words.fail("expected 'facet' or 'endsolid', found '" + std::string(word.substr(0, 40)) + "'");
    words.expect("normal");
    for (int a = 0; a < 3; ++a) words.number();
    words.expect("outer");
    words.expect("loop");
    for (int c = 0; c < 3; ++c) {
      words.expect("vertex");
      mesh::Vec3f p;
      for (std::size_t a = 0; a < 3; ++a) p[a] = words.number();
      corners.push_back(p);
    }
    words.expect("endloop");
    words.expect("endfacet");
  }
  return corners;
}

}  // namespace

void writeStl(const std::filesystem::path& path, const mesh::Mesh& mesh) {
  mesh::detail::checkIndices(mesh, "cannot write " + quoted(path));
  if (mesh.triangles.size() > std::numeric_limits<std::uint32_t>::max())
    throw InputError("cannot write " + quoted(path) + ": " + std::to_string(mesh.triangles.size()) +
                     " triangles, more than binary STL can count");
  AtomicFile file(path);
  BlockWriter out(file);
  std::string header = "binary STL written by isovdb";
  header.resize(kHeaderBytes, ' ');
  out.put(header.data(), header.size());
  out.putLittleEndian(static_cast<std::uint32_t>(mesh.triangles.size()));
  for (const mesh::Triangle& tri : mesh.triangles) {
    const mesh::Vec3f& a = mesh.positions[tri[0]];
    const mesh::Vec3f& b = mesh.positions[tri[1]];
    const mesh::Vec3f& c = mesh.positions[tri[2]];
    for (const float value : facetNormal(a, b, c)) out.putLittleEndian(value);
    for (const mesh::Vec3f* corner : {&a, &b, &c})
      for (const float value : *corner) out.putLittleEndian(value);
    out.putLittleEndian(std::uint16_t{0});
  }
  out.flush();
  file.commit();
}

mesh::Mesh readStl(const std::filesystem::path& path) {
  const std::string bytes = readWholeFile(path);
  std::vector<mesh::Vec3f> corners;
  const bool binarySize =
      bytes.size() >= kHeaderBytes + 4 &&
      bytes.size() ==
          kHeaderBytes + 4 + kFacetBytes * std::uint64_t{readLittleEndian<std::uint32_t>(bytes.data() + kHeaderBytes)};
  if (binarySize) {
    corners = binaryCorners(path, bytes, readLittleEndian<std::uint32_t>(bytes.data() + kHeaderBytes));
  } else if (bytes.compare(0, 5, "solid") == 0) {
    corners = asciiCorners(path, bytes);
  } else if (bytes.size() < kHeaderBytes + 4) {
    throw InputError(quoted(path) + ": " + std::to_string(bytes.size()) +
                     " bytes, too short for a binary STL file (84-byte header) and not ASCII STL ('solid ...')");
  } else {
    const std::uint64_t facets = readLittleEndian<std::uint32_t>(bytes.data() + kHeaderBytes);
    throw InputError(quoted(path) + ": the header counts " + std::to_string(facets) + " facets (" +
                     std::to_string(kHeaderBytes + 4 + kFacetBytes * facets) + " bytes) but the file has " +
                     std::to_string(bytes.size()) + " bytes, and it is not ASCII STL ('solid ...')");
  }
  mesh::Mesh m = soup(std::move(corners));
  mesh::weldVertices(m);  // every corner is referenced, so no vertex is left unused
  return m;
}

}  // namespace isovdb::io
