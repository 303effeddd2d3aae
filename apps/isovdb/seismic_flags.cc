// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "seismic_flags.h"

namespace isovdb::cli {

void SeismicFlags::add(CLI::App& command) {
  command.add_flag("--segy", segy, "Read the input as SEG-Y whatever its extension (.sgy/.segy are SEG-Y anyway)");
  command.add_option("--inline-byte", inlineByte, "SEG-Y: trace header byte of the inline number")
      ->capture_default_str();
  command.add_option("--crossline-byte", crosslineByte, "SEG-Y: trace header byte of the crossline number")
      ->capture_default_str();
  command.add_option("--clip", clip,
                     "Scalars (SEG-Y amplitude): samples with |value| < CLIP stay inactive; the grid's background "
                     "is CLIP (default 0: keep every sample)");
  command.add_option("--mask", mask, "Mask: inside = \"above A\" (value > A) or \"below A\" (value < A)");
  command.add_option("--mask-range", maskRange, "Mask: inside = LO <= value <= HI")->delimiter(',')->expected(2);
}

void SeismicFlags::fill(pipeline::InputChoices& choices) const {
  choices.segy = segy;
  choices.segyBytes = io::SegyOptions{.inlineByte = inlineByte, .crosslineByte = crosslineByte};
  choices.clip = clip;
  choices.mask = mask;
  if (!maskRange.empty()) choices.maskRange = std::array<double, 2>{maskRange[0], maskRange[1]};
}

}  // namespace isovdb::cli
