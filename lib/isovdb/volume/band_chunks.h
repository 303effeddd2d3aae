// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file band_chunks.h
/// @brief The narrow band of a mask computed chunk by chunk and handed out as
///        leaves, so a caller can either keep them (distanceField) or stream them
///        to disk (store::LeafwiseLevelSetWriter) without ever holding the whole band.
///        Heavy (includes openvdb.h through grids.h): include it only from .cc files.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "isovdb/volume/distance_field.h"
#include "isovdb/volume/grids.h"

namespace isovdb::volume {

/// Receives the leaves of one chunk; it owns them from then on. Called from
/// several threads at once (one chunk each), in an order that depends on thread
/// timing: a sink must be thread-safe (store::LeafwiseLevelSetWriter::add is; one
/// that adds to a tree takes a lock).
using BandLeafSink = std::function<void(std::vector<std::unique_ptr<FieldLeaf>>&&)>;

/// The mask closed by `steps` voxels: OpenVDB's face-neighbour dilation then
/// erosion, as topologyToLevelSet does before its band.
MaskGrid::Ptr closedMask(const MaskGrid& mask, int steps);

/// The band of the whole mask with OpenVDB's tools at once: topologyToLevelSet,
/// then (options.redistance) one fast-sweeping pass.
FieldGrid::Ptr bandOf(const MaskGrid& mask, const DistanceFieldOptions& options, Interrupter* interrupter);

/// The band in cubes of options.chunkSize voxels (> 0; Interface: 0 too), each from
/// the mask around it plus a halo, chunks in parallel, by options.method. Every leaf of the band goes to `sink` exactly
/// once, with its inactive values already flood-filled to ±halfWidth (OpenVDB's
/// signedFloodFill leaf rule, which depends on the leaf alone). Leaves without
/// active voxels are handed out too: whether they become tiles is the caller's
/// pruning. Returns the number of chunks.
/// @throw Interrupted on cancellation.
std::size_t computeBandInChunks(const MaskGrid& mask, const DistanceFieldOptions& options, const BandLeafSink& sink,
                                Interrupter* interrupter);

}  // namespace isovdb::volume
