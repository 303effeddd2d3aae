// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// isovdb: sparse volumes to clean triangle meshes. Parses arguments and runs one
// subcommand; all the work is in the library (pipeline/).
#include <cstdio>

#include "commands.h"
#include "isovdb/errors.h"
#include "isovdb/pipeline/memory.h"

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
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const Interrupted&) {
    std::fprintf(stderr, "isovdb: interrupted\n");
    return 130;
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
