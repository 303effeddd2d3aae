// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// A scalar field whose object lies below the isovalue (a signed distance negative
// inside): --inside below meshes it outward, in every method, as the same surface of
// the negated field would be.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "isovdb/errors.h"
#include "isovdb/mesh/validate.h"
#include "isovdb/pipeline/extract.h"
#include "isovdb/volume/grids.h"
#include "isovdb/volume/ingest.h"
#include "isovdb/volume/sampled_box.h"
#include "support/vector_slice_stream.h"

namespace isovdb::pipeline {
namespace {

constexpr double kRadius = 10.0;

/// sign * (r - kRadius) sampled on 40^3: a ball, its inside below 0 (sign 1) or above it.
volume::Volume ballField(float sign) {
  auto stream = test::VectorSliceStream::fromFunction({40, 40, 40}, [sign](int x, int y, int z) {
    const double r = std::sqrt((x - 19.6) * (x - 19.6) + (y - 20.2) * (y - 20.2) + (z - 19.3) * (z - 19.3));
    return static_cast<float>(sign * (r - kRadius));
  });
  return volume::ingestScalar(stream);
}

mesh::Mesh extractWith(const volume::Volume& field, ContourMethod method, ScalarInside inside, float iso) {
  ExtractOptions options;
  options.contour.method = method;
  options.iso = iso;
  options.scalarInside = inside;
  options.metaCellSize = 16;  // seams through the ball
  return extractMesh(field, options);
}

class ScalarInsideMethods : public ::testing::TestWithParam<ContourMethod> {};

TEST_P(ScalarInsideMethods, BelowIsTheNegatedFieldsSurfaceAboveItsIsovalue) {
  const volume::Volume distance = ballField(1.0f);
  for (const float iso : {0.0f, 2.5f}) {
    const mesh::Mesh below = extractWith(distance, GetParam(), ScalarInside::Below, iso);
    const mesh::Mesh above = extractWith(ballField(-1.0f), GetParam(), ScalarInside::Above, -iso);
    EXPECT_EQ(below.positions, above.positions) << iso;
    EXPECT_EQ(below.triangles, above.triangles) << iso;
    const mesh::MeshReport report = mesh::validateMesh(below);
    EXPECT_TRUE(report.closed && report.manifold) << iso;
    EXPECT_EQ(report.components, 1) << iso;
    EXPECT_EQ(report.selfIntersectingPairs, 0) << iso;
    const double radius = kRadius + iso;  // iso > 0 grows the ball, as on a distance field
    EXPECT_NEAR(report.signedVolume, 4.0 / 3.0 * std::numbers::pi * radius * radius * radius,
                0.03 * radius * radius * radius * 4.0)
        << iso;  // positive: outward
  }
  // The caller's field is left as it was.
  EXPECT_FLOAT_EQ(volume::fieldGrid(distance).tree().getValue(openvdb::Coord(20, 20, 19)),
                  static_cast<float>(std::sqrt(0.4 * 0.4 + 0.2 * 0.2 + 0.3 * 0.3) - kRadius));
}

INSTANTIATE_TEST_SUITE_P(AllMethods, ScalarInsideMethods,
                         ::testing::Values(ContourMethod::Adaptive, ContourMethod::Regular, ContourMethod::Vdb),
                         [](const auto& info) { return std::string(contourMethodName(info.param)); });

TEST(ScalarInside, AboveOnANegativeInsideFieldKeepsItsMeaning) {
  // Read with the default side, r - 10 is a box (the data's caps) around a ball-shaped cavity.
  const mesh::MeshReport report = mesh::validateMesh(
      extractWith(ballField(1.0f), ContourMethod::Adaptive, ScalarInside::Above, 0.0f), {.selfIntersections = false});
  EXPECT_EQ(report.components, 2);
  ASSERT_EQ(report.componentReports.size(), 2u);
  EXPECT_GT(report.signedVolume, 0.0);
}

TEST(ScalarInside, NegatedScalarKeepsGeometryAndSampledBoxAndRefusesMasks) {
  const volume::Volume field = ballField(1.0f);
  const volume::Volume negated = volume::negatedScalar(field);
  EXPECT_EQ(volume::fieldGrid(negated).background(), -volume::fieldGrid(field).background());
  EXPECT_EQ(volume::fieldGrid(negated).tree().getValue(openvdb::Coord(0, 0, 0)),
            -volume::fieldGrid(field).tree().getValue(openvdb::Coord(0, 0, 0)));
  const auto box = volume::sampledBox(negated);
  ASSERT_TRUE(box.has_value());
  EXPECT_EQ(box->max, (std::array<int, 3>{39, 39, 39}));
  EXPECT_EQ(negated.name(), field.name());
  auto maskStream =
      test::VectorSliceStream::fromFunction({8, 8, 8}, [](int x, int, int) { return x < 4 ? 1.0f : 0.0f; });
  EXPECT_THROW(volume::negatedScalar(volume::ingestMask(maskStream, {})), InputError);
}

}  // namespace
}  // namespace isovdb::pipeline
