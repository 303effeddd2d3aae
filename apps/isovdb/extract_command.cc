// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb extract IN -o OUT.ply`: the main job, volume -> closed triangle mesh.
#include <filesystem>

#include "commands.h"
#include "input_flags.h"
#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/io/mesh_file.h"
#include "isovdb/io/path_util.h"
#include "isovdb/io/ply.h"
#include "isovdb/pipeline/extract.h"
#include "isovdb/pipeline/extract_to_file.h"
#include "isovdb/pipeline/load_volume.h"
#include "mesh_follow_ups.h"
#include "setting_flags.h"

namespace isovdb::cli {

void addExtractCommand(CLI::App& app, Context& context) {
  struct State {
    std::string input, output, statsPath;
    InputFlags flags;
    pipeline::ExtractChoices choices;
    MeshFollowUps followUps;
  };
  auto state = std::make_shared<State>();
  CLI::App* command = app.add_subcommand("extract", "Volume -> triangle mesh (.ply, .obj, .stl or .glb)");
  command
      ->add_option("IN", state->input, "Volume file (.raw, .nrrd, .nhdr, .mhd, .mha, .nii, .nii.gz, .sgy, .segy, .vdb)")
      ->required();
  command->add_option("-o,--output", state->output, "Output mesh (.ply binary, .obj, .stl or .glb)")->required();
  addSettingFlags(*command, pipeline::extractSettings(state->choices));
  state->followUps.addFlags(*command);
  command->add_option("--stats", state->statsPath, "Write every figure shown as JSON");
  state->flags.add(*command);
  command->callback([state, &context] {
    mesh::Mesh mesh;
    const pipeline::ExtractOptions options = state->choices.resolve();
    const MeshFollowUps& followUps = state->followUps;
    io::checkMeshPath(state->output);
    followUps.checkPreviewPath();
    checkFilesBeforeWork({{"the input", state->input}},
                         {{"-o", state->output}, {"--stats", state->statsPath}, {"--preview", followUps.previewPath}});

    pipeline::Statistics stats;
    volume::Volume input =
        pipeline::loadVolume(state->input, state->flags.toOptions(state->input), context.interrupter(), &stats);
    // Without --check the octree methods stream a .ply meta-cell by meta-cell (the mesh
    // is never held whole); --check needs the mesh in memory. The input is moved in so
    // that a mask is freed once its distance field exists.
    std::uint64_t triangles = 0;
    // A picture of a streamed .ply reads it back; an .obj with a picture is held like --check.
    const bool holdMesh =
        followUps.check || (!followUps.previewPath.empty() && io::lowerExtension(state->output) != ".ply");
    if (!holdMesh) {
      triangles = pipeline::extractToFile(std::move(input), options, state->output, context.interrupter(), &stats);
    } else {
      mesh = pipeline::extractMesh(std::move(input), options, context.interrupter(), &stats);
      triangles = mesh.triangles.size();
      pipeline::Statistics::StageTimer timer(&stats, "write");
      io::writeMesh(state->output, mesh);
    }
    if (triangles == 0)
      std::fprintf(stderr, "isovdb: warning: '%s': no surface at iso %g (empty mesh)\n", state->input.c_str(),
                   stats["contour"].value("iso", 0.0));
    stats["output"]["path"] = state->output;
    // --boundary open asks for a mesh that ends on the data boundary: not closed by design.
    const bool passed = followUps.checkMesh(mesh, options.boundary == pipeline::BoundaryMode::Open, stats);
    // A streamed mesh was never held whole: the picture reads it back (from its temporary:
    // the outputs are renamed together at the end, io::CommitGroup).
    if (!followUps.previewPath.empty())
      followUps.drawPreview(holdMesh ? mesh : io::readPly(io::CommitGroup::readablePath(state->output)), stats);
    reportStatistics(stats, state->statsPath, context);
    // Like `isovdb check`: a mesh that fails the check is written, and the run exits 1.
    context.exitCode = passed ? 0 : 1;
  });
}

}  // namespace isovdb::cli
