// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb compare A B [--max-distance E]`: how far two meshes of one surface are
// apart (the sampled two-sided Hausdorff distance), e.g. adaptive against regular.
#include <cmath>
#include <string>

#include "commands.h"
#include "isovdb/io/mesh_file.h"
#include "isovdb/mesh/mesh_distance.h"

namespace isovdb::cli {

namespace {

/// A distance option's check: a finite number, above zero or at least zero.
/// (CLI::PositiveNumber's message printed a garbage number in place of the value.)
CLI::Validator finiteDistance(bool zeroAllowed) {
  return CLI::Validator(
      [zeroAllowed](const std::string& text) {
        double value = 0;
        if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || value < 0 ||
            (!zeroAllowed && value == 0))
          return std::string(zeroAllowed ? "expected a finite number >= 0" : "expected a positive finite number") +
                 " (mesh units), got '" + text + "'";
        return std::string();
      },
      zeroAllowed ? "DISTANCE" : "POSITIVE");
}

pipeline::Statistics::Json toJson(const mesh::OneSidedDistance& d) {
  return {{"samples", d.samples}, {"mean", d.mean}, {"p99", d.p99}, {"max", d.max}, {"farthest", d.farthest}};
}

}  // namespace

void addCompareCommand(CLI::App& app, Context& context) {
  struct State {
    std::string a, b, statsPath;
    double spacing = 0.25;
    double maxDistance = -1.0;
  };
  auto state = std::make_shared<State>();
  CLI::App* command = app.add_subcommand(
      "compare",
      "Distance between two meshes of one surface (e.g. adaptive against regular): the two-sided Hausdorff "
      "distance, sampled, with mean and 99th percentile each way, in mesh units. Exit status 1 when it exceeds "
      "--max-distance.");
  command->add_option("A", state->a, "First mesh (.ply, .obj, .stl or .glb)")->required();
  command->add_option("B", state->b, "Second mesh (.ply, .obj, .stl or .glb)")->required();
  command
      ->add_option("--spacing", state->spacing,
                   "Largest gap between samples on a triangle (mesh units); the true distance is at most the "
                   "sampled one plus spacing/sqrt(3)")
      ->check(finiteDistance(/*zeroAllowed=*/false))
      ->capture_default_str();
  command
      ->add_option("--max-distance", state->maxDistance,
                   "Fail (exit 1) when the sampled two-sided distance exceeds this (mesh units)")
      ->check(finiteDistance(/*zeroAllowed=*/true));
  command->add_option("--stats", state->statsPath, "Also write the figures as JSON");
  command->callback([state, &context] {
    checkFilesBeforeWork({{"mesh A", state->a}, {"mesh B", state->b}}, {{"--stats", state->statsPath}});
    pipeline::Statistics stats;
    mesh::Mesh a, b;
    {
      pipeline::Statistics::StageTimer timer(&stats, "read");
      a = io::readMesh(state->a);
      b = io::readMesh(state->b);
    }
    mesh::MeshDistance distance;
    {
      pipeline::Statistics::StageTimer timer(&stats, "compare");
      distance = mesh::compareMeshes(a, b, {.spacing = state->spacing});
    }
    auto& section = stats["distance"];
    section["a"] = state->a;
    section["b"] = state->b;
    section["spacing"] = distance.spacing;
    section["a_to_b"] = toJson(distance.aToB);
    section["b_to_a"] = toJson(distance.bToA);
    section["hausdorff"] = distance.hausdorff();
    section["upper_bound"] = distance.upperBound();
    const bool ok = state->maxDistance < 0.0 || distance.hausdorff() <= state->maxDistance;
    if (state->maxDistance >= 0.0) {
      section["max_distance"] = state->maxDistance;
      stats["passed"] = ok;
    }
    reportStatistics(stats, state->statsPath, context, /*everyFigure=*/true);
    context.exitCode = ok ? 0 : 1;
  });
}

}  // namespace isovdb::cli
