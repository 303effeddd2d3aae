// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/reservoir/pn_triangle.h"

#include <Eigen/Geometry>

namespace isovdb::reservoir {
namespace {

// Reflected average normal of an edge (paper 003 Fig. 4.4).
Vec3d edgeNormal(const Vec3d& pi, const Vec3d& pj, const Vec3d& ni, const Vec3d& nj) {
  const Vec3d d = pj - pi;
  const double dd = d.dot(d);
  const double v = dd > 0 ? 2 * d.dot(ni + nj) / dd : 0.0;
  Vec3d n = ni + nj - v * d;
  const double length = n.norm();
  return length > 0 ? Vec3d(n / length) : ni;
}

}  // namespace

PnTriangle::PnTriangle(const std::array<Vec3d, 3>& p, const std::array<Vec3d, 3>& n,
                       const std::array<bool, 3>& straight) {
  auto w = [&](int i, int j) { return (p[j] - p[i]).dot(n[i]); };
  // The control point of edge (i, j) a third of the way from i; `edge` numbers it (c: c, c+1).
  auto third = [&](int i, int j, int edge) {
    const double lift = straight[static_cast<std::size_t>(edge)] ? 0.0 : w(i, j);
    return Vec3d((2 * p[i] + p[j] - lift * n[i]) / 3.0);
  };
  b_[0] = p[0];
  b_[1] = p[1];
  b_[2] = p[2];
  b_[3] = third(0, 1, 0);  // b210
  b_[4] = third(1, 0, 0);  // b120
  b_[5] = third(1, 2, 1);  // b021
  b_[6] = third(2, 1, 1);  // b012
  b_[7] = third(2, 0, 2);  // b102
  b_[8] = third(0, 2, 2);  // b201
  const Vec3d e = (b_[3] + b_[4] + b_[5] + b_[6] + b_[7] + b_[8]) / 6.0;
  const Vec3d centre = (p[0] + p[1] + p[2]) / 3.0;
  b_[9] = e + (e - centre) / 2.0;
  n_[0] = n[0];
  n_[1] = n[1];
  n_[2] = n[2];
  n_[3] = edgeNormal(p[0], p[1], n[0], n[1]);
  n_[4] = edgeNormal(p[1], p[2], n[1], n[2]);
  n_[5] = edgeNormal(p[2], p[0], n[2], n[0]);
}

Vec3d PnTriangle::position(double u, double v, double w) const {
  return b_[0] * u * u * u + b_[1] * v * v * v + b_[2] * w * w * w + 3 * b_[3] * u * u * v + 3 * b_[4] * u * v * v +
         3 * b_[5] * v * v * w + 3 * b_[6] * v * w * w + 3 * b_[7] * u * w * w + 3 * b_[8] * u * u * w +
         6 * b_[9] * u * v * w;
}

Vec3d PnTriangle::quadraticNormal(double u, double v, double w) const {
  const Vec3d n =
      n_[0] * u * u + n_[1] * v * v + n_[2] * w * w + 2 * n_[3] * u * v + 2 * n_[4] * v * w + 2 * n_[5] * w * u;
  const double length = n.norm();
  return length > 0 ? Vec3d(n / length) : n_[0];
}

Vec3d envelopeNormal(const PnTriangle& patch, const PnTriangle& inflated, double u, double v, double w) {
  const Vec3d d = inflated.position(u, v, w) - patch.position(u, v, w);
  const double length = d.norm();
  return length > 1e-12 ? Vec3d(d / length) : patch.quadraticNormal(u, v, w);
}

}  // namespace isovdb::reservoir
