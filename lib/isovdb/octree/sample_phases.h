// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file sample_phases.h
/// @brief The inside/outside bit of every sample of a meta-cell, the only thing
///        the octree's topological criteria read (criteria.h).
///
/// One bit per sample (1 = inside, value <= iso), x fastest, each row of x
/// padded to whole 64-bit words. A 128-meta-cell's phases take 290 KB, which
/// stays in cache where its 9 MB of floats do not, and a run of samples along
/// x is read as one word: the face labelling and the interior scans of the
/// octree construction were bound by cache misses on the floats.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "isovdb/cell/meta_cell_samples.h"

namespace isovdb::octree {

class SamplePhases {
 public:
  SamplePhases() = default;
  SamplePhases(const cell::MetaCellSamples& samples, float iso) { compute(samples, iso); }

  /// @brief Sets the bits from `samples` (inside iff value <= iso), apron included.
  void compute(const cell::MetaCellSamples& samples, float iso);

  /// S, cells per axis of the meta-cell (0 before compute).
  int size() const noexcept { return size_; }

  /// Phase of the sample at offset (i, j, k), each in [-A, S + A].
  bool inside(int i, int j, int k) const noexcept {
    const std::size_t bit = bitIndex(i, j, k);
    return ((words_[bit >> 6] >> (bit & 63)) & 1u) != 0;
  }
  bool inside(const std::array<int, 3>& p) const noexcept { return inside(p[0], p[1], p[2]); }

  /// @brief Phases of the `length` (1..64) samples from offset (i, j, k) along +x:
  ///        bit t is sample (i + t, j, k).
  /// @pre the run lies in the block.
  std::uint64_t row(int i, int j, int k, int length) const noexcept {
    const std::size_t bit = bitIndex(i, j, k);
    const std::size_t word = bit >> 6;
    const unsigned shift = static_cast<unsigned>(bit & 63);
    std::uint64_t bits = words_[word] >> shift;
    if (shift != 0 && shift + static_cast<unsigned>(length) > 64) bits |= words_[word + 1] << (64 - shift);
    return length == 64 ? bits : bits & ((std::uint64_t{1} << length) - 1);
  }

  /// @brief Phase of the `length` samples from (i, j, k) along +x: 0 all
  ///        outside, 1 all inside, -1 both.
  int runPhase(int i, int j, int k, int length) const noexcept {
    if (length > 64) return longRunPhase(i, j, k, length);
    const std::uint64_t bits = row(i, j, k, length);
    return bits == 0 ? 0 : bits == lowBits(length) ? 1 : -1;
  }

  /// @brief Phases of the `length` (1..64) samples from (i, j, k) along `axis`
  ///        (0 = x: row(); y and z gather one bit per row or slice).
  std::uint64_t line(int i, int j, int k, int axis, int length) const noexcept;

  /// @brief Phase changes between consecutive samples of the `length` samples
  ///        from (i, j, k) along `axis`.
  int changesAlong(int i, int j, int k, int axis, int length) const noexcept;

  /// @brief Phase of the cube of `extent`^3 samples with min corner `origin`:
  ///        0 all outside, 1 all inside, -1 both.
  int boxPhase(const std::array<int, 3>& origin, int extent) const noexcept;

  /// Mask of the `count` (0..64) lowest bits.
  static constexpr std::uint64_t lowBits(int count) noexcept {
    return count >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << count) - 1;
  }

 private:
  int longRunPhase(int i, int j, int k, int length) const noexcept;

  std::size_t bitIndex(int i, int j, int k) const noexcept {
    return (static_cast<std::size_t>(k + apron_) * stride_ + static_cast<std::size_t>(j + apron_)) * rowBits_ +
           static_cast<std::size_t>(i + apron_);
  }

  int size_ = 0;
  int apron_ = 1;
  std::size_t stride_ = 0;   // samples per axis, apron included
  std::size_t rowBits_ = 0;  // bits per row of x (a multiple of 64)
  std::vector<std::uint64_t> words_;
};

/// @brief Calls `visit(cell, config)` for every unit cell of [origin, origin + size]^3
///        whose eight corners are not all of one phase: its min corner (meta-cell
///        offsets) and corner signs (bit c set iff corner c is inside), in x-fastest order.
/// @pre the cell lies in the block.
template <class Visit>
void forEachCrossedUnitCell(const SamplePhases& phases, std::array<int, 3> origin, int size, Visit&& visit) {
  // Cells i0 .. i0 + 62 of a row come from one 64-bit run of each of the four sample
  // rows at their corners: bit i of `all` (`any`) is set iff every (some) corner
  // sample at x = i0 + i is inside; a cell is crossed iff it has an inside corner but
  // not only inside corners.
  constexpr int kCellsPerRun = 63;
  for (int k = 0; k < size; ++k)
    for (int j = 0; j < size; ++j)
      for (int i0 = 0; i0 < size; i0 += kCellsPerRun) {
        const int cells = std::min(kCellsPerRun, size - i0);
        const int x = origin[0] + i0, y = origin[1] + j, z = origin[2] + k;
        const std::array<std::uint64_t, 4> rows{phases.row(x, y, z, cells + 1), phases.row(x, y + 1, z, cells + 1),
                                                phases.row(x, y, z + 1, cells + 1),
                                                phases.row(x, y + 1, z + 1, cells + 1)};
        const std::uint64_t all = rows[0] & rows[1] & rows[2] & rows[3];
        const std::uint64_t any = rows[0] | rows[1] | rows[2] | rows[3];
        std::uint64_t crossed = (any | (any >> 1)) & ~(all & (all >> 1)) & SamplePhases::lowBits(cells);
        while (crossed != 0) {
          const int i = std::countr_zero(crossed);
          crossed &= crossed - 1;
          std::uint8_t config = 0;
          for (int c = 0; c < 8; ++c) {
            const std::uint64_t row = rows[static_cast<std::size_t>(c >> 1)];  // (y, z) bits of the corner
            config = static_cast<std::uint8_t>(config | (((row >> (i + (c & 1))) & 1u) << c));
          }
          visit(std::array<int, 3>{x + i, y, z}, config);
        }
      }
}

/// @brief True if the surface crosses a face of the cell [origin, origin + size]^3 that
///        lies on the boundary of the meta-cell [0, S]^3: the face's samples are not all of
///        one phase, so a unit edge on it is bipolar. Only such a cell has triangles on the
///        seam, which stitching makes later with the neighbouring block's cells and no check
///        after contouring sees; every other cell's triangles are the block's own.
/// @pre the cell lies in the block.
bool crossesMetaCellBoundary(const SamplePhases& phases, const std::array<int, 3>& origin, int size) noexcept;

}  // namespace isovdb::octree
