// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb check MESH [--against VOLUME]`: the mesh validator, and the topology of
// the mesh compared with the voxel object it claims to represent.
#include "commands.h"
#include "input_flags.h"
#include "isovdb/io/mesh_file.h"
#include "isovdb/pipeline/mesh_report.h"

namespace isovdb::cli {

void addCheckCommand(CLI::App& app, Context& context) {
  struct State {
    std::string mesh, against, statsPath;
    InputFlags flags;
    bool noSelfIntersections = false;
    int adjacency = 26;
  };
  auto state = std::make_shared<State>();
  CLI::App* command =
      app.add_subcommand("check",
                         "Validate a mesh: closed, manifold, self-intersections, Euler characteristic and genus. "
                         "Exit status 1 when a guarantee fails.");
  command->add_option("MESH", state->mesh, "Mesh file (.ply, .obj, .stl or .glb)")->required();
  command->add_option("--against", state->against,
                      "Volume the mesh represents: compare chi(mesh) with 2*chi(solid) "
                      "(see --adjacency); the input flags below say how to read it");
  command
      ->add_option("--adjacency", state->adjacency,
                   "With --against: 26 (inside voxels touching at an edge or a corner are connected) or 6 "
                   "(faces only, background through faces and edges: the reading regular mode follows "
                   "apart from Wenger's fixes)")
      ->check(CLI::IsMember({6, 26}))
      ->capture_default_str();
  command->add_flag("--no-self-intersections", state->noSelfIntersections, "Skip the self-intersection test");
  command->add_option("--stats", state->statsPath, "Also write the figures as JSON");
  state->flags.add(*command);
  command->callback([state, &context] {
    checkFilesBeforeWork({{"the mesh", state->mesh}, {"--against", state->against}}, {{"--stats", state->statsPath}});
    pipeline::Statistics stats;
    mesh::Mesh mesh;
    {
      pipeline::Statistics::StageTimer timer(&stats, "read");
      mesh = io::readMesh(state->mesh);
    }
    mesh::MeshReport report;
    {
      pipeline::Statistics::StageTimer timer(&stats, "check");
      report = mesh::validateMesh(mesh, {.selfIntersections = !state->noSelfIntersections});
    }
    stats["mesh"] = pipeline::toJson(report);
    bool ok = pipeline::passesGuarantees(report);
    if (!state->against.empty()) {
      pipeline::Statistics::StageTimer timer(&stats, "volume_topology");
      const std::int64_t solid = pipeline::solidEulerCharacteristic(
          state->against, state->flags.toOptions(state->against),
          state->adjacency == 6 ? volume::Adjacency::Foreground6 : volume::Adjacency::Foreground26,
          context.interrupter());
      auto& topology = stats["topology"];
      topology["volume"] = state->against;
      topology["adjacency"] = state->adjacency == 6 ? "(6,18)" : "(26,6)";
      topology["solid_euler_characteristic"] = solid;
      topology["expected_mesh_euler_characteristic"] = 2 * solid;
      topology["mesh_euler_characteristic"] = report.eulerCharacteristic;
      const bool matches = report.eulerCharacteristic == 2 * solid;
      topology["matches"] = matches;
      ok = ok && matches;
    }
    stats["passed"] = ok;
    reportStatistics(stats, state->statsPath, context);
    context.exitCode = ok ? 0 : 1;
  });
}

}  // namespace isovdb::cli
