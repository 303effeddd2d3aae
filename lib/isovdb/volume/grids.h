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

/// @brief Calls `visit(box)` with the bounding box of every active tile of `tree` (root and
///        internal-node values), without visiting its leaves' voxels.
/// A tree's ValueOn iterator steps through every active voxel to reach the tiles (its depth
/// bound is compiled out of OpenVDB 10), which on a dense 256^3 field took longer than the
/// meta-cell partition the tiles were wanted for.
template <typename TreeT, typename Visit>
void forEachActiveTile(const TreeT& tree, Visit&& visit) {
  static_assert(TreeT::DEPTH == 4, "a root, two internal levels and leaves (openvdb::tree::Tree4)");
  using Upper = typename TreeT::RootNodeType::ChildNodeType;
  using Lower = typename Upper::ChildNodeType;
  using Leaf = typename Lower::ChildNodeType;
  for (auto tile = tree.root().cbeginValueOn(); tile; ++tile)
    visit(openvdb::CoordBBox::createCube(tile.getCoord(), Upper::DIM));
  for (auto upper = tree.root().cbeginChildOn(); upper; ++upper) {
    for (auto tile = upper->cbeginValueOn(); tile; ++tile)
      visit(openvdb::CoordBBox::createCube(tile.getCoord(), Lower::DIM));
    for (auto lower = upper->cbeginChildOn(); lower; ++lower)
      for (auto tile = lower->cbeginValueOn(); tile; ++tile)
        visit(openvdb::CoordBBox::createCube(tile.getCoord(), Leaf::DIM));
  }
}

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
