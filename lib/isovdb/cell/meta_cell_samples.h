// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file meta_cell_samples.h
/// @brief The dense sample block of one meta-cell, the only dense array the
///        contouring engine holds (paper 000, section 4.1–4.2).
///
/// A meta-cell is a cube of S x S x S cells (S a power of two, default 128,
/// aligned with OpenVDB's level-1 internal nodes). It holds the S + 1 samples
/// per axis that it shares with its neighbours (offsets 0..S), plus a
/// apron of A >= 1 samples (offsets -A..-1 and S+1..S+A): one sample makes the
/// Prewitt 3x3x3 gradient defined at every shared sample; regular mode asks for
/// one finest cell so that Wenger's fix sees the neighbour cell across the
/// meta-cell boundary. Values are in voxel index space, x fastest:
/// (S + 1 + 2A)^3 floats, about 9 MB for S = 128, A = 1.
///
/// Sign convention: SDF negative inside; a sample is INSIDE iff value <= iso
/// (an exact-iso sample counts as inside, everywhere in the engine).
#pragma once

#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "isovdb/cell/box_rim_gradients.h"

namespace isovdb::cell {

/// @brief True iff a sample value is inside the isosurface (value <= iso).
inline bool isInside(float value, float iso) noexcept { return value <= iso; }

/// @brief Dense samples of one meta-cell (S + 1 shared samples plus a 1-sample apron per side).
struct MetaCellSamples {
  int size = 0;                        ///< S, cells per axis (power of two); 0 = empty
  int apron = 1;                       ///< A, samples beyond the shared ones on each side (>= 1)
  std::array<int, 3> origin{0, 0, 0};  ///< index coordinate of the sample at offset (0,0,0)
  std::vector<float> values;           ///< (S + 1 + 2A)^3 values, offsets -A..S+A, x fastest
  /// The field's own Prewitt gradients on the data box's faces, where the samples beyond it
  /// read far outside (keepBoxRimGradients, cell/gradient.h); reset by allocate and reshape.
  BoxRimGradients boxRim;

  /// Samples per axis including the apron (S + 1 + 2A).
  int stride() const noexcept { return size + 1 + 2 * apron; }

  /// True if offset (i, j, k) lies in the block (apron included).
  bool contains(int i, int j, int k) const noexcept {
    return i >= -apron && j >= -apron && k >= -apron && i <= size + apron && j <= size + apron && k <= size + apron;
  }

  /// Linear index of offset (i, j, k), each in [-A, S + A].
  std::size_t indexOf(int i, int j, int k) const noexcept {
    assert(contains(i, j, k));
    const std::size_t s = static_cast<std::size_t>(stride());
    return (static_cast<std::size_t>(k + apron) * s + static_cast<std::size_t>(j + apron)) * s +
           static_cast<std::size_t>(i + apron);
  }
  /// Samples between neighbours along `axis` (0, 1, 2) in `values`.
  std::ptrdiff_t axisStep(int axis) const noexcept {
    const auto s = static_cast<std::ptrdiff_t>(stride());
    return axis == 0 ? 1 : axis == 1 ? s : s * s;
  }
  /// Value at offset (i, j, k) from `origin`, each in [-A, S + A].
  float value(int i, int j, int k) const noexcept { return values[indexOf(i, j, k)]; }
  float& value(int i, int j, int k) noexcept { return values[indexOf(i, j, k)]; }
  /// Value at an offset given as an array.
  float value(const std::array<int, 3>& p) const noexcept { return value(p[0], p[1], p[2]); }

  /// @brief Sets size, origin and apron and allocates (S + 1 + 2A)^3 values set to `fill`.
  /// @throw InputError if `size` is not a power of two in [1, 2^16] or `apron` is not in [1, size].
  void allocate(int size, std::array<int, 3> origin, float fill = 0.0f, int apron = 1);

  /// @brief As allocate, but leaves the values unspecified: for a caller that
  ///        writes every sample anyway. A block reused for meta-cells of one
  ///        size keeps its memory, so no page is faulted in again.
  /// @throw InputError as allocate.
  void reshape(int size, std::array<int, 3> origin, int apron = 1);

  /// @brief Fills every sample (apron included) from `f(x, y, z)` with x, y, z
  ///        the sample's global index coordinates (ints). Used by tests
  ///        (analytic SDFs) and small inputs.
  /// @pre allocate() was called.
  template <class F>
  void fillFrom(F&& f) {
    const int n = stride();
    std::size_t idx = 0;
    for (int k = -apron; k < n - apron; ++k)
      for (int j = -apron; j < n - apron; ++j)
        for (int i = -apron; i < n - apron; ++i)
          values[idx++] = static_cast<float>(f(origin[0] + i, origin[1] + j, origin[2] + k));
  }
};

/// @brief One-off helper: a block of size S at `origin` filled from `f(x, y, z)` (global index coords).
/// @throw InputError as MetaCellSamples::allocate.
template <class F>
MetaCellSamples makeMetaCellSamples(int size, std::array<int, 3> origin, F&& f) {
  MetaCellSamples samples;
  samples.allocate(size, origin);
  samples.fillFrom(static_cast<F&&>(f));
  return samples;
}

/// @brief 8-bit corner sign configuration of the cell [origin, origin + size] (meta-cell
///        offsets; bit c set iff corner c is inside).
inline std::uint8_t cellCornerSigns(const MetaCellSamples& samples, std::array<int, 3> origin, int size,
                                    float iso) noexcept {
  std::uint8_t signs = 0;
  for (int c = 0; c < 8; ++c) {
    const float v =
        samples.value(origin[0] + (c & 1) * size, origin[1] + ((c >> 1) & 1) * size, origin[2] + ((c >> 2) & 1) * size);
    if (isInside(v, iso)) signs = static_cast<std::uint8_t>(signs | (1u << c));
  }
  return signs;
}

}  // namespace isovdb::cell
