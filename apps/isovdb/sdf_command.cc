// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb sdf IN -o OUT.vdb`: the narrow-band signed distance field as a level-set .vdb.
#include "commands.h"
#include "input_flags.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/pipeline/load_volume.h"
#include "setting_flags.h"
#include "isovdb/pipeline/write_distance_field.h"

namespace isovdb::cli {

void addSdfCommand(CLI::App& app, Context& context) {
  struct State {
    std::string input, output, statsPath, gridName = "sdf";
    InputFlags flags;
    pipeline::DistanceChoices distance;
  };
  auto state = std::make_shared<State>();
  CLI::App* command = app.add_subcommand("sdf", "Binary volume -> narrow-band signed distance field (.vdb level set)");
  command->add_option("IN", state->input, "Volume file")->required();
  command->add_option("-o,--output", state->output, "Output .vdb file")->required();
  addSettingFlags(*command, pipeline::distanceSettings(state->distance));
  command->add_option("--name", state->gridName, "Grid name in the output file")->capture_default_str();
  command->add_option("--stats", state->statsPath, "Also write the figures as JSON");
  state->flags.add(*command);
  command->callback([state, &context] {
    const volume::DistanceFieldOptions distance = state->distance.resolve();
    checkFilesBeforeWork({{"the input", state->input}}, {{"-o", state->output}, {"--stats", state->statsPath}});
    pipeline::Statistics stats;
    const volume::Volume input =
        pipeline::loadVolume(state->input, state->flags.toOptions(state->input), context.interrupter(), &stats);
    pipeline::writeDistanceFieldVdb(input, distance, state->output, state->gridName, context.interrupter(), &stats);
    stats["output"]["path"] = state->output;
    reportStatistics(stats, state->statsPath, context);
  });
}

}  // namespace isovdb::cli
