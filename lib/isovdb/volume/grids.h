// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file grids.h
/// @brief Typed access to a Volume's OpenVDB grid. Heavy (includes openvdb.h):
///        include it only from .cc files.
#pragma once

#include <openvdb/openvdb.h>
#include <openvdb/util/NullInterrupter.h>

#include "isovdb/errors.h"
#include "isovdb/progress.h"
#include "isovdb/volume/volume.h"

namespace isovdb::volume {

using MaskGrid = openvdb::BoolGrid;
using FieldGrid = openvdb::FloatGrid;
using FieldLeaf = FieldGrid::TreeType::LeafNodeType;

/// The mask grid of a VolumeKind::Mask volume. @throw InputError for another kind.
const MaskGrid& maskGrid(const Volume& volume);
/// The float grid of a Scalar or DistanceField volume. @throw InputError for a mask.
const FieldGrid& fieldGrid(const Volume& volume);
FieldGrid::Ptr fieldGridPtr(const Volume& volume);

}  // namespace isovdb::volume

namespace isovdb::volume::detail {

/// Forwards OpenVDB's interrupter protocol to ours, so OpenVDB tools report
/// progress and honour cancellation through the caller's Interrupter.
struct VdbInterrupter : openvdb::util::NullInterrupter {
  explicit VdbInterrupter(Interrupter* target) : target_(target) {}
  void start(const char* name = nullptr) override {
    if (target_) target_->start(name ? name : "openvdb");
  }
  void end() override {
    if (target_) target_->end();
  }
  bool wasInterrupted(int percent = -1) override { return target_ && target_->wasInterrupted(percent); }

 private:
  Interrupter* target_;
};

}  // namespace isovdb::volume::detail
