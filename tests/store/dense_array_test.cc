// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// io/dense_array.h: a box of a sparse volume copied into a dense [x][y][z] array.
#include <gtest/gtest.h>

#include <vector>

#include "isovdb/errors.h"
#include "isovdb/store/dense_array.h"
#include "isovdb/volume/ingest.h"
#include "support/vector_slice_stream.h"

namespace isovdb::store {
namespace {

float sample(int x, int y, int z) { return static_cast<float>(100 * x + 10 * y + z); }

TEST(DenseArray, ScalarBoxIsCopiedInCOrderWithBackgroundOutside) {
  auto stream = test::VectorSliceStream::fromFunction({5, 4, 3}, sample);
  const volume::Volume field = volume::ingestScalar(stream);
  const volume::IndexBox box = defaultDenseBox(field);
  EXPECT_EQ(box.max, (std::array<int, 3>{4, 3, 2}));

  const volume::IndexBox wider{.min = {3, 2, 1}, .max = {5, 3, 2}};  // x = 5 lies outside the data
  std::vector<float> out(3 * 2 * 2, -1.f);
  copyToDense(field, wider, out.data());
  std::size_t i = 0;
  for (int x = 3; x <= 5; ++x)
    for (int y = 2; y <= 3; ++y)
      for (int z = 1; z <= 2; ++z, ++i) EXPECT_EQ(out[i], x <= 4 ? sample(x, y, z) : 0.f) << x << y << z;
}

TEST(DenseArray, MaskCopiesToBoolAndKindsAreChecked) {
  auto stream = test::VectorSliceStream::fromFunction(
      {6, 6, 6}, [](int x, int y, int z) { return x == 2 && y == 3 && z == 4 ? 1.f : 0.f; });
  const volume::Volume mask = volume::ingestMask(stream, {});
  std::vector<char> out(6 * 6 * 6, 1);
  copyToDense(mask, defaultDenseBox(mask), reinterpret_cast<bool*>(out.data()));
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_EQ(out[i], i == (2 * 6 + 3) * 6 + 4 ? 1 : 0) << i;
  std::vector<float> floats(out.size());
  EXPECT_THROW(copyToDense(mask, defaultDenseBox(mask), floats.data()), InputError);
}

}  // namespace
}  // namespace isovdb::store
