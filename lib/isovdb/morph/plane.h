// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file plane.h
/// @brief The two 2-D value types of the morph stage: a binary slice (Mask2) and a
///        scalar field on the same pixel grid (Field2), with bilinear sampling.
///
/// Coordinates: pixel (x, y) has its centre at (x, y); rows are y, x runs fastest
/// (index = y * width + x). A Field2 holding a signed distance is in pixels,
/// NEGATIVE inside.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace isovdb::morph {

/// A point or a displacement in pixel coordinates.
struct Vec2 {
  double x = 0.0, y = 0.0;
};

/// Binary slice: 1 = inside the object.
struct Mask2 {
  int width = 0, height = 0;
  std::vector<std::uint8_t> inside;  ///< width * height, 0 or 1

  static Mask2 empty(int width, int height) {
    return {width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height, 0)};
  }
  bool at(int x, int y) const { return inside[static_cast<std::size_t>(y) * width + x] != 0; }
  void set(int x, int y, bool value) { inside[static_cast<std::size_t>(y) * width + x] = value ? 1 : 0; }
  std::int64_t area() const {
    std::int64_t n = 0;
    for (std::uint8_t v : inside) n += v;
    return n;
  }
};

/// Scalar field on a pixel grid (signed distances, arrival times, ...).
struct Field2 {
  int width = 0, height = 0;
  std::vector<float> values;  ///< width * height

  static Field2 filled(int width, int height, float value) {
    return {width, height, std::vector<float>(static_cast<std::size_t>(width) * height, value)};
  }
  std::size_t size() const { return values.size(); }
  float at(int x, int y) const { return values[static_cast<std::size_t>(y) * width + x]; }
  float& at(int x, int y) { return values[static_cast<std::size_t>(y) * width + x]; }

  /// Bilinear value at a real position. Outside the grid the nearest border value
  /// is continued by the distance to the grid (a signed distance stays positive
  /// and grows outwards when the border is outside the object).
  float sample(double x, double y) const {
    const double cx = std::clamp(x, 0.0, double(width - 1)), cy = std::clamp(y, 0.0, double(height - 1));
    const double beyond = std::hypot(x - cx, y - cy);
    const int x0 = std::min(static_cast<int>(cx), width - 2 < 0 ? 0 : width - 2);
    const int y0 = std::min(static_cast<int>(cy), height - 2 < 0 ? 0 : height - 2);
    const int x1 = std::min(x0 + 1, width - 1), y1 = std::min(y0 + 1, height - 1);
    const double fx = cx - x0, fy = cy - y0;
    const double v =
        (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x1, y0)) + fy * ((1 - fx) * at(x0, y1) + fx * at(x1, y1));
    return static_cast<float>(v + beyond);
  }
};

/// Pixels where `field` is <= 0 (inside).
inline Mask2 insideOf(const Field2& field) {
  Mask2 mask = Mask2::empty(field.width, field.height);
  for (std::size_t i = 0; i < field.values.size(); ++i) mask.inside[i] = field.values[i] <= 0.f ? 1 : 0;
  return mask;
}

}  // namespace isovdb::morph
