// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/cell/contour_settings.h"

namespace isovdb::cell {

std::string_view contourMethodName(ContourMethod method) {
  switch (method) {
    case ContourMethod::Vdb:
      return "vdb";
    case ContourMethod::Regular:
      return "regular";
    case ContourMethod::Adaptive:
      return "adaptive";
  }
  return "unknown";
}

std::optional<ContourMethod> parseContourMethod(std::string_view name) {
  for (const ContourMethod method : {ContourMethod::Vdb, ContourMethod::Regular, ContourMethod::Adaptive})
    if (name == contourMethodName(method)) return method;
  return std::nullopt;
}

std::string_view regularTopologyName(RegularTopology topology) {
  return topology == RegularTopology::Voxels ? "voxels" : "mdmc";
}

std::optional<RegularTopology> parseRegularTopology(std::string_view name) {
  for (const RegularTopology topology : {RegularTopology::Voxels, RegularTopology::Mdmc})
    if (name == regularTopologyName(topology)) return topology;
  return std::nullopt;
}

}  // namespace isovdb::cell
