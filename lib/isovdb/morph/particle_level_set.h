// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file particle_level_set.h
/// @brief Particle level set correction of a 2-D morph (Enright et al.; paper 002
///        §3.3.13, Alg. 3.2 and 3.3): marker particles on both sides of the front
///        restore the detail (corners) the Eulerian scheme smooths away.
///
/// Our own code. Random numbers come from a seeded splitmix64 generator and the
/// particles are processed in order, so a run is reproducible bit for bit.
/// Following the paper, particles are neither re-seeded nor re-sized during the morph.
#pragma once

#include <cstdint>
#include <vector>

#include "isovdb/morph/plane.h"

namespace isovdb::morph {

struct ParticleOptions {
  int perCell = 16;               ///< particles seeded per cell near the front (half positive, half negative)
  double band = 3.0;              ///< seed in cells with a corner |φ| < band (pixels)
  int attractionIterations = 10;  ///< Alg. 3.2: tries before a particle is discarded
  std::uint64_t seed = 1;         ///< random seed (each pair derives its own from it)
};

struct Particle {
  double x = 0, y = 0;
  float sign = 1;    ///< s_p: +1 outside, -1 inside
  float level = 0;   ///< φ⁰ at the seeded position (pixels): the level set the particle stays on
  float radius = 0;  ///< r_p in [0.1, 0.5] pixels
};

class ParticleLevelSet {
 public:
  /// Alg. 3.2: seeds particles in the band of φ⁰, attracts each to a random level
  /// of its sign in [0.1, 3] pixels, discards those that fail, sets the radii.
  ParticleLevelSet(const Field2& phi0, const ParticleOptions& options);

  /// Moves every particle towards the point of the target's level set `level` closest
  /// to it: p ← p − (1 − e^{−Δt}) (φ_target(p) − level) N_target(p). Departs from
  /// eq. 3.21 (F N with N from φⁿ⁻¹): where the front is not resolved (a corner),
  /// φ's normal is the scheme's rounded one and particles following it round the
  /// corner with the front, so they cannot restore it. The target's normal is exact,
  /// and on a front parallel to the target both move it alike (normal speed = the
  /// remaining distance, decaying as e^{−t}, the model of Progress::Exponential).
  void advect(const Field2& target, double dt);

  /// Alg. 3.3: escaped particles (wrong side by more than their radius) rebuild
  /// φ⁺ (positive) and φ⁻ (negative) at their cell's corners by eq. 3.23; φ takes
  /// the smaller magnitude of the two. Particles farther than the seeding band from
  /// the front (|φ(p)| > band) are ignored, as Enright et al. delete them. Returns the
  /// number of escaped particles used. A correction may move the front but not flip
  /// an isolated pixel (no one-pixel islands or bubbles).
  std::int64_t correct(Field2& phi) const;

  const std::vector<Particle>& particles() const { return particles_; }
  std::int64_t discarded() const { return discarded_; }

 private:
  std::vector<Particle> particles_;
  std::int64_t discarded_ = 0;
  double band_ = 3.0;
};

}  // namespace isovdb::morph
