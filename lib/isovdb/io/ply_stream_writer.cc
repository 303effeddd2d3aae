#include "isovdb/io/ply_stream_writer.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "isovdb/errors.h"

namespace isovdb::io {

namespace {

/// PLY header for the given counts; `padding` spaces in a comment line make its size fixed.
std::string plyHeader(std::uint64_t vertices, std::uint64_t triangles, std::size_t padding) {
  std::string header = "ply\nformat binary_little_endian 1.0\ncomment written by isovdb\n";
  header += "comment " + std::string(padding, ' ') + "\n";
  header += "element vertex " + std::to_string(vertices) + "\n";
  header += "property float x\nproperty float y\nproperty float z\n";
  header += "element face " + std::to_string(triangles) + "\n";
  header += "property list uchar uint vertex_indices\nend_header\n";
  return header;
}

/// Room for the largest counts (20 digits each).
constexpr std::size_t kCountRoom = 2 * 20;

template <class T>
void appendLittleEndian(std::vector<char>& out, T value) {
  auto bits = std::bit_cast<std::array<char, sizeof(T)>>(value);
  if constexpr (std::endian::native == std::endian::big) std::reverse(bits.begin(), bits.end());
  out.insert(out.end(), bits.begin(), bits.end());
}

}  // namespace

PlyStreamWriter::PlyStreamWriter(const std::filesystem::path& path, std::array<double, 3> scale,
                                 std::array<double, 3> offset)
    : path_(path), scale_(scale), offset_(offset), file_(path), faces_(path) {
  const std::string header = plyHeader(0, 0, kCountRoom);
  headerSize_ = header.size();
  file_.write(header);
}

void PlyStreamWriter::addVertices(std::span<const mesh::Vec3f> positions) {
  std::vector<char> bytes;
  bytes.reserve(positions.size() * 12);
  for (const mesh::Vec3f& p : positions)
    for (int a = 0; a < 3; ++a)
      appendLittleEndian(bytes, static_cast<float>(offset_[a] + scale_[a] * static_cast<double>(p[a])));
  file_.write(bytes.data(), bytes.size());
  vertices_ += positions.size();
}

void PlyStreamWriter::addTriangles(std::span<const mesh::Triangle> triangles) {
  std::vector<char> bytes;
  bytes.reserve(triangles.size() * 13);
  for (const mesh::Triangle& t : triangles) {
    bytes.push_back(3);
    for (const std::uint32_t v : t) {
      if (v >= vertices_)
        throw InputError("cannot write '" + path_.string() + "': a triangle refers to vertex " + std::to_string(v) +
                         " of " + std::to_string(vertices_));
      appendLittleEndian(bytes, v);
    }
  }
  faces_.write(bytes.data(), bytes.size());
  triangles_ += triangles.size();
}

void PlyStreamWriter::commit() {
  if (vertices_ > std::numeric_limits<std::uint32_t>::max())
    throw InputError("cannot write '" + path_.string() + "': more than 2^32 - 1 vertices");
  faces_.flush();
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(faces_.temporaryPath().c_str(), "rb"), &std::fclose);
  if (!in) throw IoError("cannot write '" + path_.string() + "': cannot read back its triangles");
  std::vector<char> block(std::size_t{1} << 20);
  for (std::size_t n; (n = std::fread(block.data(), 1, block.size(), in.get())) > 0;) file_.write(block.data(), n);
  if (std::ferror(in.get())) throw IoError("cannot write '" + path_.string() + "': cannot read back its triangles");
  const std::string digits = std::to_string(vertices_) + std::to_string(triangles_);
  const std::string header = plyHeader(vertices_, triangles_, kCountRoom - (digits.size() - 2));
  if (header.size() != headerSize_) throw IoError("cannot write '" + path_.string() + "': header size changed");
  file_.overwrite(0, header.data(), header.size());
  file_.commit();
}

}  // namespace isovdb::io
