// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/contour/ju_udeshi.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "isovdb/cell/cell_geometry.h"
#include "isovdb/contour/quad_diagonal.h"

namespace isovdb::contour {
namespace {

/// The envelope test computes on Eigen vectors; the API exchanges plain arrays (vec3.h).
using Point = Eigen::Vector3d;
Point toPoint(const Vec3d& a) { return {a[0], a[1], a[2]}; }
Vec3d toVec3d(const Point& a) { return {a(0), a(1), a(2)}; }

/// Oriented plane n . x + d with |n| = 1.
struct Plane {
  Point n = Point::Zero();
  double d = 0.0;
  double eval(const Point& x) const { return n.dot(x) + d; }
};

/// The plane through p0, p1, p2 before it is oriented, with the scale its tests use.
struct PlaneThrough {
  Plane plane;
  double scale = 0.0;      ///< the longer of p0p1 and p0p2
  bool degenerate = true;  ///< the three points are (nearly) collinear
};

PlaneThrough planeThrough(const Point& p0, const Point& p1, const Point& p2) {
  PlaneThrough out;
  Point n = (p1 - p0).cross(p2 - p0);
  const double len = n.norm();
  // sqrt is monotonic and correctly rounded: the larger norm is the root of the larger square.
  out.scale = std::max(std::sqrt(std::max((p0 - p1).squaredNorm(), (p0 - p2).squaredNorm())), 1e-30);
  if (len <= 1e-14 * out.scale * out.scale) return out;
  n *= 1.0 / len;
  out.plane = Plane{n, -n.dot(p0)};
  out.degenerate = false;
  return out;
}

/// `through` oriented so that `reference` is on the positive side.
/// @return false if degenerate or `reference` lies (nearly) on it.
bool orientTowards(const PlaneThrough& through, const Point& reference, Plane& out) {
  if (through.degenerate) return false;
  out = through.plane;
  const double s = out.eval(reference);
  if (std::abs(s) <= 1e-12 * through.scale) return false;
  if (s < 0) out = Plane{-out.n, -out.d};
  return true;
}

/// Plane through p0, p1, p2 oriented so that `reference` is on the positive side.
/// @return false if degenerate or `reference` lies (nearly) on it.
bool orientedPlane(const Point& p0, const Point& p1, const Point& p2, const Point& reference, Plane& out) {
  return orientTowards(planeThrough(p0, p1, p2), reference, out);
}

/// A convex polygon of at most 8 vertices: a triangle clipped by two planes has at most 5.
struct SmallPolygon {
  std::array<Point, 8> points;
  std::size_t size = 0;
};

/// Keeps the part of a convex polygon where plane >= 0 (Sutherland–Hodgman).
[[gnu::always_inline]] inline void clip(const SmallPolygon& in, const Plane& plane, SmallPolygon& out) {
  out.size = 0;
  const std::size_t n = in.size;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& p = in.points[i];
    const Point& q = in.points[(i + 1) % n];
    const double sp = plane.eval(p), sq = plane.eval(q);
    if (sp >= 0) out.points[out.size++] = p;
    if ((sp >= 0) != (sq >= 0)) {
      const double t = sp / (sp - sq);
      out.points[out.size++] = p + (q - p) * t;
    }
  }
}

/// Whether x lies within `reach` of the segment [p, q]. A clipped polygon's corners are
/// mostly the segment's own ends (the cell and face points), found without a division or a
/// root; the rest compare squared lengths.
bool nearSegment(const Point& x, const Point& p, const Point& q, double reach) {
  if (x == p || x == q) return true;
  const Point d = q - p;
  const double len2 = d.squaredNorm();
  double t = len2 > 0 ? (x - p).dot(d) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return (x - (p + d * t)).squaredNorm() <= reach * reach;
}

/// One tetrahedron conv(e0, e1, P, Q) of an envelope: the planes of its
/// angular sector around the edge line and of its two outer faces.
struct Sector {
  Point P = Point::Zero(), Q = Point::Zero();
  Plane sectorP, sectorQ, outer0, outer1;
  bool valid = false;  ///< false if degenerate: no triangle is inside it
};

/// The sector of (e0, e1, P, Q) from the planes through the edge line and P and Q.
Sector makeSector(const Point& e0, const Point& e1, const Point& P, const Point& Q, const PlaneThrough& edgeP,
                  const PlaneThrough& edgeQ) {
  Sector sector;
  sector.P = P;
  sector.Q = Q;
  // Sector: the side of plane (e, P) containing Q and the side of plane (e, Q) containing P.
  // Outer faces shared with neighbouring edges' tetrahedra: (e0, P, Q) and (e1, P, Q).
  sector.valid = orientTowards(edgeP, Q, sector.sectorP) && orientTowards(edgeQ, P, sector.sectorQ) &&
                 orientedPlane(e0, P, Q, e1, sector.outer0) && orientedPlane(e1, P, Q, e0, sector.outer1);
  return sector;
}

/// The 2k tetrahedra of an envelope (cell point before and after each face point),
/// built once per edge and shared by every candidate triangle.
struct EnvelopeSectors {
  std::array<Sector, 8> sectors;
  int count = 0;
  double touch = 0.0;  ///< contact tolerance on the segments v_c v_f

  explicit EnvelopeSectors(const EdgeEnvelope& envelope) {
    const int k = envelope.cellCount;
    const Point e0 = toPoint(envelope.edgeStart), e1 = toPoint(envelope.edgeEnd);
    // Each plane through the edge line serves two sectors: a cell point's between the face
    // points on either side of it, a face point's between the cell points on either side.
    std::array<Point, 4> cells, faces;
    std::array<PlaneThrough, 4> cellPlanes, facePlanes;
    for (int i = 0; i < k; ++i) {
      const auto u = static_cast<std::size_t>(i);
      cells[u] = toPoint(envelope.cellPoints[u]);
      faces[u] = toPoint(envelope.facePoints[u]);
      cellPlanes[u] = planeThrough(e0, e1, cells[u]);
      facePlanes[u] = planeThrough(e0, e1, faces[u]);
    }
    for (int i = 0; i < k; ++i) {
      const auto before = static_cast<std::size_t>(i), after = static_cast<std::size_t>((i + 1) % k);
      sectors[static_cast<std::size_t>(count++)] =
          makeSector(e0, e1, cells[before], faces[before], cellPlanes[before], facePlanes[before]);
      sectors[static_cast<std::size_t>(count++)] =
          makeSector(e0, e1, cells[after], faces[before], cellPlanes[after], facePlanes[before]);
    }
    touch = 1e-9 * std::max(1.0, (e0 - e1).norm());
  }
};

/// Is the triangle inside the tetrahedron, within its angular sector?
bool insideSector(const Sector& sector, double touch, const SmallPolygon& triangle, const EnvelopeOptions& options) {
  if (!sector.valid) return false;
  SmallPolygon inP, inBoth;
  clip(triangle, sector.sectorP, inP);
  if (inP.size == 0) return true;
  clip(inP, sector.sectorQ, inBoth);
  for (std::size_t i = 0; i < inBoth.size; ++i) {
    const Point& x = inBoth.points[i];
    if (sector.outer0.eval(x) >= options.margin && sector.outer1.eval(x) >= options.margin) continue;
    // Allowed contact: the segment v_c v_f, which neighbouring edges share.
    if (nearSegment(x, sector.P, sector.Q, touch)) continue;
    return false;
  }
  return true;
}

bool triangleInSectors(const EnvelopeSectors& envelope, const Vec3d& a, const Vec3d& b, const Vec3d& c,
                       const EnvelopeOptions& options) {
  SmallPolygon triangle;
  triangle.points[0] = toPoint(a);
  triangle.points[1] = toPoint(b);
  triangle.points[2] = toPoint(c);
  triangle.size = 3;
  for (int i = 0; i < envelope.count; ++i)
    if (!insideSector(envelope.sectors[static_cast<std::size_t>(i)], envelope.touch, triangle, options)) return false;
  return true;
}

/// The polygon around an edge without allocating (edgePolygon's order): at most 4 cell
/// points and 4 face points; this runs once per minimal edge.
struct EdgePolygon {
  std::array<int, 8> local{};
  int size = 0;

  EdgePolygon(int cellCount, const std::array<bool, 4>& facesCrossed) {
    for (int i = 0; i < cellCount; ++i) {
      local[static_cast<std::size_t>(size++)] = i;
      if (!facesCrossed[static_cast<std::size_t>(i)]) local[static_cast<std::size_t>(size++)] = kFaceVertex + i;
    }
  }
  /// Vertex j of the polygon, cyclically.
  int at(int j) const { return local[static_cast<std::size_t>(((j % size) + size) % size)]; }
};

}  // namespace

namespace {

/// A face point the segment misses keeps the clamp of the segment's crossing with the
/// face's plane while that lies within this fraction of the face from the segment.
constexpr double kMissedFaceReach = 0.2;

/// Closest points of segments [p0, p1] and [q0, q1] (Ericson, Real-Time Collision
/// Detection 5.1.9): the point on the second and the squared distance.
std::pair<Point, double> closestOnSecondSegment(const Point& p0, const Point& p1, const Point& q0, const Point& q1) {
  const Point d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  if (a <= 1e-300) {
    t = e > 1e-300 ? std::clamp(f / e, 0.0, 1.0) : 0.0;
  } else {
    const double c = d1.dot(r);
    if (e <= 1e-300) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  const Point onFirst = p0 + d1 * s, onSecond = q0 + d2 * t;
  return {onSecond, (onFirst - onSecond).squaredNorm()};
}

}  // namespace

FacePoint clampedFacePoint(const Vec3d& a, const Vec3d& b, const MinimalFace& face, const EnvelopeOptions& options) {
  const int n = face.axis;
  const double da = a[n] - face.coordinate, db = b[n] - face.coordinate;
  const Point pa = toPoint(a), pb = toPoint(b);
  Vec3d x;
  if ((da < 0) != (db < 0) && da != db) {
    const double t = da / (da - db);
    x = toVec3d(pa + (pb - pa) * t);
  } else {
    x = toVec3d((pa + pb) * 0.5);
  }
  x[n] = face.coordinate;
  const double m = options.faceMarginFraction * face.size;
  FacePoint result;
  result.crossed = (da < 0) != (db < 0);
  for (int axis = 0; axis < 3; ++axis) {
    if (axis == n) continue;
    const double lo = face.min[axis] + m, hi = face.min[axis] + face.size - m;
    if (x[axis] < lo || x[axis] > hi) result.crossed = false;
    x[axis] = std::clamp(x[axis], lo, hi);
  }
  const double reach = kMissedFaceReach * face.size;
  if (!result.crossed && closestOnSecondSegment(pa, pb, toPoint(x), toPoint(x)).second > reach * reach) {
    // The segment misses the face, and the clamp of its crossing with the face's plane lies
    // far from it (a segment almost parallel to the face crosses the plane far away and
    // was clamped into a corner, up to a voxel off the surface both cell points lie on: a
    // pass of the error bound's post-check for the block). Then the point of the face
    // (within its margin) nearest the segment, on the face's rim. Nearer clamps stay: the
    // nearest rim point everywhere fanned 29 % more edges on the 256^3 blobs (the
    // envelope test refused more diagonals), with this reach 13 %.
    const int u = (n + 1) % 3, v = (n + 2) % 3;
    const double lu = face.min[u] + m, hu = face.min[u] + face.size - m;
    const double lv = face.min[v] + m, hv = face.min[v] + face.size - m;
    const auto corner = [&](double cu, double cv) {
      Point c;
      c[n] = face.coordinate;
      c[u] = cu;
      c[v] = cv;
      return c;
    };
    const std::array<Point, 4> rim{corner(lu, lv), corner(hu, lv), corner(hu, hv), corner(lu, hv)};
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < 4; ++i) {
      const auto [point, d2] = closestOnSecondSegment(pa, pb, rim[i], rim[(i + 1) % 4]);
      if (d2 < best) {
        best = d2;
        x = toVec3d(point);
      }
    }
    x[n] = face.coordinate;
  }
  result.point = x;
  return result;
}

bool triangleInEnvelope(const EdgeEnvelope& envelope, const Vec3d& a, const Vec3d& b, const Vec3d& c,
                        const EnvelopeOptions& options) {
  return triangleInSectors(EnvelopeSectors(envelope), a, b, c, options);
}

bool plainQuadInEnvelope(const EdgeEnvelope& envelope, const EnvelopeOptions& options) {
  const EnvelopeSectors sectors(envelope);
  const auto& c = envelope.cellPoints;
  for (std::size_t apex = 0; apex < 2; ++apex)
    if (triangleInSectors(sectors, c[apex], c[apex + 1], c[apex + 2], options) &&
        triangleInSectors(sectors, c[apex], c[apex + 2], c[(apex + 3) % 4], options))
      return true;
  return false;
}

std::vector<int> edgePolygon(int cellCount, const std::array<bool, 4>& facesCrossed) {
  const EdgePolygon polygon(cellCount, facesCrossed);
  return {polygon.local.begin(), polygon.local.begin() + polygon.size};
}

EdgeTriangulation chooseTriangulation(const EdgeEnvelope& envelope, const std::array<bool, 4>& facesCrossed,
                                      bool intersectionFree, const EnvelopeOptions& options, int firstApex) {
  const int k = envelope.cellCount;
  const std::array<bool, 4> allCrossed{true, true, true, true};
  const EdgePolygon polygon(k, intersectionFree ? facesCrossed : allCrossed);
  const int m = polygon.size;
  auto point = [&](int local) -> const Vec3d& {
    return local >= kFaceVertex ? envelope.facePoints[static_cast<std::size_t>(local - kFaceVertex)]
                                : envelope.cellPoints[static_cast<std::size_t>(local)];
  };
  // Apex order: for a quadrilateral the better diagonal first, chosen as regular mode's
  // quads choose it (quad_diagonal.h: four unit cells then give regular mode's triangles,
  // which adaptive mode's error bound is measured against), else in polygon order.
  std::array<int, 8> apexes{0, 1, 2, 3, 4, 5, 6, 7};
  int apexCount = m;
  if (m == 4) {
    const auto at = [&](int i) { return toPoint(point(polygon.at(i))); };
    if ((m == k && firstApex >= 0) ? firstApex == 1 : !firstDiagonalIsBetter(at(0), at(1), at(2), at(3)))
      std::swap(apexes[0], apexes[1]);
    apexCount = 2;
  } else if (m == 3) {
    apexCount = 1;
  }
  if (!intersectionFree) return EdgeTriangulation{false, apexes.front()};
  // Most polygons with every face crossed lie well inside their envelope: a test across the
  // edge says so without building the sectors, for the apex the full test tries first.
  if (m == k && clearlyInsideEnvelope(envelope, apexes.front(), options))
    return EdgeTriangulation{false, apexes.front()};
  const EnvelopeSectors sectors(envelope);
  for (int a = 0; a < apexCount; ++a) {
    const int apex = apexes[static_cast<std::size_t>(a)];
    bool ok = true;
    for (int j = 1; j + 1 < m && ok; ++j)
      ok = triangleInSectors(sectors, point(polygon.at(apex)), point(polygon.at(apex + j)),
                             point(polygon.at(apex + j + 1)), options);
    if (ok) return EdgeTriangulation{false, apex};
  }
  return EdgeTriangulation{true, 0};
}

void triangulateEdge(int cellCount, const std::array<bool, 4>& facesCrossed, EdgeTriangulation how,
                     std::vector<std::array<int, 3>>& out) {
  out.clear();
  const EdgePolygon polygon(cellCount, facesCrossed);
  const int m = polygon.size;
  if (how.fan) {
    for (int j = 0; j < m; ++j) out.push_back({kEdgeVertex, polygon.at(j), polygon.at(j + 1)});
    return;
  }
  for (int j = 1; j + 1 < m; ++j)
    out.push_back({polygon.at(how.apex), polygon.at(how.apex + j), polygon.at(how.apex + j + 1)});
}

}  // namespace isovdb::contour
