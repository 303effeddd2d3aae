// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/octree/unit_edge_crossings.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>
#include <bit>

#include "isovdb/bit_count.h"
#include "isovdb/octree/sample_phases.h"

namespace isovdb::octree {

namespace {

/// The Prewitt gradients of the samples of two neighbouring slices (z = k and k + 1), each
/// computed when an edge first asks for it: a sample beside the surface ends two or three
/// bipolar edges, and the gradients were most of this table's cost.
class SliceGradients {
 public:
  explicit SliceGradients(const cell::MetaCellSamples& samples)
      : samples_(samples), side_(static_cast<std::size_t>(samples.size) + 1) {
    for (Slice& slice : slices_) {
      slice.gradients.resize(side_ * side_);
      slice.known.assign((side_ * side_ + 63) / 64, 0);
    }
  }

  /// Moves the slices up by one: the upper becomes the lower, the new upper is empty.
  void advance() {
    std::swap(slices_[0], slices_[1]);
    std::fill(slices_[1].known.begin(), slices_[1].known.end(), 0);
    ++lowerZ_;
  }

  /// prewittGradient at sample (i, j, lowerZ + dz), dz 0 or 1.
  const cell::Vec3f& at(int i, int j, int dz) {
    Slice& slice = slices_[static_cast<std::size_t>(dz)];
    const std::size_t n = static_cast<std::size_t>(j) * side_ + static_cast<std::size_t>(i);
    const std::uint64_t bit = std::uint64_t{1} << (n & 63);
    if ((slice.known[n >> 6] & bit) == 0) {
      slice.gradients[n] = cell::prewittGradient(samples_, i, j, lowerZ_ + dz);
      slice.known[n >> 6] |= bit;
    }
    return slice.gradients[n];
  }

 private:
  struct Slice {
    std::vector<cell::Vec3f> gradients;
    std::vector<std::uint64_t> known;
  };
  const cell::MetaCellSamples& samples_;
  std::size_t side_;
  int lowerZ_ = 0;
  std::array<Slice, 2> slices_;
};

}  // namespace

UnitEdgeCrossings::UnitEdgeCrossings(const cell::MetaCellSamples& samples, float iso, bool sharpFeatures)
    : UnitEdgeCrossings(samples, SamplePhases(samples, iso), iso, sharpFeatures) {}

UnitEdgeCrossings::UnitEdgeCrossings(const cell::MetaCellSamples& samples, const SamplePhases& phases, float iso,
                                     bool sharpFeatures)
    : size_(samples.size), wordsPerRow_((samples.size + 64) / 64) {
  const int s = size_;
  const std::size_t rows = static_cast<std::size_t>(s + 1) * static_cast<std::size_t>(s + 1);
  for (int axis = 0; axis < 3; ++axis) {
    bipolar_[static_cast<std::size_t>(axis)].assign(rows * static_cast<std::size_t>(wordsPerRow_), 0);
    before_[static_cast<std::size_t>(axis)].assign(rows * static_cast<std::size_t>(wordsPerRow_), 0);
    crossings_[static_cast<std::size_t>(axis)].clear();
  }
  SliceGradients gradients(samples);
  for (int k = 0; k <= s; ++k, gradients.advance())
    for (int j = 0; j <= s; ++j) {
      const std::size_t row =
          (static_cast<std::size_t>(k) * static_cast<std::size_t>(s + 1) + static_cast<std::size_t>(j)) *
          static_cast<std::size_t>(wordsPerRow_);
      for (int w = 0; w < wordsPerRow_; ++w) {
        const int i0 = 64 * w;
        const int starts = std::min(64, s + 1 - i0);  // edge starts i0 .. i0 + starts - 1 along y and z
        const std::uint64_t here = phases.row(i0, j, k, starts);
        std::array<std::uint64_t, 3> bits{};
        const int along = std::min(64, s - i0);  // x edges start before sample S
        if (along > 0) bits[0] = phases.row(i0, j, k, along) ^ phases.row(i0 + 1, j, k, along);
        if (j < s) bits[1] = here ^ phases.row(i0, j + 1, k, starts);
        if (k < s) bits[2] = here ^ phases.row(i0, j, k + 1, starts);
        for (int axis = 0; axis < 3; ++axis) {
          auto& crossings = crossings_[static_cast<std::size_t>(axis)];
          bipolar_[static_cast<std::size_t>(axis)][row + static_cast<std::size_t>(w)] =
              bits[static_cast<std::size_t>(axis)];
          before_[static_cast<std::size_t>(axis)][row + static_cast<std::size_t>(w)] =
              static_cast<std::uint32_t>(crossings.size());
          for (std::uint64_t b = bits[static_cast<std::size_t>(axis)]; b != 0; b &= b - 1) {
            const int i = i0 + std::countr_zero(b);
            if (sharpFeatures) {  // crossings beside a crease are placed from its faces
              cell::EdgeIntersection hit;
              cell::intersectEdge(samples, {i, j, k}, axis, 1, iso, hit, true);
              crossings.push_back(hit);
              continue;
            }
            const cell::Vec3f& g0 = gradients.at(i, j, 0);
            const cell::Vec3f& g1 = gradients.at(i + (axis == 0 ? 1 : 0), j + (axis == 1 ? 1 : 0), axis == 2 ? 1 : 0);
            crossings.push_back(cell::unitEdgeCrossing(samples, {i, j, k}, axis, iso, g0, g1));
          }
        }
      }
    }
}

const cell::EdgeIntersection* UnitEdgeCrossings::find(const std::array<int, 3>& start, int axis) const noexcept {
  const std::size_t word =
      (static_cast<std::size_t>(start[2]) * static_cast<std::size_t>(size_ + 1) + static_cast<std::size_t>(start[1])) *
          static_cast<std::size_t>(wordsPerRow_) +
      static_cast<std::size_t>(start[0] >> 6);
  const std::uint64_t bits = bipolar_[static_cast<std::size_t>(axis)][word];
  const std::uint64_t bit = std::uint64_t{1} << (start[0] & 63);
  if ((bits & bit) == 0) return nullptr;
  const std::uint32_t index =
      before_[static_cast<std::size_t>(axis)][word] + static_cast<std::uint32_t>(countBits(bits & (bit - 1)));
  return &crossings_[static_cast<std::size_t>(axis)][index];
}

const cell::EdgeIntersection* UnitEdgeCrossings::findFirst(std::array<int, 3> start, int axis,
                                                           int length) const noexcept {
  for (int t = 0; t < length; ++t, ++start[static_cast<std::size_t>(axis)])
    if (const cell::EdgeIntersection* hit = find(start, axis)) return hit;
  return nullptr;
}

}  // namespace isovdb::octree
