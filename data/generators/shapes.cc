// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "generators/shapes.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "isovdb/errors.h"
#include "isovdb/split_mix.h"

namespace isovdb::samples {

namespace {

struct ShapeInfo {
  ShapeKind kind;
  std::string_view name;
  int eulerCharacteristic;
  std::string_view description;
};

constexpr std::array<ShapeKind, 6> kAllShapes{ShapeKind::Sphere,     ShapeKind::Torus,    ShapeKind::Genus2,
                                              ShapeKind::GyroidSlab, ShapeKind::SaltDome, ShapeKind::Blobs};
constexpr std::span<const ShapeKind> kKnownTopology(kAllShapes.data(), 5);

// Euler characteristics (chi = components - handles + cavities) and why:
// - sphere: a ball is contractible -> 1.
// - torus: a solid torus deformation-retracts onto its core circle -> chi(S^1) = 0.
// - genus2: union A u B of two solid tori whose tubes overlap in one
//   contractible lens around the origin (their core circles do not meet):
//   chi = chi(A) + chi(B) - chi(A n B) = 0 + 0 - 1 = -1 (a genus-2 handlebody).
//   The smooth blend only thickens the junction, away from both holes.
// - gyroid-slab: established numerically (see the note at kGyroidFrequency):
//   the (26, 6) digital chi is -6 at sizes 64, 77, 80, 96, 100, 128, 192, 256,
//   384 and 512, and stays -6 when any single face of the clipping box moves
//   by up to +-1.5 voxels (at size 64, checked at 64 and 128).
// - salt-dome: three components (the body and two pods, separated by gaps of
//   >= 0.25, i.e. 8 voxels at size 64), one handle (the tunnel through the
//   cap), no cavity -> 3 - 1 + 0 = 2. The body before the tunnel is a
//   blend of a ball-like cap and a cylinder stem (contractible); drilling a
//   tube right through it adds exactly one handle.
// - blobs: a random union of ellipsoids has no closed-form chi; its digital chi
//   and voxel count depend on the size and are counted (isovdb-sample prints
//   the count; volume::eulerCharacteristic gives chi).
constexpr int kUnknownChi = 0;
constexpr std::array<ShapeInfo, 6> kShapeInfo{{
    {ShapeKind::Sphere, "sphere", 1, "ball of radius 0.8 (radius 0.4*size voxels)"},
    {ShapeKind::Torus, "torus", 0, "solid torus, major radius 0.6, minor radius 0.25, axis z"},
    {ShapeKind::Genus2, "genus2", -1, "two solid tori (R 0.34, r 0.16) fused side by side: a genus-2 handlebody"},
    {ShapeKind::GyroidSlab, "gyroid-slab", -6,
     "gyroid labyrinth (period size/2) clipped to a 1.5 x 1.5 x 1 period box, "
     "size x size x 5/8 size; chi established numerically"},
    {ShapeKind::SaltDome, "salt-dome", 2,
     "perturbed mushroom (cap overhanging a stem) with a tunnel through the cap, "
     "plus two detached pods: 3 components, 1 handle"},
    {ShapeKind::Blobs, "blobs", kUnknownChi,
     "2000 random overlapping ellipsoids (semi-axes 0.006..0.06, i.e. 3..30 voxels at 1024) "
     "from --seed: a surface-heavy volume; chi not known, the voxel count is printed"},
}};

const ShapeInfo& info(ShapeKind kind) {
  for (const ShapeInfo& entry : kShapeInfo)
    if (entry.kind == kind) return entry;
  throw InputError("unknown sample shape kind " + std::to_string(static_cast<int>(kind)));
}

constexpr int kMinSize = 16;
constexpr int kMaxSize = 16384;

void validate(const ShapeOptions& options) {
  if (options.size < kMinSize || options.size > kMaxSize)
    throw InputError("ShapeOptions.size: expected " + std::to_string(kMinSize) + ".." + std::to_string(kMaxSize) +
                     " voxels, got " + std::to_string(options.size));
  if (options.label == 0) throw InputError("ShapeOptions.label: expected 1..255 (0 is the outside value), got 0");
}

struct Vec3 {
  double x, y, z;
};

double length(double x, double y) { return std::sqrt(x * x + y * y); }
double length(double x, double y, double z) { return std::sqrt(x * x + y * y + z * z); }

/// Polynomial smooth minimum (union with a fillet of width ~k).
double smoothMin(double a, double b, double k) {
  const double h = std::max(k - std::abs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}
/// Smooth maximum (intersection / subtraction with a rounded edge of width ~k).
double smoothMax(double a, double b, double k) { return -smoothMin(-a, -b, k); }

// Fields below are in normalised coordinates and negative inside. Only their
// sign matters; they are (close to) signed distances so that blends and
// perturbations have a predictable width.

double sphereField(Vec3 q) { return length(q.x, q.y, q.z) - 0.8; }

/// Solid torus around the z axis through `centre`.
double torusField(Vec3 q, Vec3 centre, double major, double minor) {
  const double x = q.x - centre.x, y = q.y - centre.y, z = q.z - centre.z;
  return length(length(x, y) - major, z) - minor;
}

/// Two solid tori in the plane z = 0 with centres (+-d, 0, 0), d = R + 0.4 r:
/// the core circles stay 2 (d - R) = 0.128 apart, the tubes (diameter 0.32)
/// overlap in one lens at the origin. Holes are 0.36 wide (11 voxels at 64).
double genus2Field(Vec3 q) {
  constexpr double kMajor = 0.34, kMinor = 0.16, kOffset = kMajor + 0.4 * kMinor;
  const double left = torusField(q, {-kOffset, 0.0, 0.0}, kMajor, kMinor);
  const double right = torusField(q, {kOffset, 0.0, 0.0}, kMajor, kMinor);
  return smoothMin(left, right, 0.04);
}

/// Axis-aligned ellipsoid; sign-exact approximation of the distance (Quilez).
double ellipsoidField(Vec3 q, Vec3 centre, Vec3 radii) {
  const double x = q.x - centre.x, y = q.y - centre.y, z = q.z - centre.z;
  const double k0 = length(x / radii.x, y / radii.y, z / radii.z);
  const double k1 = length(x / (radii.x * radii.x), y / (radii.y * radii.y), z / (radii.z * radii.z));
  if (k1 == 0.0) return -std::min({radii.x, radii.y, radii.z});
  return k0 * (k0 - 1.0) / k1;
}

/// Vertical cylinder of radius r over z in [z0, z1] (exact distance).
double cappedCylinderField(Vec3 q, double r, double z0, double z1) {
  const double half = 0.5 * (z1 - z0);
  const double dr = length(q.x, q.y) - r;
  const double dz = std::abs(q.z - 0.5 * (z0 + z1)) - half;
  return std::min(std::max(dr, dz), 0.0) + length(std::max(dr, 0.0), std::max(dz, 0.0));
}

/// Salt-dome-like body, z up. Main body: a stem (cylinder r 0.22, z -0.9..0.15)
/// blended into a cap (ellipsoid centred at z 0.35, radii 0.75 x 0.65 x 0.35),
/// so the cap overhangs the stem by ~0.5 all round. A tunnel (cylinder along y,
/// radius 0.12, axis at x 0, z 0.40) runs right through the cap: walls about 0.18
/// (5.7 voxels at 64), mouths nearly perpendicular to the cap surface. Two
/// detached ellipsoidal pods sit low beside the stem, >= 0.25 from everything.
/// A smooth perturbation of amplitude <= 0.04 and slope <= 0.35 roughens all of it
/// without changing its topology.
double saltDomeField(Vec3 q) {
  const double stem = cappedCylinderField(q, 0.22, -0.9, 0.15);
  const double cap = ellipsoidField(q, {0.0, 0.0, 0.35}, {0.75, 0.65, 0.35});
  const double tunnel = length(q.x, q.z - 0.40) - 0.12;
  double body = smoothMin(stem, cap, 0.1);
  body = smoothMax(body, -tunnel, 0.04);
  const double podA = ellipsoidField(q, {-0.62, -0.50, -0.60}, {0.20, 0.15, 0.12});
  const double podB = ellipsoidField(q, {0.58, 0.52, -0.35}, {0.16, 0.20, 0.10});
  const double unperturbed = std::min({body, podA, podB});
  // |perturbation| <= 0.04, so far from the surface the sign is already known
  // (this skips the trigonometry for most voxels without changing the result).
  if (unperturbed > 0.05 || unperturbed < -0.05) return unperturbed;
  const double perturbation =
      0.025 * std::sin(5.1 * q.x + 0.3) * std::sin(4.3 * q.y + 1.1) * std::sin(3.7 * q.z + 0.7) +
      0.015 * std::sin(7.3 * q.x - 2.9 * q.y + 4.1 * q.z + 0.5);
  return unperturbed + perturbation;
}

// Gyroid slab: the labyrinth g > 0 of the gyroid
//   g = sin X cos Y + sin Y cos Z + sin Z cos X,  (X, Y, Z) = 2 pi q,
// (period 0.5*size voxels, channels ~0.15*size wide), clipped to the box
// |qx|, |qy| <= kBoxXY, |qz| <= kBoxZ (1.5 x 1.5 x 1 periods) inside a volume
// of size x size x 5/8 size voxels. g > 0 and g < 0 are congruent labyrinths,
// so the solid and its complement have the same feature size.
//
// Its chi = -6 is established numerically, not analytically. Where the box
// cuts the labyrinth decides chi: moving one face across a level where the
// face is tangent to the gyroid surface changes it. A scan of each face at
// size 256 (one-voxel steps) found chi constant for |x|, |y| faces in about
// [0.65, 0.88] and |z| faces in about [0.38, 0.63]; the faces sit near the
// middle of those plateaus, >= 0.1 (3 voxels at size 64) from any change, so
// sampling cannot create or remove slivers where the box clips a channel.
constexpr double kGyroidFrequency = 2.0 * std::numbers::pi;
constexpr double kBoxXY = 0.75;
constexpr double kBoxZ = 0.5;

bool inGyroidBox(Vec3 q) { return std::abs(q.x) <= kBoxXY && std::abs(q.y) <= kBoxXY && std::abs(q.z) <= kBoxZ; }

/// Gyroid value from the sines and cosines of the three scaled coordinates.
double gyroid(double sx, double cx, double sy, double cy, double sz, double cz) { return sx * cy + sy * cz + sz * cx; }

// Blobs: kBlobCount ellipsoids with centres uniform in [-0.92, 0.92]^3, a size r
// log-uniform in [kBlobMinRadius, kBlobMaxRadius] (many small bodies, a few
// large ones), semi-axes r * [0.6, 1.4) each and a uniformly random rotation.
// The generator is splitmix64 with our own conversion to doubles, so the solid
// is the same with every standard library.
constexpr int kBlobCount = 2000;
constexpr double kBlobMinRadius = 0.006, kBlobMaxRadius = 0.06;

/// The solid (q - c)^T A (q - c) <= 1 in normalised coordinates.
struct Ellipsoid {
  Vec3 centre;
  double a00, a01, a02, a11, a12, a22;  ///< symmetric quadratic form
  Vec3 halfExtent;                      ///< of its axis-aligned bounding box

  double form(Vec3 q) const {
    const double x = q.x - centre.x, y = q.y - centre.y, z = q.z - centre.z;
    return a00 * x * x + a11 * y * y + a22 * z * z + 2.0 * (a01 * x * y + a02 * x * z + a12 * y * z);
  }
};

std::vector<Ellipsoid> makeBlobs(std::uint64_t seed) {
  SplitMix64 random(seed);
  std::vector<Ellipsoid> blobs;
  blobs.reserve(kBlobCount);
  for (int n = 0; n < kBlobCount; ++n) {
    Ellipsoid e{};
    e.centre = {-0.92 + 1.84 * random.uniform(), -0.92 + 1.84 * random.uniform(), -0.92 + 1.84 * random.uniform()};
    const double r = kBlobMinRadius * std::pow(kBlobMaxRadius / kBlobMinRadius, random.uniform());
    const double semi[3] = {r * (0.6 + 0.8 * random.uniform()), r * (0.6 + 0.8 * random.uniform()),
                            r * (0.6 + 0.8 * random.uniform())};
    // Uniform random rotation from a unit quaternion (Shoemake).
    const double u1 = random.uniform(), u2 = 2.0 * std::numbers::pi * random.uniform(),
                 u3 = 2.0 * std::numbers::pi * random.uniform();
    const double qa = std::sqrt(1.0 - u1) * std::sin(u2), qb = std::sqrt(1.0 - u1) * std::cos(u2),
                 qc = std::sqrt(u1) * std::sin(u3), qd = std::sqrt(u1) * std::cos(u3);
    const double rot[3][3] = {{1 - 2 * (qc * qc + qd * qd), 2 * (qb * qc - qa * qd), 2 * (qb * qd + qa * qc)},
                              {2 * (qb * qc + qa * qd), 1 - 2 * (qb * qb + qd * qd), 2 * (qc * qd - qa * qb)},
                              {2 * (qb * qd - qa * qc), 2 * (qc * qd + qa * qb), 1 - 2 * (qb * qb + qc * qc)}};
    // A = R diag(1 / semi^2) R^T; the bounding box half-extent along i is sqrt(sum_k R_ik^2 semi_k^2).
    double a[3][3] = {};
    double extent[3] = {};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) a[i][j] += rot[i][k] * rot[j][k] / (semi[k] * semi[k]);
        extent[i] += rot[i][j] * rot[i][j] * semi[j] * semi[j];
      }
    e.a00 = a[0][0], e.a01 = a[0][1], e.a02 = a[0][2], e.a11 = a[1][1], e.a12 = a[1][2], e.a22 = a[2][2];
    e.halfExtent = {std::sqrt(extent[0]), std::sqrt(extent[1]), std::sqrt(extent[2])};
    blobs.push_back(e);
  }
  return blobs;
}

/// The sampling grid of one shape at one size.
class Sampler {
 public:
  Sampler(ShapeKind kind, const ShapeOptions& options)
      : kind_(kind), dims_(shapeDims(kind, options)), size_(options.size) {
    if (kind == ShapeKind::Blobs) blobs_ = makeBlobs(options.seed);
  }

  const std::array<std::int64_t, 3>& dims() const { return dims_; }

  /// Normalised coordinate of index-space coordinate `x` along `axis`.
  double normalised(int axis, double x) const { return (2.0 * (x + 0.5) - static_cast<double>(dims_[axis])) / size_; }

  bool insideIndex(double x, double y, double z) const {
    const Vec3 q{normalised(0, x), normalised(1, y), normalised(2, z)};
    // Everything outside the sampled box is outside the solid.
    if (std::abs(q.x) > 1.0 + 1e-12 || std::abs(q.y) > 1.0 + 1e-12 ||
        std::abs(q.z) > static_cast<double>(dims_[2]) / size_ + 1e-12)
      return false;
    switch (kind_) {
      case ShapeKind::Sphere:
        return sphereField(q) < 0.0;
      case ShapeKind::Torus:
        return torusField(q, {0.0, 0.0, 0.0}, 0.6, 0.25) < 0.0;
      case ShapeKind::Genus2:
        return genus2Field(q) < 0.0;
      case ShapeKind::GyroidSlab: {
        if (!inGyroidBox(q)) return false;
        const double w = kGyroidFrequency;
        return gyroid(std::sin(w * q.x), std::cos(w * q.x), std::sin(w * q.y), std::cos(w * q.y), std::sin(w * q.z),
                      std::cos(w * q.z)) > 0.0;
      }
      case ShapeKind::SaltDome:
        return saltDomeField(q) < 0.0;
      case ShapeKind::Blobs:
        return std::any_of(blobs_.begin(), blobs_.end(), [&q](const Ellipsoid& e) { return e.form(q) <= 1.0; });
    }
    return false;
  }

  /// Fills slice z; rows in parallel. The gyroid reuses per-axis sines and
  /// cosines (the same values insideIndex() computes, so results agree exactly).
  void fillSlice(std::int64_t z, std::uint8_t label, std::uint8_t* out) const {
    const std::int64_t nx = dims_[0], ny = dims_[1];
    if (kind_ == ShapeKind::GyroidSlab) {
      fillGyroidSlice(z, label, out);
      return;
    }
    if (kind_ == ShapeKind::Blobs) {
      fillBlobSlice(z, label, out);
      return;
    }
    const double zd = static_cast<double>(z);
    tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, ny, 8), [&](const tbb::blocked_range<std::int64_t>& rows) {
      for (std::int64_t y = rows.begin(); y != rows.end(); ++y) {
        std::uint8_t* row = out + y * nx;
        const double yd = static_cast<double>(y);
        for (std::int64_t x = 0; x < nx; ++x) row[x] = insideIndex(static_cast<double>(x), yd, zd) ? label : 0;
      }
    });
  }

 private:
  /// Index-space coordinate of normalised coordinate `q` along `axis` (inverse of normalised()).
  double indexOf(int axis, double q) const { return 0.5 * (q * size_ + static_cast<double>(dims_[axis])) - 0.5; }

  /// Each body crossing the slice marks, row by row, the x-range its ellipse
  /// spans there (one voxel of slack at each end), testing each voxel of it
  /// with the same quadratic form as insideIndex(): the work follows the
  /// bodies' volume, not bodies x voxels.
  void fillBlobSlice(std::int64_t z, std::uint8_t label, std::uint8_t* out) const {
    const std::int64_t nx = dims_[0], ny = dims_[1];
    std::fill_n(out, nx * ny, std::uint8_t{0});
    const double qz = normalised(2, static_cast<double>(z));
    std::vector<const Ellipsoid*> crossing;
    for (const Ellipsoid& e : blobs_)
      if (std::abs(qz - e.centre.z) <= e.halfExtent.z) crossing.push_back(&e);
    auto clampIndex = [](double v, std::int64_t n) {
      return static_cast<std::int64_t>(std::clamp(v, -1.0, static_cast<double>(n)));
    };
    tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, ny, 8), [&](const tbb::blocked_range<std::int64_t>& rows) {
      for (std::int64_t y = rows.begin(); y != rows.end(); ++y) {
        std::uint8_t* row = out + y * nx;
        const double qy = normalised(1, static_cast<double>(y));
        for (const Ellipsoid* e : crossing) {
          if (std::abs(qy - e->centre.y) > e->halfExtent.y) continue;
          // a dx^2 + 2 b dx + c <= 0 along the row, dx = qx - centre.x.
          const double dy = qy - e->centre.y, dz = qz - e->centre.z;
          const double a = e->a00, b = e->a01 * dy + e->a02 * dz;
          const double c = e->a11 * dy * dy + e->a22 * dz * dz + 2.0 * e->a12 * dy * dz - 1.0;
          const double discriminant = b * b - a * c;
          if (discriminant < 0.0) continue;
          const double root = std::sqrt(discriminant);
          const std::int64_t first =
              std::max<std::int64_t>(0, clampIndex(std::floor(indexOf(0, e->centre.x + (-b - root) / a)) - 1.0, nx));
          const std::int64_t last = std::min<std::int64_t>(
              nx - 1, clampIndex(std::ceil(indexOf(0, e->centre.x + (-b + root) / a)) + 1.0, nx));
          for (std::int64_t x = first; x <= last; ++x)
            if (!row[x] && e->form({normalised(0, static_cast<double>(x)), qy, qz}) <= 1.0) row[x] = label;
        }
      }
    });
  }

  void fillGyroidSlice(std::int64_t z, std::uint8_t label, std::uint8_t* out) const {
    const std::int64_t nx = dims_[0], ny = dims_[1];
    const double w = kGyroidFrequency;
    const double qz = normalised(2, static_cast<double>(z));
    if (std::abs(qz) > kBoxZ) {
      std::fill_n(out, nx * ny, std::uint8_t{0});
      return;
    }
    const double sz = std::sin(w * qz), cz = std::cos(w * qz);
    std::vector<double> sx(static_cast<std::size_t>(nx)), cx(sx.size());
    std::vector<std::uint8_t> inX(sx.size());
    for (std::int64_t x = 0; x < nx; ++x) {
      const double qx = normalised(0, static_cast<double>(x));
      sx[x] = std::sin(w * qx);
      cx[x] = std::cos(w * qx);
      inX[x] = std::abs(qx) <= kBoxXY;
    }
    tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, ny, 8), [&](const tbb::blocked_range<std::int64_t>& rows) {
      for (std::int64_t y = rows.begin(); y != rows.end(); ++y) {
        std::uint8_t* row = out + y * nx;
        const double qy = normalised(1, static_cast<double>(y));
        if (std::abs(qy) > kBoxXY) {
          std::fill_n(row, nx, std::uint8_t{0});
          continue;
        }
        const double sy = std::sin(w * qy), cy = std::cos(w * qy);
        for (std::int64_t x = 0; x < nx; ++x) row[x] = inX[x] && gyroid(sx[x], cx[x], sy, cy, sz, cz) > 0.0 ? label : 0;
      }
    });
  }

  ShapeKind kind_;
  std::array<std::int64_t, 3> dims_;
  double size_;
  std::vector<Ellipsoid> blobs_;  ///< ShapeKind::Blobs only
};

class ShapeSliceStream final : public io::SliceStream {
 public:
  ShapeSliceStream(ShapeKind kind, const ShapeOptions& options)
      : sampler_(kind, options),
        label_(options.label),
        source_("sample:" + std::string(shapeName(kind)) + "@" + std::to_string(options.size)),
        bytes_(static_cast<std::size_t>(sampler_.dims()[0] * sampler_.dims()[1])) {
    header_.dims = sampler_.dims();
    header_.sampleType = io::SampleType::UInt8;
  }

  const std::string& source() const override { return source_; }
  const io::VolumeHeader& header() const override { return header_; }
  std::int64_t nextSlice() const override { return next_; }

  void readSlice(float* out) override {
    if (next_ >= header_.dims[2])
      throw InputError(source_ + ": slice " + std::to_string(next_) + " requested, the volume has " +
                       std::to_string(header_.dims[2]) + " slices");
    sampler_.fillSlice(next_, label_, bytes_.data());
    std::transform(bytes_.begin(), bytes_.end(), out, [](std::uint8_t value) { return static_cast<float>(value); });
    ++next_;
  }

 private:
  Sampler sampler_;
  std::uint8_t label_;
  std::string source_;
  io::VolumeHeader header_;
  std::vector<std::uint8_t> bytes_;
  std::int64_t next_ = 0;
};

}  // namespace

std::span<const ShapeKind> allShapes() { return kAllShapes; }

std::span<const ShapeKind> shapesOfKnownTopology() { return kKnownTopology; }

std::string_view shapeName(ShapeKind kind) { return info(kind).name; }

std::string_view shapeDescription(ShapeKind kind) { return info(kind).description; }

std::optional<ShapeKind> parseShape(std::string_view name) {
  std::string canonical(name);
  std::replace(canonical.begin(), canonical.end(), '_', '-');
  std::transform(canonical.begin(), canonical.end(), canonical.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const ShapeInfo& entry : kShapeInfo)
    if (entry.name == canonical) return entry.kind;
  return std::nullopt;
}

int knownEulerCharacteristic(ShapeKind kind) {
  if (kind == ShapeKind::Blobs)
    throw InputError("blobs: a random union of ellipsoids has no known Euler characteristic; count it");
  return info(kind).eulerCharacteristic;
}

std::array<std::int64_t, 3> shapeDims(ShapeKind kind, const ShapeOptions& options) {
  validate(options);
  const std::int64_t n = options.size;
  if (kind == ShapeKind::GyroidSlab) return {n, n, n * 5 / 8};
  return {n, n, n};
}

bool inside(ShapeKind kind, const ShapeOptions& options, double x, double y, double z) {
  return Sampler(kind, options).insideIndex(x, y, z);
}

void generateSlice(ShapeKind kind, const ShapeOptions& options, std::int64_t z, std::uint8_t* out) {
  const Sampler sampler(kind, options);
  if (z < 0 || z >= sampler.dims()[2])
    throw InputError("generateSlice: slice " + std::to_string(z) + " out of range 0.." +
                     std::to_string(sampler.dims()[2] - 1));
  sampler.fillSlice(z, options.label, out);
}

std::unique_ptr<io::SliceStream> makeShapeStream(ShapeKind kind, const ShapeOptions& options) {
  return std::make_unique<ShapeSliceStream>(kind, options);
}

}  // namespace isovdb::samples
