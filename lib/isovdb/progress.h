// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file progress.h
/// @brief Progress reporting and cancellation, modelled on openvdb::util::NullInterrupter.
///
/// Long-running functions take an optional `Interrupter*` (default nullptr),
/// call start()/end() around each stage and wasInterrupted(percent) per
/// meta-cell, slab or leaf batch (never per voxel). When wasInterrupted()
/// returns true the function throws isovdb::Interrupted.
#pragma once

#include <string>

#include "isovdb/errors.h"

namespace isovdb {

class Interrupter {
 public:
  virtual ~Interrupter() = default;
  /// A named stage begins.
  virtual void start(const char* /*name*/) {}
  /// The current stage ends.
  virtual void end() {}
  /// Reports progress in percent (-1: unknown) and asks whether to stop.
  /// @note Must be thread-safe: TBB tasks call it concurrently.
  virtual bool wasInterrupted(int /*percent*/ = -1) { return false; }
};

/// RAII stage bracket that tolerates a null interrupter.
class ProgressStage {
 public:
  ProgressStage(Interrupter* interrupter, const char* name) : interrupter_(interrupter) {
    if (interrupter_) interrupter_->start(name);
  }
  ~ProgressStage() {
    if (interrupter_) interrupter_->end();
  }
  ProgressStage(const ProgressStage&) = delete;
  ProgressStage& operator=(const ProgressStage&) = delete;

  /// Reports `done` of `total` work units; throws Interrupted on cancellation.
  void update(double done, double total) const {
    if (!interrupter_) return;
    const int percent = total > 0 ? static_cast<int>(100.0 * done / total) : -1;
    if (interrupter_->wasInterrupted(percent)) throw Interrupted();
  }

 private:
  Interrupter* interrupter_;
};

}  // namespace isovdb
