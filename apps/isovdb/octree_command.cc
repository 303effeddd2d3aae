// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb octree IN [--index I,J,K] [extract's flags]`: look at the octree of one meta-cell.
#include "commands.h"
#include "input_flags.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/pipeline/inspect_octree.h"
#include "isovdb/pipeline/load_volume.h"
#include "setting_flags.h"

namespace isovdb::cli {

void addOctreeCommand(CLI::App& app, Context& context) {
  struct State {
    std::string input, statsPath, wireframe;
    std::vector<int> index;
    InputFlags flags;
    pipeline::ExtractChoices choices;
  };
  auto state = std::make_shared<State>();
  // vdb builds no octree: the inspector's default is the octree method extract would
  // be asked for.
  state->choices.method = std::string(pipeline::contourMethodName(pipeline::ContourMethod::Adaptive));
  CLI::App* command = app.add_subcommand(
      "octree",
      "Build one meta-cell's octree and report per-level cells, complex edges and faces. It takes extract's "
      "flags and builds exactly the tree extract builds with them");
  command->add_option("IN", state->input, "Volume file")->required();
  command->add_option("--index", state->index, "Meta-cell index I,J,K (default: the first one the surface crosses)")
      ->delimiter(',')
      ->expected(3);
  command->add_option("--wireframe", state->wireframe, "Write the surface leaf cells as a wireframe PLY");
  command->add_option("--stats", state->statsPath, "Also write the figures as JSON");
  addSettingFlags(*command, pipeline::extractSettings(state->choices));
  state->flags.add(*command);
  command->callback([state, &context] {
    pipeline::InspectOctreeOptions options;
    options.extract = state->choices.resolve();
    if (!state->index.empty())
      options.metaCell = volume::MetaCellIndex{state->index[0], state->index[1], state->index[2]};
    checkFilesBeforeWork({{"the input", state->input}},
                         {{"--wireframe", state->wireframe}, {"--stats", state->statsPath}});
    if (!state->wireframe.empty()) options.wireframe = state->wireframe;
    pipeline::Statistics stats;
    const volume::Volume input =
        pipeline::loadVolume(state->input, state->flags.toOptions(state->input), context.interrupter(), &stats);
    pipeline::inspectOctree(input, options, stats, context.interrupter());
    reportStatistics(stats, state->statsPath, context);
  });
}

}  // namespace isovdb::cli
