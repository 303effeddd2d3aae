// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb info IN`: what a volume file holds and what its sparse grid costs.
#include "commands.h"
#include "input_flags.h"
#include "isovdb/store/vdb_file.h"
#include "isovdb/pipeline/load_volume.h"

namespace isovdb::cli {

void addInfoCommand(CLI::App& app, Context& context) {
  struct State {
    std::string input;
    InputFlags flags;
    std::string statsPath;
  };
  auto state = std::make_shared<State>();
  CLI::App* command = app.add_subcommand(
      "info",
      "Describe a volume: header (SEG-Y geometry), value range and percentiles, fraction active for --clip, "
      "active voxels, leaves, tiles, memory");
  command
      ->add_option("IN", state->input, "Volume file (.raw, .nrrd, .nhdr, .mhd, .mha, .nii, .nii.gz, .sgy, .segy, .vdb)")
      ->required();
  command->add_option("--stats", state->statsPath, "Also write the figures as JSON");
  state->flags.add(*command);
  command->callback([state, &context] {
    pipeline::Statistics stats;
    if (pipeline::isVdbPath(state->input)) {
      auto& grids = stats["grids"];
      grids = pipeline::Statistics::Json::array();
      for (const store::VdbGridInfo& grid : store::listVdbGrids(state->input))
        grids.push_back({{"name", grid.name}, {"value_type", grid.valueType}, {"class", grid.gridClass}});
    }
    pipeline::InputOptions options = state->flags.toOptions(state->input);
    options.sampleStatistics = !pipeline::isVdbPath(state->input);  // range, percentiles, active fraction
    pipeline::loadVolume(state->input, options, context.interrupter(), &stats);
    reportStatistics(stats, state->statsPath, context, /*everyFigure=*/true);  // the figures are the report
  });
}

}  // namespace isovdb::cli
