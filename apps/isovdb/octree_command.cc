// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb octree IN [--meta-cell I,J,K]`: look at the octree of one meta-cell.
#include "commands.h"
#include "input_flags.h"
#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/pipeline/inspect_octree.h"
#include "isovdb/pipeline/load_volume.h"

namespace isovdb::cli {

void addOctreeCommand(CLI::App& app, Context& context) {
  struct State {
    std::string input, statsPath, wireframe, construction = "adaptive";
    std::vector<int> metaCell;
    InputFlags flags;
    pipeline::InspectOctreeOptions options;
  };
  auto state = std::make_shared<State>();
  CLI::App* command =
      app.add_subcommand("octree", "Build one meta-cell's octree and report per-level cells, complex edges and faces");
  command->add_option("IN", state->input, "Volume file")->required();
  command->add_option("--meta-cell", state->metaCell, "Meta-cell index I,J,K (default: first one with surface)")
      ->delimiter(',')
      ->expected(3);
  command->add_option("--meta-cell-size", state->options.metaCellSize, "Meta-cell edge in voxels (power of two)")
      ->capture_default_str();
  command->add_option("--construction", state->construction, "regular or adaptive")->capture_default_str();
  command
      ->add_option("--min-level", state->options.octree.minDepth,
                   "Uniform subdivision down to this depth under the meta-cell")
      ->capture_default_str();
  command
      ->add_option("--max-level", state->options.octree.maxDepth,
                   "Deepest level under the meta-cell (-1: 1-voxel cells)")
      ->capture_default_str();
  command->add_option("--finest-size", state->options.octree.finestCellSize,
                      "Smallest leaf in voxels (1, 2, 4, ...; overrides --max-level)");
  command
      ->add_option("--qef-tolerance", state->options.octree.qefTolerance,
                   "Adaptive: also split leaves whose QEF residual (voxels, RMS) exceeds this; <0 off")
      ->capture_default_str();
  command->add_option("--iso", state->options.octree.iso, "Isovalue (voxels on distance fields)")
      ->capture_default_str();
  command->add_option("--wireframe", state->wireframe, "Write the surface leaf cells as a wireframe PLY");
  command->add_option("--stats", state->statsPath, "Also write the figures as JSON");
  state->flags.add(*command);
  command->callback([state, &context] {
    if (state->construction == "regular")
      state->options.octree.construction = octree::OctreeConstruction::Regular;
    else if (state->construction != "adaptive")
      throw InputError("--construction: unknown '" + state->construction + "', expected regular or adaptive");
    if (!state->metaCell.empty())
      state->options.metaCell = volume::MetaCellIndex{state->metaCell[0], state->metaCell[1], state->metaCell[2]};
    if (!state->wireframe.empty()) {
      io::AtomicFile::checkWritable(state->wireframe);
      state->options.wireframe = state->wireframe;
    }
    pipeline::Statistics stats;
    const volume::Volume input =
        pipeline::loadVolume(state->input, state->flags.toOptions(state->input), context.interrupter(), &stats);
    pipeline::inspectOctree(input, state->options, stats, context.interrupter());
    stats.recordMemory();
    if (!state->statsPath.empty()) stats.write(state->statsPath);
    printStatistics(stats);
  });
}

}  // namespace isovdb::cli
