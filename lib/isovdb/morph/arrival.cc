// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/morph/arrival.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace isovdb::morph {

ArrivalRecorder::ArrivalRecorder(const Field2& initial) : times_(Field2::filled(initial.width, initial.height, -1.f)) {}

void ArrivalRecorder::record(const Field2& previous, const Field2& current, int iteration) {
  for (std::size_t i = 0; i < current.size(); ++i) {
    const float a = previous.values[i], b = current.values[i];
    if ((a <= 0.f) != (b <= 0.f)) times_.values[i] = static_cast<float>(iteration - 1 + a / (a - b));
  }
}

Field2 arrivalScale(const Field2& times, const Field2& target, int iterations) {
  const int w = times.width, h = times.height;
  Field2 scale = Field2::filled(w, h, -1.f);
  std::deque<int> queue;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float t = times.at(x, y);
      if (t < 0) continue;
      // Closest point on the target contour: x - φ_t ∇φ_t (central differences).
      const int xl = std::max(x - 1, 0), xr = std::min(x + 1, w - 1);
      const int yd = std::max(y - 1, 0), yu = std::min(y + 1, h - 1);
      double gx = (target.at(xr, y) - target.at(xl, y)) / std::max(1, xr - xl);
      double gy = (target.at(x, yu) - target.at(x, yd)) / std::max(1, yu - yd);
      const double g = std::hypot(gx, gy);
      float end = -1.f;
      if (g > 0) {
        gx /= g;
        gy /= g;
        const double d = target.at(x, y);
        const int px = static_cast<int>(std::lround(x - d * gx)), py = static_cast<int>(std::lround(y - d * gy));
        for (int j = py - 1; j <= py + 1; ++j)
          for (int i = px - 1; i <= px + 1; ++i)
            if (i >= 0 && j >= 0 && i < w && j < h) end = std::max(end, times.at(i, j));
      }
      scale.at(x, y) = end < 0 ? static_cast<float>(iterations) : std::max(end, t);
      queue.push_back(y * w + x);
    }
  if (queue.empty()) return Field2::filled(w, h, static_cast<float>(iterations));
  while (!queue.empty()) {
    const int p = queue.front();
    queue.pop_front();
    const int x = p % w, y = p / w;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= w || ny >= h || scale.at(nx, ny) >= 0) continue;
        scale.at(nx, ny) = scale.at(x, y);
        queue.push_back(ny * w + nx);
      }
  }
  for (int pass = 0; pass < 2; ++pass) {
    Field2 smooth = scale;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (times.at(x, y) >= 0) continue;  // swept pixels keep their own scale
        double sum = 0;
        int n = 0;
        for (int j = std::max(y - 1, 0); j <= std::min(y + 1, h - 1); ++j)
          for (int i = std::max(x - 1, 0); i <= std::min(x + 1, w - 1); ++i) {
            sum += scale.at(i, j);
            ++n;
          }
        smooth.at(x, y) = static_cast<float>(sum / n);
      }
    scale = std::move(smooth);
  }
  return scale;
}

}  // namespace isovdb::morph
