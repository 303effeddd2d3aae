// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file pair_morph.h
/// @brief The intermediate slices between two consecutive slices (paper 002 §3.3):
///        centre both on their convex-hull centroids (when that registers them),
///        morph the source into the target, pick the iterates at the requested
///        fractions, set each one's area (area_match.h), de-centre them along the
///        line between the centroids.
#pragma once

#include <cstdint>
#include <vector>

#include "isovdb/morph/evolution.h"
#include "isovdb/morph/particle_level_set.h"
#include "isovdb/morph/plane.h"

namespace isovdb::morph {

/// How the slices between two originals are made.
enum class Interpolation {
  LevelSet,  ///< level-set metamorphosis (paper 002), optionally with particles
  Nearest,   ///< copy of the nearer original (plain stacking)
  Linear,    ///< (1 - s) φ_a + s φ_b without centring (shape-based interpolation)
};

/// Which iterate the slice at fraction s shows (uniform progress: paper 002's
/// conclusion, after Nilsson et al.'s time-of-arrival reparametrisation).
enum class Progress {
  Iterations,  ///< iterate s · (K + 1) of K, as the paper's evenly spaced heights: bunches near the target
  Arrival,     ///< per pixel: measured arrival time over the arrival time at the target (arrival.h)
  /// Arrival time modelled: with F = φ − φ_target and |∇φ| = 1 every point's distance to
  /// the target decays as e^{-t}, so every point is at fraction (1 - e^{-t}) / (1 - e^{-T})
  /// of its path at time t, T = K Δt; slice s shows time t(s) = -ln(1 - s (1 - e^{-T})).
  /// The most uniform on every test shape (ARCHITECTURE.md), the default.
  Exponential,
};

struct PairOptions {
  Interpolation interpolation = Interpolation::LevelSet;
  Progress progress = Progress::Exponential;
  bool particles = false;  ///< particle level set correction (LevelSet only)
  /// Centre both contours on their convex-hull centroids (paper 002 §3.3.2) when that
  /// translation makes the two slices overlap more than where they lie; false never
  /// centres. (Where a component appears or vanishes the hull centroid jumps and
  /// centring would drag the components that stay.)
  bool centre = true;
  /// Give each slice at fraction s the area (1 - s) A_a + s A_b by one offset of its φ
  /// (area_match.h): the morph shrinks sections that move sideways or grow from a cap.
  bool matchArea = true;
  EvolutionOptions evolution;
  ParticleOptions particleOptions;
  int margin = 4;  ///< pixels around the centred contours in the working grid
};

/// What one pair cost and did.
struct PairStats {
  int iterations = 0;  ///< K, steps to convergence (0 without a morph)
  bool hitMaxIterations = false;
  double timeStep = 0;        ///< Δt (CFL)
  double finalCriterion = 0;  ///< eq. 3.13 at the last step
  int workWidth = 0, workHeight = 0;
  bool centred = false;  ///< the contours were centred (PairOptions::centre and it helped)
  std::int64_t particles = 0, discardedParticles = 0, escapedParticles = 0;  ///< PLS; escaped summed over steps
  /// Mean over the slices of |p - s|, p the fraction of the swept area (A Δ B,
  /// centred) the slice covers at fraction s: 0 is perfectly uniform progress.
  double progressError = 0;
  double seconds = 0;
};

struct PairResult {
  std::vector<Field2> slices;  ///< one per fraction, canvas-sized signed distances (pixels)
  PairStats stats;
};

/// @brief Slices at `fractions` (in (0, 1), 0 = `a`, 1 = `b`) between two slices.
/// @param[in] a, b        the two slices' insides (same canvas)
/// @param[in] sdfA, sdfB  their signed distances (slice_sdf.h)
/// Deterministic: no shared state, random numbers seeded from options.
PairResult morphPair(const Mask2& a, const Mask2& b, const Field2& sdfA, const Field2& sdfB,
                     const std::vector<double>& fractions, const PairOptions& options);

}  // namespace isovdb::morph
