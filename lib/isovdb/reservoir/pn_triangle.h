// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file pn_triangle.h
/// @brief Curved PN triangles (Vlachos et al., paper 003 §4.2–4.4): cubic
/// Bézier geometry from the three vertices and normals, the corrected
/// quadratic normal patch (with the 2!/(i!j!k!) factors), and the "envelope"
/// normal: the normalised difference between an inflated patch (vertices
/// moved along their normals by `inflation`) and the patch itself.
///
/// A patch's boundary curve depends only on that edge's two vertices and
/// normals (and whether it is straight), so adjacent patches meet without cracks.
#pragma once

#include <array>

#include "isovdb/reservoir/corner_point_grid.h"

namespace isovdb::reservoir {

class PnTriangle {
 public:
  /// Corner positions and unit normals; (u, v, w) weigh corners 0, 1, 2. A straight edge
  /// (edge c: corners c, c + 1) keeps its chord: its control points are the chord's thirds,
  /// the same in both triangles of the edge; with all three straight the patch is flat.
  PnTriangle(const std::array<Vec3d, 3>& p, const std::array<Vec3d, 3>& n,
             const std::array<bool, 3>& straight = {false, false, false});

  Vec3d position(double u, double v, double w) const;
  /// Quadratic normal patch (paper 003 eq. with the Bernstein factors restored).
  Vec3d quadraticNormal(double u, double v, double w) const;

 private:
  std::array<Vec3d, 10> b_;  // b300 b030 b003 b210 b120 b021 b012 b102 b201 b111
  std::array<Vec3d, 6> n_;   // n200 n020 n002 n110 n011 n101
};

/// Envelope normal at (u, v, w): normalise(inflated.position - patch.position),
/// the quadratic normal where the difference vanishes.
Vec3d envelopeNormal(const PnTriangle& patch, const PnTriangle& inflated, double u, double v, double w);

}  // namespace isovdb::reservoir
