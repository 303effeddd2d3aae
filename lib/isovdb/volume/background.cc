// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/background.h"

#include <openvdb/tools/ChangeBackground.h>

#include "isovdb/volume/grids.h"

namespace isovdb::volume {

Volume withBackground(const Volume& volume, float background) {
  const FieldGrid::Ptr grid = fieldGrid(volume).deepCopy();
  openvdb::tools::changeBackground(grid->tree(), background);
  return Volume(volume.kind(), grid, volume.geometry(), volume.name());
}

}  // namespace isovdb::volume
