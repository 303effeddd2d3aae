// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/obj.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/io/header_text.h"
#include "isovdb/io/whole_file.h"
#include "isovdb/mesh/mesh_checks.h"

namespace isovdb::io {

namespace {

using mesh::Mesh;

constexpr std::size_t kLinesPerBlock = 1 << 15;
constexpr std::size_t kBlocksPerBatch = 16;

void checkMesh(const std::filesystem::path& path, const Mesh& mesh) {
  mesh::detail::checkIndices(mesh, "cannot write '" + path.string() + "'");
}

/// Appends numbers to a string through std::to_chars.
class LineBuilder {
 public:
  explicit LineBuilder(std::string& out) : out_(out) {}

  void text(std::string_view s) { out_.append(s); }
  void number(float value) {
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    out_.append(buffer, end);
  }
  void number(std::uint64_t value) {
    char buffer[24];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    out_.append(buffer, end);
  }

 private:
  std::string& out_;
};

/// Formats `count` lines in blocks, a batch of blocks in parallel, and writes
/// them in order. `format(begin, end, out)` appends lines [begin, end).
template <typename Format>
void writeLines(AtomicFile& file, std::size_t count, const Format& format) {
  std::vector<std::string> blocks(kBlocksPerBatch);
  for (std::size_t batch = 0; batch < count; batch += kLinesPerBlock * kBlocksPerBatch) {
    const std::size_t batchEnd = std::min(count, batch + kLinesPerBlock * kBlocksPerBatch);
    const std::size_t blockCount = (batchEnd - batch + kLinesPerBlock - 1) / kLinesPerBlock;
    tbb::parallel_for(std::size_t{0}, blockCount, [&](std::size_t b) {
      const std::size_t begin = batch + b * kLinesPerBlock;
      blocks[b].clear();
      format(begin, std::min(batchEnd, begin + kLinesPerBlock), blocks[b]);
    });
    for (std::size_t b = 0; b < blockCount; ++b) file.write(blocks[b]);
  }
}

/// Reads OBJ text line by line; failures name the file and the line.
class ObjParser {
 public:
  ObjParser(const std::filesystem::path& path, std::string_view text) : path_(path), text_(text) {}

  Mesh parse() {
    std::size_t at = 0;
    while (at < text_.size()) {
      std::size_t end = text_.find('\n', at);
      if (end == std::string_view::npos) end = text_.size();
      ++line_;
      std::string_view content = text_.substr(at, end - at);
      content = content.substr(0, content.find('#'));
      at = end + 1;
      words_ = content;
      const std::string_view keyword = nextWord();
      if (keyword == "v")
        mesh_.positions.push_back(vector());
      else if (keyword == "vn")
        normals_.push_back(vector());
      else if (keyword == "f")
        face();
    }
    for (const mesh::Triangle& t : mesh_.triangles)
      for (const std::uint32_t v : t)
        if (v >= mesh_.positions.size())
          fail("a face refers to vertex " + std::to_string(std::uint64_t{v} + 1) + " but the file has " +
                   std::to_string(mesh_.positions.size()),
               false);
    if (normalsFollowVertices_ && !mesh_.triangles.empty() && normals_.size() == mesh_.positions.size())
      mesh_.normals = std::move(normals_);
    return std::move(mesh_);
  }

 private:
  std::string_view nextWord() {
    const std::size_t begin = words_.find_first_not_of(" \t\r");
    if (begin == std::string_view::npos) {
      words_ = {};
      return {};
    }
    const std::size_t end = std::min(words_.size(), words_.find_first_of(" \t\r", begin));
    const std::string_view word = words_.substr(begin, end - begin);
    words_ = words_.substr(end);
    return word;
  }

  mesh::Vec3f vector() {
    mesh::Vec3f value;
    for (std::size_t a = 0; a < 3; ++a) {
      const std::string_view word = nextWord();
      float number = 0.0f;
      const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), number);
      if (word.empty() || ec != std::errc() || end != word.data() + word.size() || !std::isfinite(number))
        fail("expected three finite numbers, found '" + std::string(word.substr(0, 40)) + "'");
      value[a] = number;
    }
    return value;
  }

  /// The 0-based index of a 1-based or negative (relative to `count`) OBJ index.
  std::uint64_t index(std::string_view text, std::size_t count) {
    std::int64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || value == 0)
      fail("expected a vertex index, found '" + std::string(text.substr(0, 40)) + "'");
    if (value < 0 && static_cast<std::uint64_t>(-value) > count)
      fail("relative index " + std::string(text) + " but only " + std::to_string(count) + " defined so far");
    const std::uint64_t zeroBased =
        value > 0 ? static_cast<std::uint64_t>(value) - 1 : count - static_cast<std::uint64_t>(-value);
    if (zeroBased >= std::numeric_limits<std::uint32_t>::max()) fail("index " + std::string(text) + " is too large");
    return zeroBased;
  }

  void face() {
    std::vector<std::uint32_t> corners;
    for (std::string_view word = nextWord(); !word.empty(); word = nextWord()) {
      const std::size_t slash = word.find('/');
      const std::uint64_t v = index(word.substr(0, slash), mesh_.positions.size());
      corners.push_back(static_cast<std::uint32_t>(v));
      const std::size_t second = slash == std::string_view::npos ? slash : word.find('/', slash + 1);
      if (second == std::string_view::npos)
        normalsFollowVertices_ = false;
      else if (index(word.substr(second + 1), normals_.size()) != v)
        normalsFollowVertices_ = false;
    }
    if (corners.size() < 3) fail("a face with " + std::to_string(corners.size()) + " corners");
    for (std::size_t c = 1; c + 1 < corners.size(); ++c)
      mesh_.triangles.push_back({corners[0], corners[c], corners[c + 1]});
  }

  [[noreturn]] void fail(const std::string& what, bool withLine = true) const {
    throw InputError("'" + path_.string() + "'" + (withLine ? ":" + std::to_string(line_) : std::string()) + ": " +
                     what + " (an OBJ file)");
  }

  const std::filesystem::path& path_;
  std::string_view text_;
  std::string_view words_;
  std::size_t line_ = 0;
  Mesh mesh_;
  std::vector<mesh::Vec3f> normals_;
  bool normalsFollowVertices_ = true;
};

}  // namespace

void writeObj(const std::filesystem::path& path, const Mesh& mesh) {
  checkMesh(path, mesh);
  const bool normals = !mesh.normals.empty();
  AtomicFile file(path);
  file.write("# written by isovdb: " + std::to_string(mesh.positions.size()) + " vertices, " +
             std::to_string(mesh.triangles.size()) + " triangles\n");
  for (const std::string& line : mesh.comments) file.write("# " + detail::oneLine(line) + "\n");

  auto vectors = [](const std::vector<mesh::Vec3f>& values, std::string_view prefix) {
    return [&values, prefix](std::size_t begin, std::size_t end, std::string& out) {
      LineBuilder line(out);
      for (std::size_t i = begin; i < end; ++i) {
        line.text(prefix);
        line.number(values[i][0]);
        line.text(" ");
        line.number(values[i][1]);
        line.text(" ");
        line.number(values[i][2]);
        line.text("\n");
      }
    };
  };
  writeLines(file, mesh.positions.size(), vectors(mesh.positions, "v "));
  if (normals) writeLines(file, mesh.normals.size(), vectors(mesh.normals, "vn "));
  writeLines(file, mesh.triangles.size(), [&](std::size_t begin, std::size_t end, std::string& out) {
    LineBuilder line(out);
    for (std::size_t t = begin; t < end; ++t) {
      line.text("f");
      for (const std::uint32_t v : mesh.triangles[t]) {
        const std::uint64_t index = std::uint64_t{v} + 1;
        line.text(" ");
        line.number(index);
        if (normals) {
          line.text("//");
          line.number(index);
        }
      }
      line.text("\n");
    }
  });
  file.commit();
}

Mesh readObj(const std::filesystem::path& path) {
  const std::string text = readWholeFile(path);
  return ObjParser(path, text).parse();
}

}  // namespace isovdb::io
