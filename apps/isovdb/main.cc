// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// isovdb: sparse volumes to clean triangle meshes. Parses arguments and runs one
// subcommand; all the work is in the library (pipeline/).
#include <csignal>
#include <cstdio>

#include "commands.h"
#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/pipeline/memory.h"
#include "terminal_progress.h"

int main(int argc, char** argv) {
  using namespace isovdb;
  pipeline::keepFreedHeapMemory();
  CLI::App app{"isovdb: turns large sparse volumes into clean triangle meshes"};
  app.require_subcommand(1);
  app.fallthrough();
  cli::Context context;
  app.add_flag("-q,--quiet", context.quiet, "No progress on stderr");
  app.add_flag(
      "-v,--verbose", context.verbose,
      "Print every figure of the run (\"section.key: value\"), not the summary (--stats FILE writes them as JSON)");
  cli::addInfoCommand(app, context);
  cli::addSdfCommand(app, context);
  cli::addExtractCommand(app, context);
  cli::addCheckCommand(app, context);
  cli::addCompareCommand(app, context);
  cli::addOctreeCommand(app, context);
  cli::addConvertCommand(app, context);
  cli::addMorphCommand(app, context);
  cli::addReservoirCommand(app, context);
  cli::installInterruptSignals();
  try {
    // Every output of the command, or none of them: a failure after the first output
    // (the disk filling while the statistics follow the mesh) removes them all.
    io::CommitGroup outputs;
    app.parse(argc, argv);
    outputs.commitAll();
  } catch (const CLI::ParseError& e) {
    // CLI11 prints the message; its own codes (105, 114, ...) become the usage error 2,
    // as for every other bad option, and --help stays 0.
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const Interrupted&) {
    // Temporary outputs are gone by now (their owners unwound); 128 + signal, as a shell reports it.
    std::fprintf(stderr, "isovdb: interrupted\n");
    return cli::interruptSignal() == SIGTERM ? 128 + SIGTERM : 128 + SIGINT;
  } catch (const InputError& e) {
    std::fprintf(stderr, "isovdb: error: %s\n", e.what());
    return 2;
  } catch (const IoError& e) {
    std::fprintf(stderr, "isovdb: error: %s\n", e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "isovdb: error: out of memory\n");
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "isovdb: internal error: %s\n", e.what());
    return 3;
  }
  return context.exitCode;
}
