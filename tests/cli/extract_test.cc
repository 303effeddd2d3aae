// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// The main job end to end through the `isovdb` binary, on generated volumes
// with a known topology: extract, check --against, sdf, info.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <tuple>

#include <nlohmann/json.hpp>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <stb_image.h>

#include "generators/shapes.h"
#include "isovdb/mesh/preview.h"
#include "isovdb/volume/grids.h"
#include "support/analytic_sdf.h"
#include "support/test_support.h"

namespace isovdb::test {
namespace {

/// Writes a generated shape as an NRRD file with an attached header.
std::filesystem::path writeShape(const TempDir& dir, samples::ShapeKind kind, int size) {
  const samples::ShapeOptions options{.size = size};
  const auto dims = samples::shapeDims(kind, options);
  std::string bytes = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: " + std::to_string(dims[0]) + " " +
                      std::to_string(dims[1]) + " " + std::to_string(dims[2]) + "\nencoding: raw\nspacings: 1 1 1\n\n";
  std::string slice(static_cast<std::size_t>(dims[0] * dims[1]), '\0');
  for (std::int64_t z = 0; z < dims[2]; ++z) {
    samples::generateSlice(kind, options, z, reinterpret_cast<std::uint8_t*>(slice.data()));
    bytes += slice;
  }
  const auto path = dir / (std::string(samples::shapeName(kind)) + ".nrrd");
  writeFile(path, bytes);
  return path;
}

nlohmann::json readJson(const std::filesystem::path& path) { return nlohmann::json::parse(readFile(path)); }

std::string contourMethodOf(const std::filesystem::path& stats) {
  return readJson(stats)["contour"]["method"].get<std::string>();
}

class CliExtract : public ::testing::TestWithParam<std::tuple<samples::ShapeKind, std::string>> {
 protected:
  samples::ShapeKind shape() const { return std::get<0>(GetParam()); }
  const std::string& method() const { return std::get<1>(GetParam()); }
};

TEST_P(CliExtract, ClosedManifoldWithTheObjectsTopology) {
  TempDir dir;
  const auto input = writeShape(dir, shape(), 64);
  const auto mesh = dir / "mesh.ply", stats = dir / "stats.json";
  std::string output;
  ASSERT_EQ(runCommand(cliPath().string() + " -q extract " + input.string() + " -o " + mesh.string() + " --method " +
                           method() + " --check --stats " + stats.string(),
                       &output),
            0)
      << output;
  EXPECT_EQ(contourMethodOf(stats), method());
  const nlohmann::json json = readJson(stats);
  EXPECT_GT(json["contour"]["triangles"].get<int>(), 1000);
  EXPECT_TRUE(json["check"]["closed"].get<bool>());
  EXPECT_TRUE(json["check"]["manifold"].get<bool>());
  EXPECT_EQ(json["check"]["self_intersecting_pairs"].get<int>(), 0);
  EXPECT_EQ(json["check"]["euler_characteristic"].get<int>(), 2 * samples::knownEulerCharacteristic(shape()));
  EXPECT_GT(json["memory"]["peak_rss_bytes"].get<std::int64_t>(), 0);
  EXPECT_TRUE(json["timings_s"].contains("distance_field"));

  // The same comparison through `check --against`, computed from the voxels.
  const auto checkStats = dir / "check.json";
  ASSERT_EQ(runCommand(cliPath().string() + " -q check " + mesh.string() + " --against " + input.string() +
                           " --stats " + checkStats.string(),
                       &output),
            0)
      << output;
  const nlohmann::json check = readJson(checkStats);
  EXPECT_EQ(check["topology"]["solid_euler_characteristic"].get<int>(), samples::knownEulerCharacteristic(shape()));
  EXPECT_TRUE(check["topology"]["matches"].get<bool>());
  EXPECT_TRUE(check["passed"].get<bool>());
}

INSTANTIATE_TEST_SUITE_P(Shapes, CliExtract,
                         ::testing::Combine(::testing::Values(samples::ShapeKind::Sphere, samples::ShapeKind::Torus,
                                                              samples::ShapeKind::Genus2,
                                                              samples::ShapeKind::GyroidSlab,
                                                              samples::ShapeKind::SaltDome),
                                            ::testing::Values(std::string("vdb"), std::string("regular"))),
                         [](const auto& info) {
                           std::string name(samples::shapeName(std::get<0>(info.param)));
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name + "_" + std::get<1>(info.param);
                         });

TEST(CliExtract, StreamsMetaCellsAndCheckAgreesWithTheObject) {
  TempDir dir;
  const auto genus2 = writeShape(dir, samples::ShapeKind::Genus2, 48);
  for (const std::string method : {"regular", "adaptive"}) {
    const auto mesh = dir / (method + ".ply");
    const auto stats = dir / (method + ".json");
    std::string output;
    ASSERT_EQ(runCommand(cliPath().string() + " -q extract " + genus2.string() + " -o " + mesh.string() + " --method " +
                             method + " --meta-cell 16 --threads 1 --stats " + stats.string(),
                         &output),
              0)
        << output;
    const nlohmann::json json = readJson(stats);
    EXPECT_TRUE(json["output"]["streamed"].get<bool>());
    EXPECT_GT(json["meta_cells"]["contoured"].get<int>(), 8);
    EXPECT_GT(json["stitch"]["meta_edges"].get<int>(), 0);
    // The streamed file is closed, with the object's topology (check exits 1 otherwise).
    EXPECT_EQ(runCommand(cliPath().string() + " -q check " + mesh.string() + " --against " + genus2.string() +
                             (method == "regular" ? " --adjacency 6" : ""),
                         &output),
              0)
        << method << ": " << output;
  }
}

// An STL mesh carries no shared vertices: check welds its corners back, so the
// same guarantees and topology hold as for the PLY of the same run.
TEST(CliExtract, StlOutputChecksLikeThePly) {
  TempDir dir;
  const auto genus2 = writeShape(dir, samples::ShapeKind::Genus2, 48);
  const auto mesh = dir / "genus2.stl";
  const auto stats = dir / "check.json";
  std::string output;
  ASSERT_EQ(runCommand(cliPath().string() + " -q extract " + genus2.string() + " -o " + mesh.string(), &output), 0)
      << output;
  ASSERT_EQ(runCommand(cliPath().string() + " -q check " + mesh.string() + " --against " + genus2.string() +
                           " --stats " + stats.string(),
                       &output),
            0)
      << output;
  const nlohmann::json json = readJson(stats);
  EXPECT_EQ(json["mesh"]["euler_characteristic"].get<int>(), -2);  // genus 2
  EXPECT_EQ(std::filesystem::file_size(mesh), 84 + 50 * json["mesh"]["triangles"].get<std::uint64_t>());
}

TEST(CliExtract, AScalarFieldWithoutIsoMeetsItsSurfaceAtTheMiddleOfItsValues) {
  // scikit-image's rule: the genus-2 shape's 0/1 samples read as a scalar field, no --iso: 0.5.
  TempDir dir;
  const auto genus2 = writeShape(dir, samples::ShapeKind::Genus2, 48);
  const auto mesh = dir / "genus2.ply";
  const auto stats = dir / "extract.json";
  std::string output;
  ASSERT_EQ(runCommand(cliPath().string() + " -q extract " + genus2.string() + " --scalar --check -o " + mesh.string() +
                           " --stats " + stats.string(),
                       &output),
            0)
      << output;
  const nlohmann::json json = readJson(stats);
  EXPECT_EQ(json["contour"]["iso"].get<double>(), 0.5);
  EXPECT_EQ(json["contour"]["iso_rule"].get<std::string>(), "middle of the values' range");
  EXPECT_EQ(json["check"]["euler_characteristic"].get<int>(), -2);
  // A constant field has no middle: refused, naming the file and the value.
  const auto constant = dir / "constant.nrrd";
  writeFile(constant, "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 4 4 4\nencoding: raw\n\n" + std::string(64, '\7'));
  EXPECT_EQ(
      runCommand(cliPath().string() + " -q extract " + constant.string() + " --scalar -o " + (dir / "c.ply").string(),
                 &output),
      2);  // bad input
  EXPECT_NE(output.find("constant.nrrd': every value is 7, so no isovalue meets a surface (give --iso"),
            std::string::npos)
      << output;
  EXPECT_FALSE(std::filesystem::exists(dir / "c.ply"));
}

TEST(CliExtract, ObjAndGlbOutputsCheckLikeThePly) {
  TempDir dir;
  const auto genus2 = writeShape(dir, samples::ShapeKind::Genus2, 40);
  std::string output;
  for (const char* extension : {".obj", ".glb"}) {
    const auto mesh = dir / ("genus2" + std::string(extension));
    const auto stats = dir / "check.json";
    ASSERT_EQ(runCommand(cliPath().string() + " -q extract " + genus2.string() + " -o " + mesh.string(), &output), 0)
        << output;
    ASSERT_EQ(runCommand(cliPath().string() + " -q check " + mesh.string() + " --stats " + stats.string(), &output), 0)
        << extension << ": " << output;
    EXPECT_EQ(readJson(stats)["mesh"]["euler_characteristic"].get<int>(), -2) << extension;  // genus 2
  }
}

TEST(CliExtract, RejectsABadMetaCellSizeWithoutWritingAnything) {
  TempDir dir;
  const auto sphere = writeShape(dir, samples::ShapeKind::Sphere, 32);
  const auto mesh = dir / "sphere.ply";
  std::string output;
  EXPECT_EQ(runCommand(cliPath().string() + " -q extract " + sphere.string() + " -o " + mesh.string() +
                           " --method regular --meta-cell 24",
                       &output),
            2);
  EXPECT_NE(output.find("--meta-cell"), std::string::npos) << output;
  EXPECT_FALSE(std::filesystem::exists(mesh));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);  // only the input
}

TEST(CliCheck, FailsOnATopologyMismatch) {
  TempDir dir;
  const auto sphere = writeShape(dir, samples::ShapeKind::Sphere, 48);
  const auto torus = writeShape(dir, samples::ShapeKind::Torus, 48);
  const auto mesh = dir / "sphere.ply";
  std::string output;
  ASSERT_EQ(runCommand(cliPath().string() + " -q extract " + sphere.string() + " -o " + mesh.string(), &output), 0);
  EXPECT_EQ(runCommand(cliPath().string() + " -q check " + mesh.string() + " --against " + torus.string(), &output), 1)
      << output;
  EXPECT_NE(output.find("the mesh does NOT match it"), std::string::npos) << output;  // the summary
  EXPECT_NE(output.find("passed: NO"), std::string::npos) << output;
  EXPECT_EQ(
      runCommand(cliPath().string() + " -q check " + mesh.string() + " --against " + torus.string() + " --verbose",
                 &output),
      1);
  EXPECT_NE(output.find("topology.matches: false"), std::string::npos) << output;  // every figure
}

// --check fails the run like `isovdb check` does: plain dual contouring (no
// Ju-Udeshi fans) self-intersects on the salt dome; the mesh is still written.
TEST(CliExtract, CheckExitsOneWhenTheMeshFailsIt) {
  TempDir dir;
  const auto salt = writeShape(dir, samples::ShapeKind::SaltDome, 64);
  const auto mesh = dir / "salt.ply";
  const auto stats = dir / "salt.json";
  std::string output;
  EXPECT_EQ(runCommand(cliPath().string() + " -q extract " + salt.string() + " -o " + mesh.string() +
                           " --method adaptive --no-intersection-free --check --stats " + stats.string(),
                       &output),
            1)
      << output;
  const nlohmann::json json = readJson(stats);
  EXPECT_GT(json["check"]["self_intersecting_pairs"].get<int>(), 0);
  EXPECT_FALSE(json["passed"].get<bool>());
  EXPECT_TRUE(std::filesystem::exists(mesh));
  // With the fans the same run passes.
  EXPECT_EQ(runCommand(cliPath().string() + " -q extract " + salt.string() + " -o " + mesh.string() +
                           " --method adaptive --check --stats " + stats.string(),
                       &output),
            0)
      << output;
  EXPECT_TRUE(readJson(stats)["passed"].get<bool>());
}

TEST(CliSdf, WritesALevelSetThatOpenVdbReads) {
  TempDir dir;
  const auto input = writeShape(dir, samples::ShapeKind::Sphere, 48);
  const auto vdb = dir / "sphere.vdb";
  std::string output;
  const auto stats = dir / "sdf.json";
  ASSERT_EQ(runCommand(cliPath().string() + " -q sdf " + input.string() + " -o " + vdb.string() + " --name salt" +
                           " --stats " + stats.string(),
                       &output),
            0)
      << output;
  // Streamed leaf by leaf (the band never held whole); the spill file is gone.
  const nlohmann::json json = readJson(stats);
  EXPECT_TRUE(json["distance_field"]["streamed_to_file"].get<bool>());
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
    files.push_back(entry.path().filename().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"sdf.json", "sphere.nrrd", "sphere.vdb"}));
  openvdb::initialize();
  openvdb::io::File file(vdb.string());
  file.open();
  auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("salt"));
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->getGridClass(), openvdb::GRID_LEVEL_SET);
  EXPECT_LT(grid->tree().getValue(openvdb::Coord(24, 24, 24)), 0.f);  // centre is inside
  EXPECT_GT(grid->tree().getValue(openvdb::Coord(0, 0, 0)), 0.f);
  EXPECT_EQ(json["distance_field"]["leaf_nodes"].get<std::int64_t>(),
            static_cast<std::int64_t>(grid->tree().leafCount()));
  EXPECT_EQ(json["distance_field"]["active_voxels"].get<std::int64_t>(),
            static_cast<std::int64_t>(grid->activeVoxelCount()));
  file.close();

  // And the .vdb is itself a valid input: contour it directly. It is the field
  // `extract` computes in memory from the same mask, so the meshes are the same bytes
  // where the mask's box plays no part: adaptive mode splits the surface cells that reach
  // past the mask's box (x = 48 here, where its caps would go), and a .vdb has no box. In
  // meta-cells of 16 those cells lie on a meta-cell's boundary, where the error bound's
  // plane test splits them too; in one meta-cell of 128, the .vdb's cells across x = 48 may
  // stay whole (octree::kInteriorPlaneShare).
  ASSERT_EQ(runCommand(cliPath().string() + " -q extract " + vdb.string() + " -o " + (dir / "m.ply").string() +
                           " --meta-cell 16 --check --verbose",
                       &output),
            0)
      << output;
  EXPECT_NE(output.find("check.closed: true"), std::string::npos) << output;
  ASSERT_EQ(runCommand(cliPath().string() + " -q extract " + input.string() + " -o " + (dir / "direct.ply").string() +
                           " --meta-cell 16",
                       &output),
            0)
      << output;
  EXPECT_EQ(readFile(dir / "m.ply"), readFile(dir / "direct.ply"));
}

// --sharp-features through the binary on an exact distance field (.vdb level set
// of a capped cylinder): the flag reaches the octree and the contouring (more
// leaves on the rims) and the mesh keeps the guarantees.
TEST(CliExtract, SharpFeaturesOnALevelSetKeepTheGuarantees) {
  TempDir dir;
  const std::array<double, 3> c{32.41, 31.63, 32.27};
  const volume::Volume cylinder =
      levelSetVolume(64, [&](const std::array<double, 3>& p) { return cylinderSdf(p, c, 14.3, 11.2); });
  const auto vdb = dir / "cylinder.vdb";
  openvdb::initialize();
  const openvdb::FloatGrid::Ptr grid = volume::fieldGridPtr(cylinder);
  grid->setName("cylinder");
  openvdb::io::File(vdb.string()).write(openvdb::GridPtrVec{grid});
  int triangles[2] = {0, 0};
  for (const bool sharp : {false, true}) {
    const auto stats = dir / (sharp ? "sharp.json" : "plain.json");
    std::string output;
    ASSERT_EQ(
        runCommand(cliPath().string() + " -q extract " + vdb.string() + " -o " + (dir / "m.ply").string() +
                       " --method adaptive --max-cell-size 8 --qef-tolerance 0.25 --max-error 0 --check --stats " +
                       stats.string() + (sharp ? " --sharp-features" : ""),
                   &output),
        0)
        << output;
    const nlohmann::json json = readJson(stats);
    EXPECT_EQ(json["meta_cells"]["sharp_features"].get<bool>(), sharp);
    EXPECT_TRUE(json["check"]["closed"].get<bool>());
    EXPECT_EQ(json["check"]["self_intersecting_pairs"].get<int>(), 0);
    EXPECT_EQ(json["check"]["euler_characteristic"].get<int>(), 2);
    triangles[sharp] = json["contour"]["triangles"].get<int>();
  }
  // The rims' leaves are refined (at 0.25 the QEF criterion alone leaves them coarse; the
  // error bound, off here, would refine them too).
  EXPECT_GT(triangles[1], 2 * triangles[0]);
}

TEST(CliExtract, PrintsAShortSummaryAndEveryFigureWithVerbose) {
  TempDir dir;
  const auto torus = writeShape(dir, samples::ShapeKind::Torus, 48);
  const std::string run = cliPath().string() + " -q extract " + torus.string() + " -o " + (dir / "t.ply").string() +
                          " --method regular --check";
  std::string summary, every;
  ASSERT_EQ(runCommand(run, &summary), 0) << summary;
  ASSERT_EQ(runCommand(run + " --verbose", &every), 0) << every;
  const auto lines = [](const std::string& s) { return std::count(s.begin(), s.end(), '\n'); };
  EXPECT_LE(lines(summary), 15) << summary;
  EXPECT_GT(lines(every), 60) << every;
  for (const char* fragment : {"input: ", "distance field: ", "mesh: ", " triangles",
                               "check: closed, manifold, 0 self-intersecting pairs, Euler characteristic 0",
                               "passed: yes", "time: read ", "peak memory: ", "output: "})
    EXPECT_NE(summary.find(fragment), std::string::npos) << fragment << " in\n" << summary;
  EXPECT_NE(every.find("check.euler_characteristic: 0"), std::string::npos) << every;
}

TEST(CliExtract, PreviewDrawsTheStreamedMesh) {
  TempDir dir;
  const auto torus = writeShape(dir, samples::ShapeKind::Torus, 48);
  const auto png = dir / "torus.png";
  std::string output;
  ASSERT_EQ(runCommand(cliPath().string() + " -q extract " + torus.string() + " -o " + (dir / "t.ply").string() +
                           " --method adaptive --preview " + png.string(),
                       &output),
            0)
      << output;
  EXPECT_NE(output.find("preview: " + png.string()), std::string::npos) << output;
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(png.c_str(), &width, &height, &channels, 3);
  ASSERT_NE(pixels, nullptr);
  EXPECT_EQ(width, 800);
  EXPECT_EQ(height, 600);
  std::size_t object = 0;
  for (int i = 0; i < width * height; ++i) object += pixels[3 * i] != mesh::kPreviewBackground;
  stbi_image_free(pixels);
  EXPECT_GT(object, std::size_t(width * height / 20));  // the torus fills part of the picture
  // Only .png; nothing written on the error.
  const auto bad = dir / "torus.jpg";
  EXPECT_EQ(runCommand(cliPath().string() + " -q extract " + torus.string() + " -o " + (dir / "u.ply").string() +
                           " --preview " + bad.string(),
                       &output),
            2);
  EXPECT_NE(output.find("--preview writes a .png"), std::string::npos) << output;
  EXPECT_FALSE(std::filesystem::exists(dir / "u.ply"));
}

TEST(CliInfo, ReportsTheSparseGrid) {
  TempDir dir;
  const auto input = writeShape(dir, samples::ShapeKind::Sphere, 48);
  std::string output;
  ASSERT_EQ(runCommand(cliPath().string() + " -q info " + input.string(), &output), 0) << output;
  for (const char* field : {"input.dims: [48,48,48]", "input.active_voxels:", "input.leaf_nodes:",
                            "input.active_tiles:", "input.grid_memory_bytes:"})
    EXPECT_NE(output.find(field), std::string::npos) << field << " in " << output;
}

TEST(CliHelp, EverySubcommandHasHelp) {
  for (const char* command : {"info", "sdf", "extract", "check"}) {
    std::string output;
    EXPECT_EQ(runCommand(cliPath().string() + " " + command + " --help", &output), 0);
    EXPECT_NE(output.find("Usage"), std::string::npos) << command;
  }
}

}  // namespace
}  // namespace isovdb::test
