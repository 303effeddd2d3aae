// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file evolution.h
/// @brief Level-set metamorphosis of one slice into another on a 2-D pixel grid:
///        φ_t + (φ − φ_target)|∇φ| = 0 (paper 002 eq. 2.13), forward Euler with the
///        CFL time step of §3.3.4 and the convergence test of eq. 3.13 (§3.3.7).
///
/// The Hamiltonian is discretised with the Godunov upwind scheme of Osher and
/// Sethian (the scheme OpenVDB's LevelSetMorphing uses, first order) rather than
/// the paper's Roe-Fix (Alg. 3.1); both are monotone upwind schemes. Why this is
/// our own 2-D code and not tools::LevelSetMorphing: ARCHITECTURE.md, morph stage.
#pragma once

#include "isovdb/morph/plane.h"

namespace isovdb::morph {

struct EvolutionOptions {
  /// Eq. 3.13 stops the morph when |‖φⁿ − φ_t‖ − ‖φⁿ⁻¹ − φ_t‖| < tolerance, with
  /// ‖·‖ the Frobenius norm scaled to a 64 × 64 slice (× 64 / sqrt(pixels)), so the
  /// same tolerance fits every slice size. The paper's 0.25 (MATLAB, 64² to 256²
  /// slices) stops early; smaller is closer to the target and slower.
  double tolerance = 0.02;
  /// Safety stop (the statistics say when it was hit).
  int maxIterations = 5000;
  /// Δt = cfl / max over the grid of |F| (|φx| + |φy|) / |∇φ| (eq. 3.7); the paper uses 3/4.
  double cfl = 0.75;
};

/// @brief One morph, step by step (a stateful engine: the particle level set
///        corrects φ between steps, the replay reads every iterate).
/// Deterministic: the same inputs give the same iterates bit for bit.
class LevelSetMorph {
 public:
  /// @pre source and target have the same size (at least 2 × 2)
  LevelSetMorph(Field2 source, Field2 target, const EvolutionOptions& options);

  /// One forward Euler step; returns false once converged (eq. 3.13) or at maxIterations.
  bool step();

  const Field2& phi() const { return phi_; }
  /// For the particle level set: corrections between steps (call corrected() after).
  Field2& phi() { return phi_; }
  /// φ was changed from outside: the next eq. 3.13 test compares with the corrected φ.
  void corrected() { lastNorm_ = distanceToTarget(); }
  const Field2& target() const { return target_; }
  double timeStep() const { return dt_; }
  int iteration() const { return iteration_; }
  /// Eq. 3.13's value after the last step.
  double criterion() const { return criterion_; }
  bool hitMaxIterations() const { return iteration_ >= options_.maxIterations; }

 private:
  double distanceToTarget() const;

  Field2 phi_, target_, next_;
  EvolutionOptions options_;
  double dt_ = 0, lastNorm_ = 0, criterion_ = 0;
  int iteration_ = 0;
};

}  // namespace isovdb::morph
