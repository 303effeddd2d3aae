// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/morph/centring.h"

#include <algorithm>
#include <vector>

namespace isovdb::morph {

namespace {

struct Point {
  long long x, y;  // doubled coordinates: pixel corners at odd values
  bool operator<(const Point& o) const { return x != o.x ? x < o.x : y < o.y; }
};

long long cross(const Point& o, const Point& a, const Point& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

}  // namespace

std::optional<Vec2> hullCentroid(const Mask2& mask) {
  // Only the leftmost and rightmost inside pixel of each row can be hull corners.
  std::vector<Point> points;
  for (int y = 0; y < mask.height; ++y) {
    int lo = -1, hi = -1;
    for (int x = 0; x < mask.width; ++x)
      if (mask.at(x, y)) {
        if (lo < 0) lo = x;
        hi = x;
      }
    if (lo < 0) continue;
    for (int x : {lo, hi})
      for (int dy : {-1, 1})
        for (int dx : {-1, 1}) points.push_back({2LL * x + dx, 2LL * y + dy});
  }
  if (points.empty()) return std::nullopt;
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end(),
                           [](const Point& a, const Point& b) { return a.x == b.x && a.y == b.y; }),
               points.end());
  // Andrew's monotone chain.
  std::vector<Point> hull(2 * points.size());
  std::size_t k = 0;
  for (const Point& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  double area2 = 0, cx = 0, cy = 0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Point& a = hull[i];
    const Point& b = hull[(i + 1) % hull.size()];
    const double c = static_cast<double>(a.x * b.y - b.x * a.y);
    area2 += c;
    cx += (a.x + b.x) * c;
    cy += (a.y + b.y) * c;
  }
  // Halve the doubled coordinates.
  return Vec2{cx / (3.0 * area2) / 2.0, cy / (3.0 * area2) / 2.0};
}

Field2 resample(const Field2& field, int width, int height, Vec2 offset) {
  Field2 out = Field2::filled(width, height, 0.f);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) out.at(x, y) = field.sample(x + offset.x, y + offset.y);
  return out;
}

}  // namespace isovdb::morph
