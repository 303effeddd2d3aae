// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/meta_cell_pieces.h"

#include <cstring>
#include <type_traits>

#include "isovdb/errors.h"

namespace isovdb::pipeline {

namespace {

// "IVMC" and the layout's version: bump it whenever a field below changes.
constexpr std::uint32_t kMagic = 0x434d5649u;
constexpr std::uint32_t kVersion = 1;

template <typename T>
void put(std::string& out, const T& value) {
  static_assert(std::is_trivially_copyable_v<T>);
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

/// A vector's size, then its elements as they lie in memory (arrays of floats or ints: no padding).
template <typename T>
void putVector(std::string& out, const std::vector<T>& values) {
  static_assert(std::is_trivially_copyable_v<T>);
  put(out, static_cast<std::uint64_t>(values.size()));
  out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

/// Field by field: the structs' padding bytes would make the same seam encode differently.
void putCell(std::string& out, const contour::SeamCell& c) {
  put(out, c.key);
  put(out, c.origin);
  put(out, c.size);
  put(out, c.cornerSigns);
  put(out, static_cast<std::uint8_t>(c.alternative));
  put(out, c.vertices);
  put(out, c.positions);
  put(out, c.splitFaces);
  put(out, c.splitVertices);
  put(out, c.edgeCrossing);
}

void putFace(std::string& out, const contour::SeamFace& f) {
  put(out, f.face.min);
  put(out, f.face.size);
  put(out, f.face.axis);
  put(out, f.face.part);
  put(out, f.vertex);
}

}  // namespace

MetaCellPieces::MetaCellPieces() {
  put(bytes_, kMagic);
  put(bytes_, kVersion);
}

void MetaCellPieces::add(const volume::MetaCellIndex& index, contour::MetaCellMesh&& block) {
  put(bytes_, index);
  putVector(bytes_, block.mesh.positions);
  putVector(bytes_, block.mesh.triangles);
  const std::size_t seamStart = bytes_.size();
  put(bytes_, static_cast<std::uint64_t>(block.seam.cells.size()));
  for (const contour::SeamCell& c : block.seam.cells) putCell(bytes_, c);
  put(bytes_, static_cast<std::uint64_t>(block.seam.faces.size()));
  for (const contour::SeamFace& f : block.seam.faces) putFace(bytes_, f);
  seamBytes_ += static_cast<std::int64_t>(bytes_.size() - seamStart);
  ++count_;
}

namespace {

/// Reads values back from the bytes, refusing to read past their end.
class Cursor {
 public:
  Cursor(std::string_view bytes, std::size_t& at, const std::string& source)
      : bytes_(bytes), at_(at), source_(source) {}

  template <typename T>
  void get(T& value) {
    need(sizeof(T));
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
  }

  template <typename T>
  void getVector(std::vector<T>& values) {
    std::uint64_t n = 0;
    get(n);
    if (n > (bytes_.size() - at_) / sizeof(T)) fail();
    values.resize(static_cast<std::size_t>(n));
    std::memcpy(values.data(), bytes_.data() + at_, values.size() * sizeof(T));
    at_ += values.size() * sizeof(T);
  }

  std::size_t count(std::size_t leastBytesEach) {
    std::uint64_t n = 0;
    get(n);
    if (n > (bytes_.size() - at_) / leastBytesEach) fail();
    return static_cast<std::size_t>(n);
  }

  [[noreturn]] void fail() const {
    throw InputError(source_ + ": meta-cell pieces end early or are corrupt (at byte " + std::to_string(at_) + " of " +
                     std::to_string(bytes_.size()) + ")");
  }

 private:
  void need(std::size_t n) const {
    if (n > bytes_.size() - at_) fail();
  }
  std::string_view bytes_;
  std::size_t& at_;
  const std::string& source_;
};

}  // namespace

MetaCellPieceReader::MetaCellPieceReader(std::string_view bytes, std::string source)
    : bytes_(bytes), source_(std::move(source)) {
  Cursor in(bytes_, at_, source_);
  std::uint32_t magic = 0, version = 0;
  in.get(magic);
  in.get(version);
  if (magic != kMagic || version != kVersion)
    throw InputError(source_ + ": not meta-cell pieces of this isovdb (a worker built from other sources?)");
}

bool MetaCellPieceReader::next(volume::MetaCellIndex& index, contour::MetaCellMesh& block) {
  if (at_ == bytes_.size()) return false;
  Cursor in(bytes_, at_, source_);
  block = {};
  in.get(index);
  in.getVector(block.mesh.positions);
  in.getVector(block.mesh.triangles);
  block.seam.cells.resize(in.count(sizeof(octree::MortonKey)));
  for (contour::SeamCell& c : block.seam.cells) {
    std::uint8_t alternative = 0;
    in.get(c.key);
    in.get(c.origin);
    in.get(c.size);
    in.get(c.cornerSigns);
    in.get(alternative);
    c.alternative = alternative != 0;
    in.get(c.vertices);
    in.get(c.positions);
    in.get(c.splitFaces);
    in.get(c.splitVertices);
    in.get(c.edgeCrossing);
  }
  block.seam.faces.resize(in.count(sizeof(std::int32_t)));
  for (contour::SeamFace& f : block.seam.faces) {
    in.get(f.face.min);
    in.get(f.face.size);
    in.get(f.face.axis);
    in.get(f.face.part);
    in.get(f.vertex);
  }
  const auto vertices = static_cast<std::uint32_t>(block.mesh.positions.size());
  for (const mesh::Triangle& t : block.mesh.triangles)
    for (const std::uint32_t v : t)
      if (v >= vertices) in.fail();
  return true;
}

}  // namespace isovdb::pipeline
