// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb reservoir`'s stages together on real decks: every mesh manifold and free of
// self-intersections once its loops are untangled.
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "isovdb/mesh/validate.h"
#include "isovdb/pipeline/reservoir_extract.h"
#include "support/test_support.h"

namespace isovdb::pipeline {
namespace {

struct Deck {
  std::vector<std::filesystem::path> files;
  std::vector<double> isos;
};

TEST(ReservoirExtract, RealDecksGiveManifoldMeshesWithoutSelfIntersections) {
  // ResInsight's box of Reek (bundled) had 3 pairs at PORO 0.15; Equinor's Reek (shared
  // data) 3-6 at 0.13, 0.15, 0.16, 0.21, 0.23, 0.24 and 0.26 after the pinch-outs were
  // joined, between thin cells with twisted faces.
  std::vector<Deck> decks{
      {{test::dataDir() / "reservoir/reek_box/reek_box_grid_w_props.grdecl"}, {0.1, 0.15, 0.2, 0.25}}};
  const auto reek = test::sharedDataDir() / "reservoir/reek";
  if (std::filesystem::exists(reek))
    decks.push_back({{reek / "reek_sim_grid.grdecl", reek / "reek_sim_poro.grdecl"}, {0.13, 0.16, 0.21, 0.24}});
  std::int64_t untangled = 0;
  for (const Deck& deck : decks)
    for (const double iso : deck.isos) {
      Statistics stats;
      ReservoirOptions options;
      options.inputs = deck.files;
      options.property = "PORO";
      options.iso = iso;
      const mesh::Mesh m = extractReservoir(options, stats);
      const mesh::MeshReport report = mesh::validateMesh(m);
      const std::string what = deck.files.front().filename().string() + " PORO " + std::to_string(iso);
      ASSERT_GT(m.triangleCount(), 1000u) << what;
      EXPECT_EQ(report.selfIntersectingPairs, 0) << what;
      EXPECT_TRUE(report.manifold) << what;
      EXPECT_EQ(report.degenerateTriangles, 0) << what;
      EXPECT_EQ(report.inconsistentlyOrientedEdges, 0) << what;
      EXPECT_EQ(stats["reservoir"]["untangle"]["pairs_after"], 0) << what;
      untangled += stats["reservoir"]["untangle"]["pairs_before"].get<std::int64_t>();
    }
  EXPECT_GT(untangled, 0) << "no deck needed untangling: the test no longer reaches it";
}

}  // namespace
}  // namespace isovdb::pipeline
