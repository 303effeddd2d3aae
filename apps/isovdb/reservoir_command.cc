// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb reservoir GRID.grdecl [MORE.grdecl...] --property NAME --iso V -o OUT.ply`:
// isosurface of a cell property of a corner-point reservoir grid (paper 003).
#include <iostream>

#include "commands.h"
#include "mesh_follow_ups.h"
#include "isovdb/errors.h"
#include "isovdb/io/mesh_file.h"
#include "isovdb/pipeline/reservoir_extract.h"

namespace isovdb::cli {

void addReservoirCommand(CLI::App& app, Context& context) {
  struct State {
    std::vector<std::string> inputs;
    std::string output, statsPath, tessellate;
    pipeline::ReservoirOptions options;
    MeshFollowUps followUps;
  };
  auto state = std::make_shared<State>();
  CLI::App* command =
      app.add_subcommand("reservoir",
                         "Corner-point grid (Eclipse GRDECL) -> isosurface of a cell property (Marching Cubes on "
                         "hexahedra, Jacobian normals)");
  command->add_option("GRID", state->inputs, "GRDECL deck, then optional files with more keywords (properties)")
      ->required();
  command->add_option("--property", state->options.property, "Cell property keyword (PORO, FACIES, PERMX, ...)")
      ->required();
  command->add_option("--iso", state->options.iso, "Iso-value")->required();
  command->add_option("-o,--output", state->output, "Output mesh: .ply (binary), .obj or .glb with normals, or .stl")
      ->required();
  command->add_option("--tessellate", state->tessellate, "max=K: curved PN triangles, per-edge factors up to K");
  command->add_option("--stats", state->statsPath, "Also write the figures as JSON");
  state->followUps.addFlags(*command);
  command->add_option("--threads", state->options.threads, "Worker threads (0 = every core); the output is the same")
      ->capture_default_str();
  command
      ->add_option("--max-values", state->options.limits.maxValues,
                   "Most values the deck's keywords may hold together (n*value repeats counted); a guard "
                   "against hostile decks")
      ->capture_default_str();
  command->callback([state, &context] {
    for (const auto& input : state->inputs) state->options.inputs.emplace_back(input);
    if (!state->tessellate.empty()) {
      const std::string prefix = "max=";
      if (state->tessellate.rfind(prefix, 0) != 0)
        throw InputError("--tessellate: expected max=K, got '" + state->tessellate + "'");
      try {
        state->options.maxTessellation = std::stoi(state->tessellate.substr(prefix.size()));
      } catch (const std::exception&) {
        throw InputError("--tessellate: K must be an integer, got '" + state->tessellate + "'");
      }
      if (state->options.maxTessellation < 1 || state->options.maxTessellation > 64)
        throw InputError("--tessellate: K must be between 1 and 64");
    }
    std::vector<NamedFile> inputs;
    for (const auto& input : state->inputs) inputs.push_back({"the input", input});
    io::checkMeshPath(state->output);
    state->followUps.checkPreviewPath();
    checkFilesBeforeWork(
        inputs, {{"-o", state->output}, {"--stats", state->statsPath}, {"--preview", state->followUps.previewPath}});
    pipeline::Statistics stats;
    // With the check, the Marching Cubes mesh's self-intersecting pairs are told apart by the
    // cells that made them (statistics reservoir.self_intersecting_pairs).
    state->options.attributeSelfIntersections = state->followUps.check && !state->followUps.noSelfIntersections;
    const mesh::Mesh mesh = pipeline::extractReservoir(state->options, stats, context.interrupter());
    {
      pipeline::Statistics::StageTimer timer(&stats, "write");
      io::writeMesh(state->output, mesh);
    }
    for (const auto& w : stats["reservoir"]["warnings"])
      std::cerr << "isovdb: warning: " << w.get<std::string>() << '\n';
    stats["output"]["path"] = state->output;
    stats["output"]["triangles"] = mesh.triangleCount();
    stats["output"]["vertices"] = mesh.vertexCount();
    // A reservoir surface ends where the grid, its active cells or the property do: open by design.
    const bool passed = state->followUps.checkMesh(mesh, /*openByDesign=*/true, stats);
    state->followUps.drawPreview(mesh, stats);
    reportStatistics(stats, state->statsPath, context);
    // Like `isovdb check`: a mesh that fails the check is written, and the run exits 1.
    context.exitCode = passed ? 0 : 1;
  });
}

}  // namespace isovdb::cli
