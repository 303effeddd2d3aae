// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// SEG-Y end to end through the `isovdb` binary: info, extract (amplitude iso and
// masks, every method, --boundary cap|open checked with the mesh validator),
// convert (.sgy -> .vdb -> .raw) and bad input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <array>
#include <map>
#include <utility>

#include "generators/segy_writer.h"
#include "isovdb/io/ply.h"
#include "isovdb/mesh/validate.h"
#include "support/test_support.h"

namespace isovdb::test {
namespace {

const std::filesystem::path kF3 = dataDir() / "seismic" / "f3.sgy";
// The F3 crop's sample positions in world units: 23 inlines and 18 crosslines
// about 25 m apart, 75 samples every 4 ms from 4 ms.
constexpr int kDims[3] = {23, 18, 75};

std::string cli() { return cliPath().string() + " -q "; }

nlohmann::json runJson(const std::string& arguments, const TempDir& dir) {
  const auto stats = dir / "stats.json";
  std::string output;
  EXPECT_EQ(runCommand(cli() + arguments + " --stats " + stats.string(), &output), 0) << output;
  return nlohmann::json::parse(readFile(stats));
}

/// The survey box in world units, read from the extraction's statistics.
struct WorldBox {
  std::array<double, 3> min, max;
};
WorldBox surveyBox(const nlohmann::json& stats) {
  WorldBox box;
  for (int a = 0; a < 3; ++a) {
    const double spacing = stats["input"]["spacing"][a].get<double>();
    box.min[a] = stats["input"]["origin"][a].get<double>();
    box.max[a] = box.min[a] + spacing * (kDims[a] - 1);
  }
  return box;
}

/// `voxels`: how far beyond a face a cap may lie, in voxels (adaptive mode's caps are made
/// within 2 * 10^-3 voxel of the faces; the other methods' are flattened onto them).
bool onBoxFace(const mesh::Vec3f& p, const mesh::Vec3f& q, const WorldBox& box, const std::array<double, 3>& spacing,
               double voxels) {
  for (int a = 0; a < 3; ++a) {
    const double tolerance = 1e-4 * std::max(1.0, std::abs(box.max[a])) + voxels * spacing[a];
    for (const double plane : {box.min[a], box.max[a]})
      if (std::abs(p[a] - plane) < tolerance && std::abs(q[a] - plane) < tolerance) return true;
  }
  return false;
}

TEST(CliSegy, InfoPrintsGeometryPercentilesAndTheActiveFractionOfAClip) {
  TempDir dir;
  const nlohmann::json stats = runJson("info " + kF3.string() + " --clip 3000", dir);
  const auto& input = stats["input"];
  EXPECT_EQ(input["format"], "segy");
  EXPECT_EQ(input["segy"]["inlines"]["first"], 111);
  EXPECT_EQ(input["segy"]["crosslines"]["last"], 892);
  EXPECT_EQ(input["segy"]["sample_interval_us"], 4000.0);
  EXPECT_EQ(input["samples"]["min"], -10239.0);
  EXPECT_EQ(input["samples"]["max"], 10827.0);
  EXPECT_EQ(input["samples"]["percentiles"]["p50"], 0.0);
  const double fraction = input["samples"]["active_fraction"].get<double>();
  EXPECT_GT(fraction, 0.05);
  EXPECT_LT(fraction, 0.5);
  // The grid keeps exactly the samples outside the dead band.
  EXPECT_EQ(input["active_voxels"].get<std::int64_t>(),
            static_cast<std::int64_t>(std::llround(fraction * kDims[0] * kDims[1] * kDims[2])));
}

TEST(CliSegy, InfoNamesTheRevisionAndTheHeadersItSteppedOver) {
  TempDir dir;
  const auto path = dataDir() / "seismic" / "segyio" / "trace-header-extensions.sgy";
  const nlohmann::json segy = runJson("info " + path.string(), dir)["input"]["segy"];
  EXPECT_EQ(segy["revision"], "2.1");
  EXPECT_EQ(segy["extended_text_headers"], 1);
  EXPECT_EQ(segy["trace_header_extensions"], 2);
  const nlohmann::json stanzas = runJson(
      "info " + (dataDir() / "seismic" / "segyio" / "stanzas-unknown-count.sgy").string(), dir)["input"]["segy"];
  EXPECT_EQ(stanzas["extended_text_headers"], 3);
  EXPECT_TRUE(stanzas["extended_text_headers_ended_by_endtext"].get<bool>());
}

TEST(CliSegy, CappedIsosurfaceIsClosedAndOpenOneEndsOnTheSurveyBoundary) {
  for (const std::string method : {"vdb", "adaptive"}) {
    SCOPED_TRACE(method);
    const double voxels = method == "adaptive" ? 2.01e-3 : 0.0;
    TempDir dir;
    const auto capPly = dir / "cap.ply", openPly = dir / "open.ply";
    const std::string run = "extract " + kF3.string() + " --iso 3000 --clip 1000 --method " + method;
    const nlohmann::json cap = runJson(run + " -o " + capPly.string(), dir);
    const nlohmann::json open = runJson(run + " --boundary open -o " + openPly.string(), dir);
    const WorldBox box = surveyBox(cap);
    std::array<double, 3> spacing{};
    for (int a = 0; a < 3; ++a) spacing[a] = cap["input"]["spacing"][a].get<double>();

    const mesh::Mesh capMesh = io::readPly(capPly);
    const mesh::MeshReport capReport = mesh::validateMesh(capMesh, {.selfIntersections = false});
    EXPECT_GT(capReport.triangles, 10000);
    EXPECT_TRUE(capReport.closed);
    EXPECT_EQ(capReport.boundaryEdges, 0);
    // Some caps lie on the survey faces, none beyond them.
    std::int64_t onFace = 0;
    for (const mesh::Vec3f& p : capMesh.positions)
      for (int a = 0; a < 3; ++a) {
        const double tolerance = 1e-3 + voxels * spacing[a];
        ASSERT_GE(p[a], box.min[a] - tolerance);
        ASSERT_LE(p[a], box.max[a] + tolerance);
        onFace += p[a] <= box.min[a] + tolerance - 1e-3 || p[a] >= box.max[a] - tolerance + 1e-3;
      }
    EXPECT_GT(onFace, 100);

    const mesh::Mesh openMesh = io::readPly(openPly);
    const mesh::MeshReport openReport = mesh::validateMesh(openMesh, {.selfIntersections = false});
    EXPECT_EQ(open["contour"]["cap_triangles_dropped"].get<std::int64_t>(), capReport.triangles - openReport.triangles);
    EXPECT_FALSE(openReport.closed);
    EXPECT_GT(openReport.boundaryEdges, 100);
    EXPECT_EQ(openReport.nonManifoldEdges, 0);
    // Every boundary edge lies on a face of the survey box: the surface is closed elsewhere.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edgeUse;
    for (const mesh::Triangle& t : openMesh.triangles)
      for (int e = 0; e < 3; ++e) {
        const auto [u, v] = std::minmax(t[e], t[(e + 1) % 3]);
        ++edgeUse[{u, v}];
      }
    std::int64_t boundaryEdges = 0;
    for (const auto& [edge, uses] : edgeUse) {
      if (uses != 1) continue;
      ++boundaryEdges;
      ASSERT_TRUE(onBoxFace(openMesh.positions[edge.first], openMesh.positions[edge.second], box, spacing, voxels))
          << "boundary edge inside the survey";
    }
    EXPECT_EQ(boundaryEdges, openReport.boundaryEdges);
  }
}

TEST(CliSegy, EveryMethodAndBothMasksContourTheCube) {
  TempDir dir;
  for (const std::string method : {"vdb", "regular", "adaptive"}) {
    SCOPED_TRACE(method);
    const nlohmann::json stats =
        runJson("extract " + kF3.string() + " --iso -3000 --method " + method + " -o " + (dir / "m.ply").string(), dir);
    EXPECT_EQ(stats["input"]["kind"], "scalar");
    EXPECT_GT(stats["contour"]["triangles"].get<int>(), 5000);
  }
  for (const std::string mask : {"--mask 'above 3000'", "--mask 'below -3000'", "--mask-range 2000,4000"}) {
    SCOPED_TRACE(mask);
    const nlohmann::json stats =
        runJson("extract " + kF3.string() + " " + mask + " --check -o " + (dir / "m.ply").string(), dir);
    EXPECT_EQ(stats["input"]["kind"], "mask");
    EXPECT_GT(stats["contour"]["triangles"].get<int>(), 5000);
    EXPECT_TRUE(stats["check"]["closed"].get<bool>());
  }
}

TEST(CliSegy, ConvertKeepsTheSurveyScaleAndMetadataAndGoesBackToDenseFloats) {
  TempDir dir;
  const auto vdb = dir / "f3.vdb", raw = dir / "f3.raw";
  runJson("convert " + (dataDir() / "seismic" / "f3_format1_ibm_msb.sgy").string() + " -o " + vdb.string(), dir);
  openvdb::initialize();
  openvdb::io::File file(vdb.string());
  file.open();
  const openvdb::GridBase::Ptr grid = file.readGrid("field");
  file.close();
  const openvdb::Vec3d voxel = grid->voxelSize();
  EXPECT_NEAR(voxel[0], 25.0, 0.01);
  EXPECT_NEAR(voxel[1], 25.0, 0.01);
  EXPECT_EQ(voxel[2], 4.0);
  EXPECT_EQ(grid->indexToWorld(openvdb::Vec3d(0, 0, 0))[2], 4.0);
  EXPECT_EQ(grid->metaValue<std::int32_t>("segy_inline_first"), 111);
  EXPECT_EQ(grid->metaValue<std::int32_t>("segy_crossline_last"), 892);
  EXPECT_EQ(grid->metaValue<double>("segy_sample_interval_us"), 4000.0);

  const nlohmann::json stats = runJson("convert " + vdb.string() + " -o " + raw.string(), dir);
  EXPECT_EQ(stats["output"]["dims"], nlohmann::json::array({23, 18, 75}));
  EXPECT_EQ(std::filesystem::file_size(raw), 23u * 18 * 75 * 4);
  EXPECT_NE(readFile(dir / "f3.nhdr").find("sizes: 23 18 75"), std::string::npos);
  // The dense copy reads back with the same range as the SEG-Y file.
  const nlohmann::json back = runJson("info " + (dir / "f3.nhdr").string() + " --scalar", dir);
  EXPECT_EQ(back["input"]["samples"]["min"], -10239.0);
  EXPECT_EQ(back["input"]["samples"]["max"], 10827.0);
}

class CliSegyBadInput : public ::testing::Test {
 protected:
  TempDir in, out;
  std::filesystem::path cube(const std::string& name, const std::function<void(std::string&)>& damage) {
    const auto path = in / name;
    samples::writeSegyCube(path, {.inlines = 3, .crosslines = 4, .samples = 6}, [](int i, int j, float* trace) {
      for (int k = 0; k < 6; ++k) trace[k] = static_cast<float>(i + j + k);
      return true;
    });
    std::string bytes = readFile(path);
    damage(bytes);
    writeFile(path, bytes);
    return path;
  }
  /// One line "isovdb: error: '<file>': ...<fragment>...", exit 2, nothing written.
  void expectCleanFailure(const std::filesystem::path& input, const std::string& fragment,
                          const std::string& flags = "") {
    std::string output;
    const auto vdb = out / "out.vdb";
    EXPECT_EQ(runCommand(cli() + "convert " + input.string() + " -o " + vdb.string() + " " + flags, &output), 2)
        << output;
    EXPECT_EQ(std::count(output.begin(), output.end(), '\n'), 1) << output;
    EXPECT_EQ(output.rfind("isovdb: error: '" + input.string() + "': ", 0), 0u) << output;
    EXPECT_NE(output.find(fragment), std::string::npos) << output;
    EXPECT_TRUE(std::filesystem::is_empty(out.path())) << "output left behind";
  }
};

TEST_F(CliSegyBadInput, EachProblemIsOneLineNamingTheFileAndNothingIsWritten) {
  expectCleanFailure(cube("truncated.sgy", [](std::string& b) { b.resize(b.size() - 100); }), "truncated");
  expectCleanFailure(cube("text.sgy", [](std::string& b) { b.resize(3200); }), "ends after the textual header");
  expectCleanFailure(cube("count.sgy", [](std::string& b) { b[3221] = 5; }), "not a whole number of");
  expectCleanFailure(cube("format.sgy", [](std::string& b) { b[3225] = 6; }), "unsupported sample format code 6");
  expectCleanFailure(cube("monotonic.sgy", [](std::string& b) { b[3600 + 8 * 264 + 191] = 1; }), "are not monotonic");
  expectCleanFailure(cube("duplicate.sgy", [](std::string&) {}), "both have inline", "--crossline-byte 189");
  expectCleanFailure(cube("nosuchfield.sgy", [](std::string&) {}), "--inline-byte 3 is not", "--inline-byte 3");
  // The extension is not needed with --segy.
  expectCleanFailure(cube("cube.dat", [](std::string& b) { b.resize(3300); }), "ends after the textual header",
                     "--segy");
}

}  // namespace
}  // namespace isovdb::test
