/// @file meta_cell_samples.h
/// @brief The dense sample block of one meta-cell, the only dense array the
///        contouring engine holds (paper 000, section 4.1–4.2).
///
/// A meta-cell is a cube of S x S x S cells (S a power of two, default 128,
/// aligned with OpenVDB's level-1 internal nodes). It holds the S + 1 samples
/// per axis that it shares with its neighbours (offsets 0..S), plus a
/// one-sample apron (offsets -1 and S + 1) so that the Prewitt 3x3x3 gradient
/// is defined at every shared sample. Values are in voxel index space,
/// x fastest: (S + 3)^3 floats, about 9 MB for S = 128.
///
/// Sign convention: SDF negative inside; a sample is INSIDE iff value <= iso
/// (an exact-iso sample counts as inside, everywhere in the engine).
#pragma once

#include <array>
#include <cassert>
#include <cstddef>
#include <vector>

namespace isovdb::octree {

/// @brief True iff a sample value is inside the isosurface (value <= iso).
inline bool isInside(float value, float iso) noexcept { return value <= iso; }

/// @brief Dense samples of one meta-cell (S + 1 shared samples plus a 1-sample apron per side).
struct MetaCellSamples {
  int size = 0;                         ///< S, cells per axis (power of two); 0 = empty
  std::array<int, 3> origin{0, 0, 0};   ///< index coordinate of the sample at offset (0,0,0)
  std::vector<float> values;            ///< (S + 3)^3 values, offsets -1..S+1, x fastest

  /// Samples per axis including the apron (S + 3).
  int stride() const noexcept { return size + 3; }

  /// Linear index of offset (i, j, k), each in [-1, S + 1].
  std::size_t indexOf(int i, int j, int k) const noexcept {
    assert(i >= -1 && j >= -1 && k >= -1 && i <= size + 1 && j <= size + 1 && k <= size + 1);
    const std::size_t s = static_cast<std::size_t>(stride());
    return (static_cast<std::size_t>(k + 1) * s + static_cast<std::size_t>(j + 1)) * s +
           static_cast<std::size_t>(i + 1);
  }
  /// Value at offset (i, j, k) from `origin`, each in [-1, S + 1].
  float value(int i, int j, int k) const noexcept { return values[indexOf(i, j, k)]; }
  float& value(int i, int j, int k) noexcept { return values[indexOf(i, j, k)]; }
  /// Value at an offset given as an array.
  float value(const std::array<int, 3>& p) const noexcept { return value(p[0], p[1], p[2]); }

  /// @brief Sets size and origin and allocates (S + 3)^3 values set to `fill`.
  /// @throw InputError if `size` is not a power of two in [1, 2^16].
  void allocate(int size, std::array<int, 3> origin, float fill = 0.0f);

  /// @brief Fills every sample (apron included) from `f(x, y, z)` with x, y, z
  ///        the sample's global index coordinates (ints). Used by tests
  ///        (analytic SDFs) and small inputs.
  /// @pre allocate() was called.
  template <class F>
  void fillFrom(F&& f) {
    const int n = stride();
    std::size_t idx = 0;
    for (int k = -1; k < n - 1; ++k)
      for (int j = -1; j < n - 1; ++j)
        for (int i = -1; i < n - 1; ++i)
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

}  // namespace isovdb::octree
