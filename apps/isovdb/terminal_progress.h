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

class TerminalProgress : public Interrupter {
 public:
  explicit TerminalProgress(bool enabled);
  void start(const char* name) override;
  void end() override;
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
