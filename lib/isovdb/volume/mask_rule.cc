// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/mask_rule.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "isovdb/errors.h"

namespace isovdb::volume {

namespace {

/// The largest float at most `t`, and the smallest at least `t`: for a float v, v > t iff
/// v > floatBelow(t), v < t iff v < floatAbove(t) (and likewise for >=, <=), so the
/// comparisons run on floats as they are stored, several per instruction.
float floatBelow(double t) {
  const auto f = static_cast<float>(t);
  return static_cast<double>(f) > t ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float floatAbove(double t) {
  const auto f = static_cast<float>(t);
  return static_cast<double>(f) < t ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

template <class Inside>
void classifyWith(const float* __restrict values, std::size_t n, std::uint8_t* __restrict out, Inside inside) {
  for (std::size_t i = 0; i < n; ++i) out[i] = inside(values[i]) ? 1 : 0;
}

}  // namespace

void MaskRule::classify(std::span<const float> values, std::uint8_t* out) const {
  // The same answers as inside() (NaN is never inside).
  const float* in = values.data();
  const std::size_t n = values.size();
  if (!labels.empty()) {
    classifyWith(in, n, out, [this](float v) { return inside(v); });
    return;
  }
  switch (test) {
    case MaskTest::Above:
      classifyWith(in, n, out, [t = floatBelow(threshold)](float v) { return v > t; });
      return;
    case MaskTest::Below:
      classifyWith(in, n, out, [t = floatAbove(threshold)](float v) { return v < t; });
      return;
    case MaskTest::Between:
      classifyWith(in, n, out,
                   [lo = floatAbove(threshold), hi = floatBelow(upper)](float v) { return v >= lo && v <= hi; });
      return;
  }
}

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
