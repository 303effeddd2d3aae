// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
//
// Ju–Udeshi's envelope test of a quad with every face crossed, the case of almost every
// minimal edge, answered in the plane across the edge (ju_udeshi.h,
// quadClearlyInsideEnvelope). The full test builds eight sectors (four planes each) and
// clips each triangle by each sector: 40 % of regular contouring on a distance field.
// Here the same corners are found from 2D cross products, and only a clear answer is
// given; anything near a bound goes to the full test.
#include <array>
#include <cmath>

#include "isovdb/contour/ju_udeshi.h"

namespace isovdb::contour {
namespace {

/// A point seen along the edge: (u, v) across it from the edge line, w along it from e0.
struct Across {
  double u = 0, v = 0, w = 0;
};

double cross(const Across& a, const Across& b) { return a.u * b.v - a.v * b.u; }

/// Relative floor below which a cross product or distance counts as degenerate.
constexpr double kDegenerate = 1e-6;

}  // namespace

bool quadClearlyInsideEnvelope(const EdgeEnvelope& envelope, int apex, const EnvelopeOptions& options) {
  if (envelope.cellCount != 4 || (apex != 0 && apex != 1)) return false;
  int axis = -1;
  for (int a = 0; a < 3; ++a) {
    if (envelope.edgeEnd[a] == envelope.edgeStart[a]) continue;
    if (axis >= 0) return false;
    axis = a;
  }
  if (axis < 0) return false;
  const double s = envelope.edgeEnd[axis] - envelope.edgeStart[axis];
  if (!(s > 0)) return false;
  const int ua = (axis + 1) % 3, va = (axis + 2) % 3;
  const auto across = [&](const Vec3d& p) {
    return Across{p[ua] - envelope.edgeStart[ua], p[va] - envelope.edgeStart[va], p[axis] - envelope.edgeStart[axis]};
  };
  // The ring c0 f0 c1 f1 c2 f2 c3 f3: sector j is conv(e0, e1, ring[j], ring[j + 1]).
  std::array<Across, 8> ring;
  for (int i = 0; i < 4; ++i) {
    ring[static_cast<std::size_t>(2 * i)] = across(envelope.cellPoints[static_cast<std::size_t>(i)]);
    ring[static_cast<std::size_t>(2 * i + 1)] = across(envelope.facePoints[static_cast<std::size_t>(i)]);
  }
  const auto at = [&](int j) -> const Across& { return ring[static_cast<std::size_t>(j & 7)]; };
  // Every point clear of the edge line, and the face points on the four half-planes
  // around it (one coordinate across exactly 0), so that the rays turn around O once.
  std::array<double, 8> reach{};  // max(|X - e0|, |X - e1|)
  for (int j = 0; j < 8; ++j) {
    const Across& x = at(j);
    const double r2 = x.u * x.u + x.v * x.v;
    if (!(r2 >= kDegenerate * kDegenerate * s * s)) return false;
    reach[static_cast<std::size_t>(j)] = std::sqrt(r2 + std::max(x.w * x.w, (s - x.w) * (s - x.w)));
    if ((j & 1) && ((x.u == 0) == (x.v == 0))) return false;
  }
  const double turn = cross(at(0), at(1)) > 0 ? 1.0 : -1.0;
  for (int i = 0; i < 4; ++i)
    if (!(turn * cross(at(2 * i + 1), at(2 * i + 3)) > 0)) return false;
  // Per sector: the outer planes (e0, P, Q) and (e1, P, Q) have |n_w| >= 1 / tilt, so a
  // height gap g above the lower one or below the upper one is >= g / tilt away from it.
  std::array<double, 8> tilt{};
  double maxTilt = 0;
  for (int j = 0; j < 8; ++j) {
    const double c = turn * cross(at(j), at(j + 1));
    const double product = reach[static_cast<std::size_t>(j)] * reach[static_cast<std::size_t>((j + 1) & 7)];
    if (!(c >= kDegenerate * product)) return false;
    tilt[static_cast<std::size_t>(j)] = product / c;
    maxTilt = std::max(maxTilt, product / c);
  }
  const double slack = 1e-9 * s;
  const auto clearBetween = [&](double height, double lower, double upper, double sectorTilt) {
    const double need = 2.0 * options.margin * sectorTilt + slack;
    return height - lower >= need && upper - height >= need;
  };

  // The diagonal from A = c_apex to C = c_apex+2; B = c_apex+1 and D = c_apex+3 on either side.
  const int a = 2 * apex;
  const Across &A = at(a), &B = at(a + 2), &C = at(a + 4), &D = at(a + 6);
  const Across d{C.u - A.u, C.v - A.v, C.w - A.w};
  const double sideO = cross(d, Across{-A.u, -A.v, 0});
  const double sideB = cross(d, Across{B.u - A.u, B.v - A.v, 0});
  const double length = std::sqrt(d.u * d.u + d.v * d.v);
  if (!(std::abs(sideO) > kDegenerate * length * s) || sideB == 0) return false;
  // O on B's side: triangle (A, B, C) covers O and the diagonal crosses the rays on D's
  // side; otherwise the reverse.
  const bool oUnderABC = (sideO > 0) == (sideB > 0);
  const int firstRay = oUnderABC ? a + 5 : a + 1;  // f, c, f between the diagonal's ends
  for (int r = firstRay; r < firstRay + 3; ++r) {
    const Across& R = at(r);
    const double denominator = cross(R, d);
    if (denominator == 0) return false;
    const double beta = cross(A, d) / denominator;
    const double t = cross(A, R) / denominator;
    if (!(t > 0 && t < 1 && beta > 0 && beta < 1)) return false;
    const double height = A.w + t * d.w;
    const double lower = beta * R.w;
    const double sectorTilt =
        std::max(tilt[static_cast<std::size_t>((r - 1) & 7)], tilt[static_cast<std::size_t>(r & 7)]);
    if (!clearBetween(height, lower, lower + (1.0 - beta) * s, sectorTilt)) return false;
  }
  // The triangle over O: its height there, inside every sector's [0, s].
  const Across& X = A;
  const Across& Y = oUnderABC ? B : C;
  const Across& Z = oUnderABC ? C : D;
  const double area = cross(Across{Y.u - X.u, Y.v - X.v, 0}, Across{Z.u - X.u, Z.v - X.v, 0});
  if (area == 0) return false;
  const double lx = cross(Y, Z) / area, ly = cross(Z, X) / area, lz = cross(X, Y) / area;
  if (!(lx > kDegenerate && ly > kDegenerate && lz > kDegenerate)) return false;
  return clearBetween(lx * X.w + ly * Y.w + lz * Z.w, 0.0, s, maxTilt);
}

}  // namespace isovdb::contour
