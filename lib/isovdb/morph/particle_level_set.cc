// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/morph/particle_level_set.h"

#include <algorithm>
#include <cmath>

#include "isovdb/split_mix.h"

namespace isovdb::morph {

namespace {

bool inDomain(const Field2& f, double x, double y) { return x >= 0 && y >= 0 && x <= f.width - 1 && y <= f.height - 1; }

/// Unit normal ∇φ/|∇φ| by bilinear interpolation of central differences; (1/√2, 1/√2)
/// where the gradient vanishes (paper eq. 3.18).
Vec2 normalAt(const Field2& f, double x, double y) {
  const double h = 0.5;
  const double gx = (f.sample(x + h, y) - f.sample(x - h, y)) / (2 * h);
  const double gy = (f.sample(x, y + h) - f.sample(x, y - h)) / (2 * h);
  const double g = std::hypot(gx, gy);
  if (!(g > 1e-9)) return {M_SQRT1_2, M_SQRT1_2};
  return {gx / g, gy / g};
}

}  // namespace

ParticleLevelSet::ParticleLevelSet(const Field2& phi0, const ParticleOptions& options) : band_(options.band) {
  SplitMix64 random(options.seed);
  const double vMin = 0.1, vMax = 3.0, rMin = 0.1, rMax = 0.5;
  for (int y = 0; y + 1 < phi0.height; ++y)
    for (int x = 0; x + 1 < phi0.width; ++x) {
      const bool nearFront = std::abs(phi0.at(x, y)) < options.band || std::abs(phi0.at(x + 1, y)) < options.band ||
                             std::abs(phi0.at(x, y + 1)) < options.band ||
                             std::abs(phi0.at(x + 1, y + 1)) < options.band;
      if (!nearFront) continue;
      int positives = options.perCell / 2, negatives = options.perCell - positives;
      for (int k = 0; k < options.perCell; ++k) {
        Particle p;
        p.x = x + random.uniform();
        p.y = y + random.uniform();
        p.sign = random.uniform() < 0.5 ? -1.f : 1.f;
        if ((p.sign > 0 && positives <= 0) || (p.sign < 0 && negatives <= 0)) p.sign = -p.sign;
        (p.sign > 0 ? positives : negatives)--;
        // Attraction to a random level of the particle's sign (Alg. 3.2, eq. 3.16).
        const double goal = p.sign * (vMin + (vMax - vMin) * random.uniform());
        bool placed = false;
        for (int it = 0; it < options.attractionIterations && !placed; ++it) {
          const double value = phi0.sample(p.x, p.y);
          const Vec2 n = normalAt(phi0, p.x, p.y);
          const double step = goal - value;
          for (double lambda : {1.0, 0.5}) {
            const double nx = p.x + lambda * step * n.x, ny = p.y + lambda * step * n.y;
            if (!inDomain(phi0, nx, ny)) continue;
            const double v = p.sign * phi0.sample(nx, ny);
            if (v >= vMin && v <= vMax) {
              p.x = nx;
              p.y = ny;
              placed = true;
              break;
            }
          }
          if (!placed) {
            const double nx = p.x + 0.25 * step * n.x, ny = p.y + 0.25 * step * n.y;
            if (inDomain(phi0, nx, ny)) {
              p.x = nx;
              p.y = ny;
            }
          }
        }
        if (!placed) {
          ++discarded_;
          continue;
        }
        p.level = phi0.sample(p.x, p.y);
        p.radius = static_cast<float>(std::clamp(double(p.sign) * p.level, rMin, rMax));
        particles_.push_back(p);
      }
    }
}

void ParticleLevelSet::advect(const Field2& target, double dt) {
  // Exact solution of dp/dt = -(φ_target(p) - level) N_target over one step when the
  // path stays on one target normal: the remaining distance decays by e^{-Δt}.
  const double fraction = 1 - std::exp(-dt);
  for (Particle& p : particles_) {
    const double remaining = target.sample(p.x, p.y) - p.level;
    const Vec2 n = normalAt(target, p.x, p.y);
    p.x = std::clamp(p.x - fraction * remaining * n.x, 0.0, double(target.width - 1));
    p.y = std::clamp(p.y - fraction * remaining * n.y, 0.0, double(target.height - 1));
  }
}

std::int64_t ParticleLevelSet::correct(Field2& phi) const {
  Field2 plus = phi, minus = phi;
  std::int64_t escaped = 0;
  for (const Particle& p : particles_) {
    const double value = phi.sample(p.x, p.y);
    const bool wrongSide = p.sign > 0 ? value < 0 : value > 0;
    // Escaped by more than the radius; beyond the seeding band a particle no longer
    // describes the front near it (Enright et al. delete such particles).
    if (!wrongSide || std::abs(value) <= p.radius || std::abs(value) > band_) continue;
    ++escaped;
    const int x0 = std::min(static_cast<int>(p.x), phi.width - 2), y0 = std::min(static_cast<int>(p.y), phi.height - 2);
    for (int y = y0; y <= y0 + 1; ++y)
      for (int x = x0; x <= x0 + 1; ++x) {
        const double d = std::hypot(x - p.x, y - p.y);
        // Eq. 3.23: the local level set bends towards the side the corner is on.
        const float local = static_cast<float>(phi.at(x, y) <= 0 ? p.sign * p.radius - d : p.sign * p.radius + d);
        if (p.sign > 0)
          plus.at(x, y) = std::max(plus.at(x, y), local);
        else
          minus.at(x, y) = std::min(minus.at(x, y), local);
      }
  }
  if (escaped == 0) return 0;
  const Field2 before = phi;
  for (int y = 0; y < phi.height; ++y)
    for (int x = 0; x < phi.width; ++x) {
      const float a = plus.at(x, y), b = minus.at(x, y);
      const float merged = std::abs(a) <= std::abs(b) ? a : b;
      const bool inside = merged <= 0;
      // A correction moves the front; it does not nucleate a one-pixel island or
      // bubble: a sign flip needs a 4-neighbour already on the new side.
      if (inside != (before.at(x, y) <= 0)) {
        const bool joined = (x > 0 && (before.at(x - 1, y) <= 0) == inside) ||
                            (x + 1 < phi.width && (before.at(x + 1, y) <= 0) == inside) ||
                            (y > 0 && (before.at(x, y - 1) <= 0) == inside) ||
                            (y + 1 < phi.height && (before.at(x, y + 1) <= 0) == inside);
        if (!joined) continue;
      }
      phi.at(x, y) = merged;
    }
  return escaped;
}

}  // namespace isovdb::morph
