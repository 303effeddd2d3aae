// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/mask_rule.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace isovdb::volume {
namespace {

/// Floats around each bound (its neighbours on both sides, several steps out), the
/// extremes, the zeros, infinities and NaN: where classify()'s float comparisons and
/// inside()'s double ones could part.
std::vector<float> valuesAround(const std::vector<double>& bounds) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  std::vector<float> values{0.0f,
                            -0.0f,
                            kInf,
                            -kInf,
                            std::numeric_limits<float>::quiet_NaN(),
                            std::numeric_limits<float>::max(),
                            std::numeric_limits<float>::lowest(),
                            std::numeric_limits<float>::denorm_min(),
                            -std::numeric_limits<float>::denorm_min()};
  for (const double b : bounds) {
    float below = static_cast<float>(b), above = static_cast<float>(b);
    values.push_back(below);
    for (int step = 0; step < 3; ++step) {
      below = std::nextafter(below, -kInf);
      above = std::nextafter(above, kInf);
      values.push_back(below);
      values.push_back(above);
    }
  }
  return values;
}

void expectClassifyAsInside(const MaskRule& rule, const std::vector<float>& values) {
  std::vector<std::uint8_t> out(values.size(), 7);
  rule.classify(values, out.data());
  for (std::size_t i = 0; i < values.size(); ++i)
    EXPECT_EQ(out[i], rule.inside(values[i]) ? 1 : 0)
        << rule.describe() << ", value " << values[i] << " (" << std::hexfloat << values[i] << ")";
}

TEST(MaskRule, ClassifyAgreesWithInsideAtEveryBound) {
  // Bounds a float holds exactly and bounds it does not (0.1, 1e-40 below the normal
  // range, 1e39 beyond the largest float), each way round.
  const std::vector<double> bounds{0.0, 0.5, 0.1, -0.1, 1e-40, -1e-40, 1e39, -1e39, 127.5, 1000.3, -86.0};
  const std::vector<float> values = valuesAround(bounds);
  for (const double t : bounds) {
    expectClassifyAsInside(MaskRule{.test = MaskTest::Above, .threshold = t, .labels = {}}, values);
    expectClassifyAsInside(MaskRule{.test = MaskTest::Below, .threshold = t, .labels = {}}, values);
    for (const double u : bounds)
      if (u >= t)
        expectClassifyAsInside(MaskRule{.test = MaskTest::Between, .threshold = t, .upper = u, .labels = {}}, values);
  }
  expectClassifyAsInside(MaskRule{.labels = {13, 0.1}}, valuesAround({13, 0.1}));
}

TEST(MaskRule, ClassifyFillsEveryByte) {
  // Lengths around a vector register's width, so a vectorised loop's tail is covered.
  for (std::size_t n = 0; n < 70; ++n) {
    std::vector<float> values(n);
    for (std::size_t i = 0; i < n; ++i) values[i] = static_cast<float>(i % 5) - 2.0f;
    std::vector<std::uint8_t> out(n + 1, 7);
    MaskRule{.threshold = 0.0, .labels = {}}.classify(values, out.data());
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(out[i], values[i] > 0.0f ? 1 : 0) << "n " << n << ", i " << i;
    EXPECT_EQ(out[n], 7) << "wrote past the end at n " << n;
  }
}

}  // namespace
}  // namespace isovdb::volume
