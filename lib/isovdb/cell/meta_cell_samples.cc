// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/cell/meta_cell_samples.h"

#include <algorithm>
#include <string>

#include "isovdb/errors.h"

namespace isovdb::cell {

void MetaCellSamples::allocate(int newSize, std::array<int, 3> newOrigin, float fill, int newApron) {
  reshape(newSize, newOrigin, newApron);
  std::fill(values.begin(), values.end(), fill);
}

void MetaCellSamples::reshape(int newSize, std::array<int, 3> newOrigin, int newApron) {
  if (newSize < 1 || newSize > (1 << 16) || (newSize & (newSize - 1)) != 0)
    throw InputError("meta-cell size: expected a power of two in [1, 65536], got " + std::to_string(newSize));
  if (newApron < 1 || newApron > newSize)
    throw InputError("meta-cell apron: expected 1.." + std::to_string(newSize) + " samples, got " +
                     std::to_string(newApron));
  size = newSize;
  apron = newApron;
  origin = newOrigin;
  boxRim.active = false;
  const std::size_t n = static_cast<std::size_t>(newSize + 1 + 2 * newApron);
  values.resize(n * n * n);
}

}  // namespace isovdb::cell
