// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file statistics.h
/// @brief Every figure a run shows (counts, timings per stage, memory), kept as
///        ordered JSON so `--stats OUT.json` writes exactly what was shown.
#pragma once

#include <chrono>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace isovdb::pipeline {

class Statistics {
 public:
  using Json = nlohmann::ordered_json;

  /// The whole report; sections are objects ("input", "timings_s", "mesh", ...).
  Json& json() { return json_; }
  const Json& json() const { return json_; }
  Json& operator[](const std::string& section) { return json_[section]; }

  /// Records the wall time of a stage under "timings_s", and the resident memory
  /// right after it under "memory", when it goes out of scope.
  class StageTimer {
   public:
    StageTimer(Statistics* stats, std::string stage)
        : stats_(stats), stage_(std::move(stage)), start_(std::chrono::steady_clock::now()) {}
    ~StageTimer() {
      if (!stats_) return;
      const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
      // A stage timed several times (interleaved with another) adds up.
      Json& seconds = stats_->json_["timings_s"][stage_];
      seconds = (seconds.is_number() ? seconds.get<double>() : 0.0) + elapsed.count();
      stats_->recordStageMemory(stage_);
    }
    StageTimer(const StageTimer&) = delete;
    StageTimer& operator=(const StageTimer&) = delete;

   private:
    Statistics* stats_;
    std::string stage_;
    std::chrono::steady_clock::time_point start_;
  };

  /// Records peak and current resident memory under "memory".
  void recordMemory();
  /// Records the peak resident memory so far under "memory.peak_rss_after_<stage>_bytes".
  void recordStageMemory(const std::string& stage);

  /// Writes the report as indented JSON (through a temporary file).
  /// @throw IoError when the path is not writable.
  void write(const std::filesystem::path& path) const;

 private:
  Json json_ = Json::object();
};

}  // namespace isovdb::pipeline
