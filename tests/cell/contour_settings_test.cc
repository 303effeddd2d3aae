// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// The names of the contouring settings (named_values.h's tables): the names users type,
// the round trip, and the message that lists them.
#include "isovdb/cell/contour_settings.h"

#include <gtest/gtest.h>

#include <string>

namespace isovdb::cell {
namespace {

TEST(ContourSettings, EveryMethodNameParsesBackToItsMethod) {
  for (const auto& [method, name] : kContourMethodNames) {
    EXPECT_EQ(contourMethodName(method), name);
    EXPECT_EQ(parseContourMethod(name), method);
  }
  EXPECT_EQ(parseContourMethod("Adaptive"), std::nullopt);  // names are exact
  EXPECT_EQ(parseRegularTopology("mdmc"), RegularTopology::Mdmc);
  EXPECT_EQ(regularTopologyName(RegularTopology::Voxels), "voxels");
}

TEST(ContourSettings, UnknownNameIsAnInputErrorListingTheNamesInOrder) {
  EXPECT_EQ(nameList(kContourMethodNames), "vdb, regular or adaptive");
  EXPECT_EQ(nameList(kRegularTopologyNames), "voxels or mdmc");
  try {
    parseNamed(kContourMethodNames, "marching", "--method", "method");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--method: unknown method 'marching', expected vdb, regular or adaptive");
  }
  EXPECT_EQ(parseNamed(kContourMethodNames, "regular", "--method", "method"), ContourMethod::Regular);
}

}  // namespace
}  // namespace isovdb::cell
