#include "seismic_flags.h"

#include <cmath>

#include "isovdb/errors.h"

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

void SeismicFlags::apply(const std::string& path, bool otherMask, pipeline::InputOptions& options) const {
  options.clip = clip;
  if (segy || io::isSegyPath(path))
    options.segy = io::SegyOptions{.inlineByte = inlineByte, .crosslineByte = crosslineByte};
  const bool ownMask = !mask.empty() || !maskRange.empty();
  if (!mask.empty() && !maskRange.empty()) throw InputError("--mask and --mask-range exclude each other");
  if (ownMask && otherMask) throw InputError("--mask/--mask-range exclude --threshold and --labels");
  if (!mask.empty()) {
    options.rule = volume::parseMaskText(mask);
  } else if (!maskRange.empty()) {
    if (!(maskRange[0] <= maskRange[1]) || !std::isfinite(maskRange[0]) || !std::isfinite(maskRange[1]))
      throw InputError("--mask-range: expected LO,HI with LO <= HI, got " + std::to_string(maskRange[0]) + "," +
                       std::to_string(maskRange[1]));
    options.rule = volume::MaskRule{.test = volume::MaskTest::Between, .threshold = maskRange[0], .upper = maskRange[1], .labels = {}};
  }
  if (ownMask) options.denseAs = pipeline::DenseAs::Mask;
  else if (options.segy && !otherMask) options.denseAs = pipeline::DenseAs::Scalar;
}

}  // namespace isovdb::cli
