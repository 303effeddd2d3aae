// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/distance_field.h"

#include <openvdb/tools/LevelSetUtil.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tools/SignedFloodFill.h>

#include <mutex>

#include "isovdb/volume/band_chunks.h"
#include "isovdb/volume/sampled_box.h"

namespace isovdb::volume {

void checkDistanceFieldOptions(const DistanceFieldOptions& options) {
  if (options.halfWidth < 1 || options.halfWidth > 64)
    throw InputError("distance field: half-width " + std::to_string(options.halfWidth) +
                     " is out of range, expected 1..64 voxels");
  // Closing by N dilates and erodes N voxels, each a pass over the grown mask: 64 already
  // fills any cavity narrower than 128 voxels, and 10^6 ran for minutes.
  if (options.closingSteps < 0 || options.closingSteps > 64)
    throw InputError("distance field: closing steps " + std::to_string(options.closingSteps) +
                     " is out of range, expected 0..64");
  if (options.chunkSize < 0 || options.chunkSize % 8 != 0)
    throw InputError("distance field: chunk size " + std::to_string(options.chunkSize) +
                     " must be 0 or a positive multiple of 8 voxels");
}

Volume distanceField(const Volume& mask, const DistanceFieldOptions& options, Interrupter* interrupter) {
  const MaskGrid& grid = maskGrid(mask);
  checkDistanceFieldOptions(options);
  FieldGrid::Ptr sdf;
  if (options.chunkSize == 0 && options.method == DistanceMethod::Tracker) {
    ProgressStage progress(interrupter, "distance field");
    sdf = bandOf(grid, options, interrupter);
    progress.update(1, 1);
  } else {
    sdf = FieldGrid::create(static_cast<float>(options.halfWidth));
    std::mutex adding;
    computeBandInChunks(
        grid, options,
        [&sdf, &adding](std::vector<std::unique_ptr<FieldLeaf>>&& leaves) {
          const std::lock_guard<std::mutex> lock(adding);
          for (auto& leaf : leaves) sdf->tree().addLeaf(leaf.release());
        },
        interrupter);
    // Inactive space between chunks' bands: negative inside, positive outside.
    openvdb::tools::signedFloodFill(sdf->tree());
    openvdb::tools::pruneLevelSet(sdf->tree());
  }
  sdf->setTransform(openvdb::math::Transform::createLinearTransform(1.0));
  sdf->setName("sdf");
  sdf->setGridClass(openvdb::GRID_LEVEL_SET);
  Volume field(VolumeKind::DistanceField, sdf, mask.geometry(), mask.name());
  // The field covers the mask's index space: where the data ended travels with it (to_numpy's
  // default box, caps on the data boundary).
  if (const std::optional<IndexBox> box = sampledBox(mask)) setSampledBox(field, *box);
  return field;
}

Volume interiorMask(const Volume& sdf, double iso) {
  if (sdf.kind() != VolumeKind::DistanceField)
    throw InputError("'" + sdf.name() + "': interior mask needs a distance field");
  MaskGrid::Ptr mask = openvdb::tools::sdfInteriorMask(fieldGrid(sdf), static_cast<float>(iso));
  return Volume(VolumeKind::Mask, mask, sdf.geometry(), sdf.name());
}

}  // namespace isovdb::volume
