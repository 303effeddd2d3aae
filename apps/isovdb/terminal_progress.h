// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file terminal_progress.h
/// @brief Progress on stderr for work longer than a second; `--quiet` disables it.
#pragma once

#include <chrono>
#include <mutex>
#include <string>
#include <vector>

#include "isovdb/progress.h"

namespace isovdb::cli {

/// Makes SIGINT and SIGTERM cancel the run instead of killing the process: the next
/// wasInterrupted() returns true, so the work unwinds and its temporary output files
/// are removed. A second signal ends the process at once (the default action).
void installInterruptSignals();
/// The signal that asked the run to stop; 0 when none did.
int interruptSignal();

class TerminalProgress : public Interrupter {
 public:
  explicit TerminalProgress(bool enabled);
  void start(const char* name) override;
  void end() override;
  /// True once a signal installed by installInterruptSignals() arrived; otherwise
  /// prints the stage's progress and returns false.
  bool wasInterrupted(int percent) override;

 private:
  struct Stage {
    std::string name;
    std::chrono::steady_clock::time_point start;
    int lastPercent = -1;
    bool shown = false;
  };
  bool enabled_;
  bool tty_;
  std::mutex mutex_;
  std::vector<Stage> stages_;
};

}  // namespace isovdb::cli
