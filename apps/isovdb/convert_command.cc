// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb convert IN -o OUT`: a volume to another format — SEG-Y or any input to a
// sparse .vdb grid (transform and survey metadata kept), or a .vdb to dense float32
// (.raw with a .nhdr header beside it, or .nrrd) for interchange.
#include "commands.h"
#include "input_flags.h"
#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/store/dense_writer.h"
#include "isovdb/store/vdb_file.h"
#include "isovdb/pipeline/load_volume.h"

namespace isovdb::cli {

void addConvertCommand(CLI::App& app, Context& context) {
  struct State {
    std::string input, output, statsPath, gridName;
    InputFlags flags;
  };
  auto state = std::make_shared<State>();
  CLI::App* command = app.add_subcommand(
      "convert", "Volume -> sparse .vdb grid (SEG-Y keeps its survey metadata), or -> dense float32 .raw/.nrrd");
  command
      ->add_option("IN", state->input, "Volume file (.sgy, .segy, .vdb, .raw, .nrrd, .nhdr, .mhd, .mha, .nii, .nii.gz)")
      ->required();
  command
      ->add_option("-o,--output", state->output,
                   "Output: .vdb (sparse grid), .nrrd (dense float32) or .raw (dense float32, little-endian, "
                   "x fastest, with an NRRD header OUT.nhdr beside it)")
      ->required();
  command->add_option("--name", state->gridName, ".vdb output: grid name (default: field, mask or sdf by kind)");
  command->add_option("--stats", state->statsPath, "Also write the figures as JSON");
  state->flags.add(*command);
  command->callback([state, &context] {
    const bool toVdb = pipeline::isVdbPath(state->output);
    if (!toVdb && !store::isDenseOutputPath(state->output))
      throw InputError("'" + state->output + "': unknown output format, expected .vdb, .nrrd or .raw");
    checkFilesBeforeWork({{"the input", state->input}}, {{"-o", state->output}, {"--stats", state->statsPath}});
    pipeline::Statistics stats;
    const volume::Volume input =
        pipeline::loadVolume(state->input, state->flags.toOptions(state->input), context.interrupter(), &stats);
    {
      pipeline::Statistics::StageTimer timer(&stats, "write");
      stats["output"]["path"] = state->output;
      if (toVdb) {
        store::writeVdb(state->output, input, {.gridName = state->gridName});
      } else {
        const store::DenseWriteResult written = store::writeDenseVolume(state->output, input);
        stats["output"]["dims"] = written.dims;
        stats["output"]["sample_type"] = "float32 little-endian";
        stats["output"]["header"] = written.header.string();
      }
    }
    reportStatistics(stats, state->statsPath, context);
  });
}

}  // namespace isovdb::cli
