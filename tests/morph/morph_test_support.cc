// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "morph_test_support.h"

#include <algorithm>
#include <cmath>

#include "isovdb/morph/slice_image.h"

namespace isovdb::morph::test {

Mask2 rectangle(int w, int h, double x0, double y0, double x1, double y1) {
  Mask2 m = Mask2::empty(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m.set(x, y, x >= x0 && x <= x1 && y >= y0 && y <= y1);
  return m;
}

Mask2 disc(int w, int h, double cx, double cy, double r) {
  Mask2 m = Mask2::empty(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m.set(x, y, std::hypot(x - cx, y - cy) <= r);
  return m;
}

Mask2 unite(const Mask2& a, const Mask2& b) {
  Mask2 m = a;
  for (std::size_t i = 0; i < m.inside.size(); ++i) m.inside[i] = a.inside[i] | b.inside[i];
  return m;
}

Mask2 subtract(const Mask2& a, const Mask2& b) {
  Mask2 m = a;
  for (std::size_t i = 0; i < m.inside.size(); ++i) m.inside[i] = a.inside[i] && !b.inside[i];
  return m;
}

Mask2 contourOf(const Mask2& mask) {
  Mask2 out = Mask2::empty(mask.width, mask.height);
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x) {
      if (!mask.at(x, y)) continue;
      const auto outside = [&](int i, int j) {
        return i < 0 || j < 0 || i >= mask.width || j >= mask.height || !mask.at(i, j);
      };
      out.set(x, y, outside(x - 1, y) || outside(x + 1, y) || outside(x, y - 1) || outside(x, y + 1));
    }
  return out;
}

SliceStack stackOf(const std::vector<Mask2>& masks, const std::vector<double>& heights) {
  SliceStack stack;
  stack.width = masks.front().width;
  stack.height = masks.front().height;
  for (std::size_t i = 0; i < masks.size(); ++i)
    stack.slices.push_back({masks[i], heights[i], "slice " + std::to_string(i)});
  return stack;
}

std::vector<Mask2> pyramid() {
  return {rectangle(64, 64, 10, 14, 53, 49), rectangle(64, 64, 17, 20, 46, 43), rectangle(64, 64, 27, 24, 42, 35)};
}

std::vector<Mask2> candlestick() {
  const int n = 64;
  return {unite(disc(n, n, 20, 32, 7), disc(n, n, 44, 32, 7)), disc(n, n, 32, 32, 12),
          unite(disc(n, n, 18, 32, 6), disc(n, n, 46, 32, 6)),
          unite(unite(disc(n, n, 14, 32, 4), disc(n, n, 24, 32, 4)), disc(n, n, 46, 32, 5))};
}

std::vector<Mask2> vase() {
  const int n = 64;
  const Mask2 circleSquare = subtract(disc(n, n, 32, 32, 22), rectangle(n, n, 23, 23, 41, 41));
  const Mask2 squareCircle = subtract(rectangle(n, n, 12, 12, 52, 52), disc(n, n, 32, 32, 11));
  return {circleSquare, squareCircle, circleSquare};
}

void writeStack(const std::filesystem::path& dir, const std::vector<Mask2>& masks, bool asContours) {
  std::filesystem::create_directories(dir);
  for (std::size_t i = 0; i < masks.size(); ++i)
    writeSliceImage(dir / ("slice_" + std::to_string(i) + ".png"), asContours ? contourOf(masks[i]) : masks[i]);
}

Mask2 crossSection(const mesh::Mesh& mesh, double z, int w, int h) {
  struct Segment {
    double x0, y0, x1, y1;
  };
  std::vector<Segment> segments;
  for (const auto& t : mesh.triangles) {
    std::vector<std::pair<double, double>> cut;
    for (int e = 0; e < 3; ++e) {
      const auto& a = mesh.positions[t[e]];
      const auto& b = mesh.positions[t[(e + 1) % 3]];
      if ((a[2] <= z) == (b[2] <= z)) continue;
      const double s = (z - a[2]) / (double(b[2]) - a[2]);
      cut.emplace_back(a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]));
    }
    if (cut.size() == 2) segments.push_back({cut[0].first, cut[0].second, cut[1].first, cut[1].second});
  }
  Mask2 out = Mask2::empty(w, h);
  for (int y = 0; y < h; ++y) {
    std::vector<double> xs;
    for (const Segment& s : segments)
      if ((s.y0 <= y) != (s.y1 <= y)) xs.push_back(s.x0 + (y - s.y0) / (s.y1 - s.y0) * (s.x1 - s.x0));
    std::sort(xs.begin(), xs.end());
    for (int x = 0; x < w; ++x)
      out.set(x, y, (std::lower_bound(xs.begin(), xs.end(), double(x)) - xs.begin()) % 2 == 1);
  }
  return out;
}

double symmetricDifference(const Mask2& a, const Mask2& b) {
  std::int64_t diff = 0;
  for (std::size_t i = 0; i < a.inside.size(); ++i) diff += a.inside[i] != b.inside[i];
  return static_cast<double>(diff) / std::max<std::int64_t>(1, b.area());
}

}  // namespace isovdb::morph::test
