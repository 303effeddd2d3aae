// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file meta_cell_pieces.h
/// @brief The meta-cells one task of a distributed run contoured, as bytes for the trip
///        to the client (isovdb.distributed, Dask): each one's mesh and its seam (the
///        kept boundary cells and face vertices the stitcher reads), in meta-cell order.
///
/// Compact and exact: every field written as the engine holds it (floats bit for bit),
/// so the client's assembled mesh is the bytes one process writes. Little-endian, as
/// every machine this runs on; a version word guards against a client and workers built
/// from different sources.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "isovdb/pipeline/octree_contour.h"

namespace isovdb::pipeline {

/// Encodes the meta-cells handed to it, one after the other.
class MetaCellPieces final : public MetaCellConsumer {
 public:
  MetaCellPieces();
  void add(const volume::MetaCellIndex& index, contour::MetaCellMesh&& block) override;
  const std::string& bytes() const noexcept { return bytes_; }
  std::string release() noexcept { return std::move(bytes_); }
  std::int64_t count() const noexcept { return count_; }
  /// Of bytes(): those of the seams (what a run's stitching moves between machines).
  std::int64_t seamBytes() const noexcept { return seamBytes_; }

 private:
  std::string bytes_;
  std::int64_t count_ = 0;
  std::int64_t seamBytes_ = 0;
};

/// Decodes what MetaCellPieces encoded, one meta-cell at a time.
class MetaCellPieceReader {
 public:
  /// @param source names the bytes in messages (e.g. "slab 3 of 8").
  /// @throw InputError when the bytes do not start as MetaCellPieces' do.
  MetaCellPieceReader(std::string_view bytes, std::string source);
  /// The next meta-cell, or false after the last.
  /// @throw InputError for truncated or inconsistent bytes.
  bool next(volume::MetaCellIndex& index, contour::MetaCellMesh& block);

 private:
  std::string_view bytes_;
  std::string source_;
  std::size_t at_ = 0;
};

}  // namespace isovdb::pipeline
