// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Every contouring method writes outward-facing triangles (counter-clockwise seen
// from outside) on every input kind: the signed volume of each closed component is
// positive around a body and negative around a cavity.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "support/test_support.h"

namespace isovdb::test {
namespace {

constexpr int kSize = 40;
constexpr double kRadius = 12.0;

double distanceFromCentre(int x, int y, int z) {
  const double dx = x - 19.6, dy = y - 20.3, dz = z - 19.8;
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

/// An NRRD of kSize^3 samples of `type` ("uint8" or "float") from `value(x, y, z)`.
std::filesystem::path writeNrrd(const TempDir& dir, const std::string& name, const std::string& type,
                                const std::function<double(int, int, int)>& value) {
  std::string bytes = "NRRD0004\ntype: " + type + "\ndimension: 3\nsizes: 40 40 40\nencoding: raw\nendian: little\n\n";
  for (int z = 0; z < kSize; ++z)
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const double v = value(x, y, z);
        if (type == "uint8") {
          bytes.push_back(static_cast<char>(v));
        } else {
          const float f = static_cast<float>(v);
          char raw[4];
          std::memcpy(raw, &f, 4);
          bytes.append(raw, 4);
        }
      }
  const auto path = dir / (name + ".nrrd");
  writeFile(path, bytes);
  return path;
}

/// Runs extract with --check and returns the check's figures.
nlohmann::json extractChecked(const TempDir& dir, const std::string& input, const std::string& flags) {
  const auto mesh = dir / "mesh.ply", stats = dir / "stats.json";
  std::string output;
  EXPECT_EQ(runCommand(cliPath().string() + " -q extract " + input + " " + flags + " -o " + mesh.string() +
                           " --check --no-self-intersections --stats " + stats.string(),
                       &output),
            0)
      << flags << ": " << output;
  return nlohmann::json::parse(readFile(stats))["check"];
}

/// Every closed component faces the way `sign` says (+1 bodies, -1 cavities); the whole mesh too.
void expectFacing(const nlohmann::json& check, int sign, const std::string& what) {
  ASSERT_TRUE(check["closed"].get<bool>()) << what;
  EXPECT_GT(sign * check["signed_volume"].get<double>(), 0.0) << what;
  for (const auto& component : check["largest_components"])
    EXPECT_GT(sign * component["signed_volume"].get<double>(), 0.0) << what;
}

TEST(CliOrientation, EveryMethodFacesOutwardOnEveryInputKind) {
  TempDir dir;
  const auto mask = writeNrrd(dir, "mask", "uint8",
                              [](int x, int y, int z) { return distanceFromCentre(x, y, z) < kRadius ? 1.0 : 0.0; });
  // A scalar field high inside (a body at iso 0.5; at 0 the background, 0, would count as inside) and one high outside:
  // its inside reaches the data box, and without the caps (--boundary open) only the ball's surface is left, around a
  // cavity.
  const auto bump =
      writeNrrd(dir, "bump", "float", [](int x, int y, int z) { return kRadius - distanceFromCentre(x, y, z); });
  const auto radius =
      writeNrrd(dir, "radius", "float", [](int x, int y, int z) { return distanceFromCentre(x, y, z); });
  // A level set .vdb, as `isovdb sdf` writes it.
  const auto levelSet = dir / "sphere.vdb";
  std::string output;
  ASSERT_EQ(runCommand(cliPath().string() + " -q sdf " + mask.string() + " -o " + levelSet.string(), &output), 0)
      << output;
  // A SEG-Y amplitude cube at an iso in its positive lobes.
  const auto segy = dataDir() / "seismic" / "f3.sgy";
  for (const std::string method : {"vdb", "regular", "adaptive"}) {
    const std::string m = " --method " + method;
    expectFacing(extractChecked(dir, mask.string(), m), +1, method + " mask");
    expectFacing(extractChecked(dir, levelSet.string(), m), +1, method + " level set");
    expectFacing(extractChecked(dir, bump.string(), m + " --scalar --iso 0.5"), +1, method + " scalar, high inside");
    expectFacing(extractChecked(dir, radius.string(), m + " --scalar --iso 12 --boundary open"), -1,
                 method + " scalar, high outside");
    const nlohmann::json seismic = extractChecked(dir, segy.string(), m + " --iso 3700");
    EXPECT_GT(seismic["signed_volume"].get<double>(), 0.0) << method << " SEG-Y";
    EXPECT_GT(seismic["largest_components"][0]["signed_volume"].get<double>(), 0.0) << method << " SEG-Y";
  }
}

}  // namespace
}  // namespace isovdb::test
