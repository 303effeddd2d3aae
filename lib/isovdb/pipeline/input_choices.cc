// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/input_choices.h"

#include <cmath>

#include "isovdb/errors.h"

namespace isovdb::pipeline {

InputOptions resolveInputChoices(const std::filesystem::path& path, const InputChoices& choices) {
  InputOptions options;
  options.raw = choices.raw;
  options.gridName = choices.grid;
  options.clip = choices.clip;
  options.denseAs = choices.scalar ? DenseAs::Scalar : DenseAs::Mask;
  options.rule.threshold = choices.threshold.value_or(0.0);
  options.rule.labels = choices.labels;
  if (choices.segy || io::isSegyPath(path)) options.segy = choices.segyBytes;

  const bool otherMask = choices.threshold.has_value() || !choices.labels.empty();
  const bool ownMask = !choices.mask.empty() || choices.maskRange.has_value();
  if (!choices.mask.empty() && choices.maskRange) throw InputError("--mask and --mask-range exclude each other");
  if (ownMask && otherMask) throw InputError("--mask/--mask-range exclude --threshold and --labels");
  if (!choices.mask.empty()) {
    options.rule = volume::parseMaskText(choices.mask);
  } else if (choices.maskRange) {
    const auto [lo, hi] = *choices.maskRange;
    if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi))
      throw InputError("--mask-range: expected LO,HI with LO <= HI, got " + std::to_string(lo) + "," +
                       std::to_string(hi));
    options.rule = volume::MaskRule{.test = volume::MaskTest::Between, .threshold = lo, .upper = hi, .labels = {}};
  }
  if (ownMask)
    options.denseAs = DenseAs::Mask;
  else if (options.segy && !otherMask)
    options.denseAs = DenseAs::Scalar;
  return options;
}

}  // namespace isovdb::pipeline
