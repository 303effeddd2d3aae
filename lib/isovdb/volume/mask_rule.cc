// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/mask_rule.h"

#include <cmath>
#include <sstream>

#include "isovdb/errors.h"

namespace isovdb::volume {

std::string MaskRule::describe() const {
  std::ostringstream out;
  if (!labels.empty()) {
    out << "label in {";
    for (std::size_t i = 0; i < labels.size(); ++i) out << (i ? "," : "") << labels[i];
    out << "}";
    return out.str();
  }
  switch (test) {
    case MaskTest::Above:
      out << "value > " << threshold;
      break;
    case MaskTest::Below:
      out << "value < " << threshold;
      break;
    case MaskTest::Between:
      out << "value in [" << threshold << ", " << upper << "]";
      break;
  }
  return out.str();
}

MaskRule parseMaskText(const std::string& text) {
  std::istringstream in(text);
  std::string word;
  double bound = 0;
  std::string rest;
  const auto fail = [&] { return InputError("--mask: expected 'above A' or 'below A', got '" + text + "'"); };
  if (!(in >> word >> bound) || (in >> rest) || !std::isfinite(bound)) throw fail();
  MaskRule rule;
  rule.threshold = bound;
  if (word == "above")
    rule.test = MaskTest::Above;
  else if (word == "below")
    rule.test = MaskTest::Below;
  else
    throw fail();
  return rule;
}

}  // namespace isovdb::volume
