// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file commands.h
/// @brief The subcommands of `isovdb`. Each file registers one; none holds an algorithm.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <string>
#include <vector>

#include "isovdb/pipeline/statistics.h"
#include "terminal_progress.h"

namespace isovdb::cli {

/// State shared by all subcommands: global flags and the exit code of the one that ran.
struct Context {
  bool quiet = false;
  bool verbose = false;  ///< print every figure, not the summary
  int exitCode = 0;
  std::unique_ptr<TerminalProgress> progress;
  TerminalProgress* interrupter() {
    if (!progress) progress = std::make_unique<TerminalProgress>(!quiet);
    return progress.get();
  }
};

void addInfoCommand(CLI::App& app, Context& context);
void addSdfCommand(CLI::App& app, Context& context);
void addExtractCommand(CLI::App& app, Context& context);
void addCheckCommand(CLI::App& app, Context& context);
void addCompareCommand(CLI::App& app, Context& context);
void addOctreeCommand(CLI::App& app, Context& context);
void addConvertCommand(CLI::App& app, Context& context);
void addMorphCommand(CLI::App& app, Context& context);
void addReservoirCommand(CLI::App& app, Context& context);

/// A file named on the command line, and the option (or argument) that named it.
struct NamedFile {
  std::string option;  ///< "-o", "--stats", "the input", ...
  std::string path;    ///< empty: not given
};

/// Before any work: every output can be written (its folder exists and is writable),
/// and no output names the same file as an input or another output (`--stats` equal
/// to `-o`, or `-o` equal to the input, would silently overwrite it).
/// @throw InputError naming both options; IoError when an output cannot be written.
void checkFilesBeforeWork(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs);

/// Prints a statistics report on stdout: every figure as "section.key: value" lines,
/// or a summary of at most ~15 lines (input, what was built, the check, time, memory, output).
void printStatistics(const pipeline::Statistics& stats, bool everyFigure);

/// The end of every subcommand: the peak memory recorded, the figures written to
/// `statsPath` as JSON (when not empty) and printed on stdout, summarised unless
/// `--verbose` or `everyFigure` (`--quiet` silences the progress on stderr, not the figures).
void reportStatistics(pipeline::Statistics& stats, const std::string& statsPath, const Context& context,
                      bool everyFigure = false);

}  // namespace isovdb::cli
