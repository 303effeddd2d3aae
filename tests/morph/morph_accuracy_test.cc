// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// How close the morph comes to the solid it was sliced from (issue #8's ground-truth
// and corner lines, small enough for a unit test; bench/morph_eval.py has the full
// figures): area matching and the particles' corners.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "isovdb/morph/area_match.h"
#include "isovdb/morph/pair_morph.h"
#include "isovdb/morph/reconstruct.h"
#include "isovdb/morph/slice_sdf.h"
#include "morph_test_support.h"

namespace isovdb::morph::test {
namespace {

TEST(AreaMatch, LeavesTheAskedAreaInsideUpToTiesOrNothing) {
  const Field2 sdf = signedDistance(disc(48, 48, 24, 24, 10));
  for (std::int64_t area : {1, 150, 314, 700}) {
    Field2 phi = sdf;
    shiftToArea(phi, area);
    // Pixels of one value stay on one side: at most the last value's ties are added.
    float last = -1e30f;
    for (float v : phi.values)
      if (v <= 0) last = std::max(last, v);
    std::int64_t ties = 0;
    for (float v : phi.values) ties += v == last;
    EXPECT_GE(insideOf(phi).area(), area);
    EXPECT_LT(insideOf(phi).area() - area, ties);
  }
  Field2 phi = sdf;
  shiftToArea(phi, 0);
  EXPECT_EQ(insideOf(phi).area(), 0);
}

/// A torus of radii 18 and 7 whose axis is tilted 30° from z, on 64 × 64 slices.
Mask2 tiltedTorusSlice(double z) {
  Mask2 m = Mask2::empty(64, 64);
  const double tilt = M_PI / 6;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const double px = x - 31.5, py = y - 31.5, pz = z;
      const double ry = py * std::cos(tilt) + pz * std::sin(tilt), rz = -py * std::sin(tilt) + pz * std::cos(tilt);
      m.set(x, y, std::hypot(std::hypot(px, ry) - 18, rz) <= 7);
    }
  return m;
}

/// |planes' inside pixels - the solid's| / the solid's, between the first and the last slice.
double volumeError(const PairOptions& pair) {
  const int step = 8, first = -12, count = 4;  // slices at z = -12, -4, 4, 12
  std::vector<Mask2> masks;
  std::vector<double> heights;
  for (int k = 0; k < count; ++k) {
    masks.push_back(tiltedTorusSlice(first + k * step));
    heights.push_back(k * step);
  }
  ReconstructOptions options;
  options.pair = pair;
  const Reconstruction r = reconstruct(stackOf(masks, heights), options);
  double made = 0, truth = 0;
  for (int z = 0; z < static_cast<int>(r.planes.size()); ++z) {
    made += static_cast<double>(insideOf(r.planes[z]).area());
    truth += static_cast<double>(tiltedTorusSlice(first + z).area());
  }
  return std::abs(made - truth) / truth;
}

TEST(MorphAccuracy, TiltedTorusKeepsItsVolumeWithAreaMatching) {
  PairOptions matched;
  PairOptions unmatched;
  unmatched.matchArea = false;
  const double withMatch = volumeError(matched), without = volumeError(unmatched);
  EXPECT_LT(withMatch, 0.03);
  EXPECT_LT(withMatch, without);  // the morph alone shrinks the moving sections
}

/// Mean over the intermediate planes of area / bounding-box area (1 = sharp corners).
double cornerSharpness(bool particles) {
  const std::vector<Mask2> masks = {rectangle(64, 64, 6, 10, 57, 53), rectangle(64, 64, 16, 18, 47, 45)};
  ReconstructOptions options;
  options.pair.particles = particles;
  const Reconstruction r = reconstruct(stackOf(masks, {0, 8}), options);
  double sum = 0;
  for (int z = 1; z < 8; ++z) {
    const Mask2 m = insideOf(r.planes[z]);
    int x0 = m.width, y0 = m.height, x1 = -1, y1 = -1;
    for (int y = 0; y < m.height; ++y)
      for (int x = 0; x < m.width; ++x)
        if (m.at(x, y)) {
          x0 = std::min(x0, x);
          x1 = std::max(x1, x);
          y0 = std::min(y0, y);
          y1 = std::max(y1, y);
        }
    sum += static_cast<double>(m.area()) / ((x1 - x0 + 1) * (y1 - y0 + 1));
  }
  return sum / 7;
}

TEST(MorphAccuracy, ParticlesKeepRectangleCornersSharperThanTheLevelSet) {
  const double levelSet = cornerSharpness(false), particles = cornerSharpness(true);
  // At most two thirds of the level set's corner loss (bench: the pyramid, 100 x 70).
  EXPECT_GT(1 - levelSet, 1.5 * (1 - particles)) << "level set " << levelSet << ", particles " << particles;
}

}  // namespace
}  // namespace isovdb::morph::test
