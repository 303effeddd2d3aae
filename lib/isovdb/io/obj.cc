// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/obj.h"

#include <algorithm>
#include <charconv>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"
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

}  // namespace

void writeObj(const std::filesystem::path& path, const Mesh& mesh) {
  checkMesh(path, mesh);
  const bool normals = !mesh.normals.empty();
  AtomicFile file(path);
  file.write("# written by isovdb: " + std::to_string(mesh.positions.size()) + " vertices, " +
             std::to_string(mesh.triangles.size()) + " triangles\n");

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

}  // namespace isovdb::io
