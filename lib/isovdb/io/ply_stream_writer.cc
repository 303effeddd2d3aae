// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/ply_stream_writer.h"

#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "isovdb/errors.h"
#include "isovdb/io/little_endian.h"
#include "isovdb/io/ply.h"

namespace isovdb::io {

PlyStreamWriter::PlyStreamWriter(const std::filesystem::path& path, std::array<double, 3> scale,
                                 std::array<double, 3> offset, std::size_t triangleBytesInMemory)
    : path_(path), scale_(scale), offset_(offset), triangleBytesInMemory_(triangleBytesInMemory), file_(path) {
  const std::string header = detail::binaryPlyHeader(0, 0, false);
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
  std::vector<char> batch;  // nothing is kept or written before every index is checked
  batch.reserve(triangles.size() * 13);
  for (const mesh::Triangle& t : triangles) {
    appendLittleEndian(batch, std::uint8_t{3});
    for (const std::uint32_t v : t) {
      if (v >= vertices_)
        throw InputError("cannot write '" + path_.string() + "': a triangle refers to vertex " + std::to_string(v) +
                         " of " + std::to_string(vertices_));
      appendLittleEndian(batch, v);
    }
  }
  // Past the budget, the waiting batches go to the spill file, and every batch after them.
  if (!spilled_ && waitingBytes_ + batch.size() > triangleBytesInMemory_) {
    spilled_.emplace(path_);
    for (const std::vector<char>& waiting : waitingFaces_) spilled_->write(waiting.data(), waiting.size());
    std::vector<std::vector<char>>().swap(waitingFaces_);
  }
  if (spilled_) {
    spilled_->write(batch.data(), batch.size());
  } else {
    waitingBytes_ += batch.size();
    waitingFaces_.push_back(std::move(batch));
  }
  triangles_ += triangles.size();
}

void PlyStreamWriter::commit() {
  if (vertices_ > std::numeric_limits<std::uint32_t>::max())
    throw InputError("cannot write '" + path_.string() + "': more than 2^32 - 1 vertices");
  if (spilled_) {
    spilled_->flush();
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(spilled_->temporaryPath().c_str(), "rb"),
                                                       &std::fclose);
    if (!in) throw IoError("cannot write '" + path_.string() + "': cannot read back its triangles");
    std::vector<char> block(std::size_t{1} << 20);
    for (std::size_t n; (n = std::fread(block.data(), 1, block.size(), in.get())) > 0;) file_.write(block.data(), n);
    if (std::ferror(in.get())) throw IoError("cannot write '" + path_.string() + "': cannot read back its triangles");
  }
  for (const std::vector<char>& waiting : waitingFaces_) file_.write(waiting.data(), waiting.size());
  const std::string header = detail::binaryPlyHeader(vertices_, triangles_, false);
  if (header.size() != headerSize_) throw IoError("cannot write '" + path_.string() + "': header size changed");
  file_.overwrite(0, header.data(), header.size());
  file_.commit();
}

}  // namespace isovdb::io
