// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// pipeline/input_choices.h: front-end choices resolved into InputOptions.
#include <gtest/gtest.h>

#include "isovdb/errors.h"
#include "isovdb/pipeline/input_choices.h"

namespace isovdb::pipeline {
namespace {

TEST(InputChoices, DenseFilesAreMasksAboveZeroByDefault) {
  const InputOptions options = resolveInputChoices("v.nrrd", {});
  EXPECT_EQ(options.denseAs, DenseAs::Mask);
  EXPECT_EQ(options.rule.test, volume::MaskTest::Above);
  EXPECT_EQ(options.rule.threshold, 0.0);
  EXPECT_FALSE(options.segy);
}

TEST(InputChoices, SegyIsAnAmplitudeFieldUnlessAMaskIsChosen) {
  InputChoices choices;
  choices.segyBytes = {.inlineByte = 9, .crosslineByte = 21};
  InputOptions options = resolveInputChoices("cube.SGY", choices);
  ASSERT_TRUE(options.segy);
  EXPECT_EQ(options.segy->inlineByte, 9);
  EXPECT_EQ(options.denseAs, DenseAs::Scalar);

  choices.threshold = 5.0;
  EXPECT_EQ(resolveInputChoices("cube.sgy", choices).denseAs, DenseAs::Mask);

  choices = {};
  choices.segy = true;
  choices.maskRange = std::array<double, 2>{-1.0, 2.0};
  options = resolveInputChoices("cube.bin", choices);
  ASSERT_TRUE(options.segy);
  EXPECT_EQ(options.denseAs, DenseAs::Mask);
  EXPECT_EQ(options.rule.test, volume::MaskTest::Between);
  EXPECT_EQ(options.rule.upper, 2.0);
}

TEST(InputChoices, ContradictionsAreRejected) {
  InputChoices both;
  both.mask = "above 1";
  both.maskRange = std::array<double, 2>{0.0, 1.0};
  EXPECT_THROW(resolveInputChoices("a.sgy", both), InputError);
  InputChoices withLabels;
  withLabels.labels = {3};
  withLabels.mask = "below 0";
  EXPECT_THROW(resolveInputChoices("a.nrrd", withLabels), InputError);
  InputChoices reversed;
  reversed.maskRange = std::array<double, 2>{2.0, 1.0};
  EXPECT_THROW(resolveInputChoices("a.nrrd", reversed), InputError);
}

}  // namespace
}  // namespace isovdb::pipeline
