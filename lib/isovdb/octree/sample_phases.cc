// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/octree/sample_phases.h"

#include <algorithm>

#include "isovdb/bit_count.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace isovdb::octree {

void SamplePhases::compute(const cell::MetaCellSamples& samples, float iso) {
  size_ = samples.size;
  apron_ = samples.apron;
  stride_ = static_cast<std::size_t>(samples.stride());
  const std::size_t wordsPerRow = (stride_ + 63) / 64;
  rowBits_ = wordsPerRow * 64;
  words_.resize(stride_ * stride_ * wordsPerRow);
  const float* value = samples.values.data();
  std::uint64_t* out = words_.data();
  for (std::size_t r = 0; r < stride_ * stride_; ++r)
    for (std::size_t w = 0; w < wordsPerRow; ++w) {
      const std::size_t count = std::min<std::size_t>(64, stride_ - w * 64);
      std::uint64_t word = 0;
      std::size_t t = 0;
#if defined(__SSE2__)
      // Four comparisons per instruction: this pass reads every float of the meta-cell.
      const __m128 threshold = _mm_set1_ps(iso);
      for (; t + 4 <= count; t += 4)
        word |= static_cast<std::uint64_t>(_mm_movemask_ps(_mm_cmple_ps(_mm_loadu_ps(value + t), threshold))) << t;
#endif
      for (; t < count; ++t) word |= static_cast<std::uint64_t>(cell::isInside(value[t], iso)) << t;
      value += count;
      *out++ = word;
    }
}

int SamplePhases::longRunPhase(int i, int j, int k, int length) const noexcept {
  int phase = -1;
  for (int t = 0; t < length; t += 64) {
    const int count = std::min(64, length - t);
    const std::uint64_t bits = row(i + t, j, k, count);
    const int p = bits == 0 ? 0 : bits == lowBits(count) ? 1 : -1;
    if (p < 0 || (phase >= 0 && p != phase)) return -1;
    phase = p;
  }
  return phase;
}

int SamplePhases::boxPhase(const std::array<int, 3>& origin, int extent) const noexcept {
  const int phase = runPhase(origin[0], origin[1], origin[2], extent);
  for (int k = 0; k < extent && phase >= 0; ++k)
    for (int j = 0; j < extent; ++j)
      if (runPhase(origin[0], origin[1] + j, origin[2] + k, extent) != phase) return -1;
  return phase;
}

std::uint64_t SamplePhases::line(int i, int j, int k, int axis, int length) const noexcept {
  if (axis == 0) return row(i, j, k, length);
  // Across rows: step the bit index by a row (y) or a slice (z) of rows.
  const std::size_t step = axis == 1 ? rowBits_ : rowBits_ * stride_;
  std::size_t bit = bitIndex(i, j, k);
  std::uint64_t bits = 0;
  for (int t = 0; t < length; ++t, bit += step) bits |= ((words_[bit >> 6] >> (bit & 63)) & 1u) << t;
  return bits;
}

int SamplePhases::changesAlong(int i, int j, int k, int axis, int length) const noexcept {
  std::array<int, 3> p{i, j, k};
  const int first = p[static_cast<std::size_t>(axis)];
  int changes = 0;
  // Chunks of 64 samples that overlap by one, so each pair is compared once.
  for (int t = 0; t + 1 < length; t += 63) {
    const int count = std::min(64, length - t);
    p[static_cast<std::size_t>(axis)] = first + t;
    const std::uint64_t bits = line(p[0], p[1], p[2], axis, count);
    changes += countBits((bits ^ (bits >> 1)) & lowBits(count - 1));
  }
  return changes;
}

bool crossesMetaCellBoundary(const SamplePhases& phases, const std::array<int, 3>& origin, int size) noexcept {
  for (std::size_t a = 0; a < 3; ++a)
    for (const int plane : {0, phases.size()}) {
      if (origin[a] + (plane == 0 ? 0 : size) != plane) continue;
      std::array<int, 3> p = origin;
      p[a] = plane;
      if (a != 0) {  // runs of size + 1 samples along x, one per line across the face
        const std::size_t across = a == 1 ? 2 : 1;
        const int first = phases.runPhase(p[0], p[1], p[2], size + 1);
        if (first < 0) return true;
        for (int t = 1; t <= size; ++t) {
          p[across] = origin[across] + t;
          if (phases.runPhase(p[0], p[1], p[2], size + 1) != first) return true;
        }
        continue;
      }
      const bool first = phases.inside(p);  // the face x = plane: sample by sample
      for (int k = 0; k <= size; ++k)
        for (int j = 0; j <= size; ++j)
          if (phases.inside(plane, origin[1] + j, origin[2] + k) != first) return true;
    }
  return false;
}

}  // namespace isovdb::octree
