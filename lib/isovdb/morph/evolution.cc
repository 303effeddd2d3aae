// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/morph/evolution.h"

#include <algorithm>
#include <cmath>

#include "isovdb/errors.h"

namespace isovdb::morph {

namespace {

/// One-sided differences at (x, y), mirrored at the border (zero flux).
struct Differences {
  float xm, xp, ym, yp;  // D⁻x, D⁺x, D⁻y, D⁺y
};

float sq(float v) { return v * v; }

Differences differences(const Field2& f, int x, int y) {
  const float c = f.at(x, y);
  const float l = x > 0 ? f.at(x - 1, y) : 2 * c - f.at(x + 1, y);
  const float r = x < f.width - 1 ? f.at(x + 1, y) : 2 * c - f.at(x - 1, y);
  const float d = y > 0 ? f.at(x, y - 1) : 2 * c - f.at(x, y + 1);
  const float u = y < f.height - 1 ? f.at(x, y + 1) : 2 * c - f.at(x, y - 1);
  return {c - l, r - c, c - d, u - c};
}

}  // namespace

LevelSetMorph::LevelSetMorph(Field2 source, Field2 target, const EvolutionOptions& options)
    : phi_(std::move(source)), target_(std::move(target)), options_(options) {
  if (phi_.width != target_.width || phi_.height != target_.height || phi_.width < 2 || phi_.height < 2)
    throw InputError("level-set morph: source and target slices differ in size or are smaller than 2 x 2");
  next_ = phi_;
  // CFL (eq. 3.7), evaluated once on φ⁰ over the four one-sided combinations.
  double maxRate = 0;
  for (int y = 0; y < phi_.height; ++y)
    for (int x = 0; x < phi_.width; ++x) {
      const Differences d = differences(phi_, x, y);
      const double speed = std::abs(phi_.at(x, y) - target_.at(x, y));
      for (float gx : {d.xm, d.xp})
        for (float gy : {d.ym, d.yp}) {
          const double norm = std::hypot(gx, gy);
          if (norm > 0) maxRate = std::max(maxRate, speed * (std::abs(gx) + std::abs(gy)) / norm);
        }
    }
  dt_ = maxRate > 0 ? options_.cfl / maxRate : 0.0;
  lastNorm_ = distanceToTarget();
}

double LevelSetMorph::distanceToTarget() const {
  double sum = 0;
  for (std::size_t i = 0; i < phi_.size(); ++i) {
    const double d = phi_.values[i] - target_.values[i];
    sum += d * d;
  }
  return std::sqrt(sum) * 64.0 / std::sqrt(static_cast<double>(phi_.size()));
}

bool LevelSetMorph::step() {
  if (dt_ == 0 || iteration_ >= options_.maxIterations) return false;
  for (int y = 0; y < phi_.height; ++y)
    for (int x = 0; x < phi_.width; ++x) {
      const float phi = phi_.at(x, y);
      const float speed = phi - target_.at(x, y);
      const Differences d = differences(phi_, x, y);
      // Godunov: F > 0 moves the front outwards (along ∇φ).
      float grad2 = 0;
      if (speed > 0) {
        grad2 = sq(std::max(d.xm, 0.f)) + sq(std::min(d.xp, 0.f)) + sq(std::max(d.ym, 0.f)) + sq(std::min(d.yp, 0.f));
      } else {
        grad2 = sq(std::min(d.xm, 0.f)) + sq(std::max(d.xp, 0.f)) + sq(std::min(d.ym, 0.f)) + sq(std::max(d.yp, 0.f));
      }
      next_.at(x, y) = static_cast<float>(phi - dt_ * speed * std::sqrt(grad2));
    }
  std::swap(phi_, next_);
  ++iteration_;
  const double norm = distanceToTarget();
  criterion_ = std::abs(norm - lastNorm_);
  lastNorm_ = norm;
  return criterion_ >= options_.tolerance && iteration_ < options_.maxIterations;
}

}  // namespace isovdb::morph
