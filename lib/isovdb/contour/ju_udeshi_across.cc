// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
//
// Ju–Udeshi's envelope test of an edge's quad or triangle with every face crossed, the
// case of almost every minimal edge, answered in the plane across the edge (ju_udeshi.h,
// clearlyInsideEnvelope). The full test builds 2k sectors (four planes each) and clips
// each triangle by each sector: 40 % of regular contouring on a distance field. Here the
// same corners are found from 2D cross products, and only a clear answer is given;
// anything near a bound goes to the full test.
#include <algorithm>
#include <array>
#include <cmath>

#include "isovdb/contour/ju_udeshi.h"

namespace isovdb::contour {
namespace {

/// A point seen along the edge: (u, v) across it from the edge line, w along it from e0.
/// No member initialisers: the test runs once per quad and zeroing its rings of them cost
/// an eighth of its time.
struct Across {
  double u, v, w;
};

double cross(const Across& a, const Across& b) { return a.u * b.v - a.v * b.u; }

/// Relative floor below which a cross product or distance counts as degenerate.
constexpr double kDegenerate = 1e-6;
/// Points closer to the edge line than this fraction of the edge, and sectors whose
/// sine is below it, go to the full test: its planes through such points are nearly
/// degenerate, which it refuses by its own thresholds.
constexpr double kNearLine = 1e-3;

}  // namespace

bool clearlyInsideEnvelope(const EdgeEnvelope& envelope, int apex, const EnvelopeOptions& options) {
  const int k = envelope.cellCount;
  if (!((k == 4 && (apex == 0 || apex == 1)) || (k == 3 && apex == 0))) return false;
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
  // The ring c0 f0 c1 f1 ...: sector j is conv(e0, e1, ring[j], ring[j + 1]).
  const int n = 2 * k;
  // Twice around, so that ring[j] for j < 2n needs no remainder (a division per lookup).
  std::array<Across, 16> ring;
  for (int i = 0; i < k; ++i) {
    ring[static_cast<std::size_t>(2 * i)] = across(envelope.cellPoints[static_cast<std::size_t>(i)]);
    ring[static_cast<std::size_t>(2 * i + 1)] = across(envelope.facePoints[static_cast<std::size_t>(i)]);
  }
  std::copy_n(ring.begin(), n, ring.begin() + n);
  const auto at = [&](int j) -> const Across& { return ring[static_cast<std::size_t>(j)]; };
  const auto wrap = [n](int j) { return static_cast<std::size_t>(j >= n ? j - n : j); };
  // Every point clear of the edge line, and the face points on the half-planes around it
  // (one coordinate across exactly 0).
  for (int j = 0; j < n; ++j) {
    const Across& x = at(j);
    if (!(x.u * x.u + x.v * x.v >= kNearLine * kNearLine * s * s)) return false;
    if ((j & 1) && ((x.u == 0) == (x.v == 0))) return false;
  }
  // Per sector (P, Q): its outer planes (e0, P, Q) and (e1, P, Q) have normals
  // (P - e) x (Q - e) whose component along the edge is the cross product across it, so a
  // height gap g above the lower one or below the upper one lies at least g / tilt from
  // it, tilt = |P - e| |Q - e| / |cross| (the larger for e0 and e1). Every sector turns
  // the same way (less than half a turn).
  const double turn = cross(at(0), at(1)) > 0 ? 1.0 : -1.0;
  std::array<double, 8> sine;  // turn * cross(ring[j], ring[j + 1])
  for (int j = 0; j < n; ++j) {
    const Across &p = at(j), &q = at(j + 1);
    const double c = turn * cross(p, q);
    if (!(c > 0) || !(c * c >= kNearLine * kNearLine * (p.u * p.u + p.v * p.v) * (q.u * q.u + q.v * q.v))) return false;
    sine[static_cast<std::size_t>(j)] = c;
  }
  // The rays turn around the edge once: from face ray to face ray (half-axes, through the
  // cell point between them) a quarter, a half or three quarters of a turn, four in all.
  int quarters = 0;
  for (int i = 0; i < k; ++i) {
    const Across &f = at(2 * i + 1), &g = at(2 * i + 3);
    const double c = turn * cross(f, g), d = f.u * g.u + f.v * g.v;
    quarters += c > 0 ? 1 : c < 0 ? 3 : d < 0 ? 2 : 4;
  }
  if (quarters != 4) return false;
  // The checks with given tilts (a bound of each sector's 1 / |n_w|).
  const auto clearWith = [&](const std::array<double, 8>& sectorTilts, double largestTilt) {
    const double slack = 1e-9 * s;
    const auto clearBetween = [&](double height, double lower, double upper, double sectorTilt) {
      const double need = 2.0 * options.margin * sectorTilt + slack;
      return height - lower >= need && upper - height >= need;
    };
    // The height over O of the triangle (X, Y, Z) whose shadow holds O: inside every
    // sector's [0, s].
    const auto clearOverO = [&](const Across& X, const Across& Y, const Across& Z) {
      const double area = cross(Across{Y.u - X.u, Y.v - X.v, 0}, Across{Z.u - X.u, Z.v - X.v, 0});
      if (area == 0) return false;
      const double lx = cross(Y, Z) / area, ly = cross(Z, X) / area, lz = cross(X, Y) / area;
      if (!(lx > kDegenerate && ly > kDegenerate && lz > kDegenerate)) return false;
      return clearBetween(lx * X.w + ly * Y.w + lz * Z.w, 0.0, s, largestTilt);
    };
    // Three cells: one triangle through the three face points, over O.
    if (k == 3) return clearOverO(at(0), at(2), at(4));

    // Four: the diagonal from A = c_apex to C = c_apex+2; B = c_apex+1 and D = c_apex+3 on
    // either side.
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
      const double sectorTilt = std::max(sectorTilts[wrap(r - 1)], sectorTilts[wrap(r)]);
      if (!clearBetween(height, lower, lower + (1.0 - beta) * s, sectorTilt)) return false;
    }
    return oUnderABC ? clearOverO(A, B, C) : clearOverO(A, C, D);
  };
  std::array<double, 8> tilt;
  double maxTilt = 0;
  // First with every |P - e| |Q - e| bounded by R^2, R^2 the largest distance across plus
  // the largest height (no square roots): larger tilts ask more, so what is clear with them
  // is clear with the points' own distances below, the answer the same. Nearly every
  // quad is clear at once.
  double across2 = 0, height2 = 0;
  for (int j = 0; j < n; ++j) {
    const Across& x = at(j);
    across2 = std::max(across2, x.u * x.u + x.v * x.v);
    height2 = std::max(height2, std::max(x.w * x.w, (s - x.w) * (s - x.w)));
  }
  const double bound = (across2 + height2) * (1.0 + 1e-12);  // above the products' rounding too
  bool bounded = true;
  for (int j = 0; j < n && bounded; ++j) {
    const double c = sine[static_cast<std::size_t>(j)];
    bounded = c >= kDegenerate * bound;
    tilt[static_cast<std::size_t>(j)] = bound / c;
    maxTilt = std::max(maxTilt, bound / c);
  }
  if (bounded && clearWith(tilt, maxTilt)) return true;
  // With the points' own distances, max(|X - e0|, |X - e1|).
  std::array<double, 16> reach;
  for (int j = 0; j < n; ++j) {
    const Across& x = at(j);
    reach[static_cast<std::size_t>(j)] = std::sqrt(x.u * x.u + x.v * x.v + std::max(x.w * x.w, (s - x.w) * (s - x.w)));
  }
  std::copy_n(reach.begin(), n, reach.begin() + n);
  maxTilt = 0;
  for (int j = 0; j < n; ++j) {
    const double c = sine[static_cast<std::size_t>(j)];
    const double product = reach[static_cast<std::size_t>(j)] * reach[static_cast<std::size_t>(j + 1)];
    if (!(c >= kDegenerate * product)) return false;
    tilt[static_cast<std::size_t>(j)] = product / c;
    maxTilt = std::max(maxTilt, product / c);
  }
  if (clearWith(tilt, maxTilt)) return true;
  // |P - e| |Q - e| overstates the normal where the two points lie near e's height (an
  // edge end the surface passes close to): again with the normals themselves.
  maxTilt = 0;
  for (int j = 0; j < n; ++j) {
    const Across &p = at(j), &q = at(j + 1);
    const double c = turn * cross(p, q);
    const auto normal2 = [&](double w) {
      const double pw = p.w - w, qw = q.w - w;
      const double x = p.v * qw - pw * q.v, y = pw * q.u - p.u * qw;
      return x * x + y * y + c * c;
    };
    tilt[static_cast<std::size_t>(j)] = std::sqrt(std::max(normal2(0.0), normal2(s))) / c;
    maxTilt = std::max(maxTilt, tilt[static_cast<std::size_t>(j)]);
  }
  return clearWith(tilt, maxTilt);
}

}  // namespace isovdb::contour
