// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Property test (#22): on random smooth fields, both octree methods give one mesh
// with every guarantee at once: closed, manifold, consistently oriented, free of
// self-intersections (exact predicates), and the same topology in both modes.
// The fields are seeded sums of Gaussian bumps and waves, sampled on small grids
// and cut by meta-cells of 16 voxels, with surfaces that leave the sampled box
// (caps), nearly touching bumps (ambiguous faces) and thin necks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "isovdb/mesh/validate.h"
#include "isovdb/pipeline/extract.h"
#include "isovdb/volume/ingest.h"
#include "support/vector_slice_stream.h"

namespace isovdb::pipeline {
namespace {

struct Bump {
  double x, y, z, width, height;
};

/// A seeded smooth field on n^3 samples: Gaussian bumps of either sign plus a weak wave,
/// so that its level sets bend, split and merge within a few voxels.
volume::Volume randomField(std::uint32_t seed, int n, std::string& description) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Bump> bumps(3 + seed % 5);
  for (Bump& b : bumps)
    b = {unit(random) * n, unit(random) * n, unit(random) * n, 2.0 + 6.0 * unit(random),
         (unit(random) < 0.8 ? 1.0 : -0.6) * (0.5 + unit(random))};
  const double k = 0.2 + 0.6 * unit(random), wave = 0.15 * unit(random);
  std::ostringstream text;
  text << "seed " << seed << ", n " << n << ", " << bumps.size() << " bumps, wave " << wave;
  description = text.str();
  auto stream = test::VectorSliceStream::fromFunction({n, n, n}, [&](int x, int y, int z) {
    double v = wave * std::sin(k * x) * std::cos(k * y + 0.3 * z);
    for (const Bump& b : bumps) {
      const double r2 = (x - b.x) * (x - b.x) + (y - b.y) * (y - b.y) + (z - b.z) * (z - b.z);
      v += b.height * std::exp(-r2 / (2.0 * b.width * b.width));
    }
    return static_cast<float>(v);
  });
  return volume::ingestScalar(stream);
}

mesh::MeshReport meshReport(const volume::Volume& field, ContourMethod method, float iso) {
  ExtractOptions options;
  options.contour.method = method;
  options.iso = iso;
  options.metaCellSize = 16;  // seams through every field of 24 samples and more
  options.threads = 1;
  return mesh::validateMesh(extractMesh(field, options));
}

TEST(FieldGuarantees, BothModesAreClosedManifoldIntersectionFreeWithOneTopology) {
  int meshes = 0;
  for (std::uint32_t seed = 1; seed <= 80; ++seed) {
    std::string description;
    const int n = 20 + static_cast<int>(seed % 3) * 6;
    const volume::Volume field = randomField(seed, n, description);
    for (const float iso : {0.3f, 0.55f}) {
      const mesh::MeshReport regular = meshReport(field, ContourMethod::Regular, iso);
      const mesh::MeshReport adaptive = meshReport(field, ContourMethod::Adaptive, iso);
      for (const auto* report : {&regular, &adaptive}) {
        const char* mode = report == &regular ? "regular" : "adaptive";
        EXPECT_TRUE(report->closed) << mode << ", " << description << ", iso " << iso;
        EXPECT_EQ(report->nonManifoldEdges, 0) << mode << ", " << description << ", iso " << iso;
        EXPECT_EQ(report->nonManifoldVertices, 0) << mode << ", " << description << ", iso " << iso;
        EXPECT_EQ(report->inconsistentlyOrientedEdges, 0) << mode << ", " << description << ", iso " << iso;
        EXPECT_EQ(report->selfIntersectingPairs, 0) << mode << ", " << description << ", iso " << iso;
      }
      EXPECT_EQ(adaptive.eulerCharacteristic, regular.eulerCharacteristic) << description << ", iso " << iso;
      EXPECT_EQ(adaptive.components, regular.components) << description << ", iso " << iso;
      meshes += regular.triangles > 0;
    }
  }
  EXPECT_GT(meshes, 130);  // the fields have surfaces, not empty meshes
}

}  // namespace
}  // namespace isovdb::pipeline
