// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/reservoir/grdecl_edits.h"

#include <algorithm>
#include <stdexcept>

namespace isovdb::reservoir {

CellBox cellBoxOf(const std::array<std::optional<int>, 6>& bounds, const CellBox& defaults,
                  const std::array<int, 3>& dims) {
  static constexpr const char* kNames[6] = {"I1", "I2", "J1", "J2", "K1", "K2"};
  CellBox box = defaults;
  for (int b = 0; b < 6; ++b) {
    if (!bounds[static_cast<std::size_t>(b)]) continue;
    const int axis = b / 2, value = *bounds[static_cast<std::size_t>(b)];
    if (value < 1 || value > dims[static_cast<std::size_t>(axis)])
      throw std::invalid_argument(std::string("box bound ") + kNames[b] + " = " + std::to_string(value) +
                                  " outside 1.." + std::to_string(dims[static_cast<std::size_t>(axis)]));
    (b % 2 == 0 ? box.lo : box.hi)[static_cast<std::size_t>(axis)] = value - 1;
  }
  for (int a = 0; a < 3; ++a) {
    const auto i = static_cast<std::size_t>(a);
    if (box.lo[i] > box.hi[i])
      throw std::invalid_argument(std::string("box bound ") + kNames[2 * a] + " above " + kNames[2 * a + 1]);
    // The defaults (an open BOX) were checked against the grid of their time: SPECGRID may have shrunk it since.
    if (box.lo[i] < 0 || box.hi[i] >= dims[i])
      throw std::invalid_argument(std::string("box ") + kNames[2 * a] + ".." + kNames[2 * a + 1] + " = " +
                                  std::to_string(box.lo[i] + 1) + ".." + std::to_string(box.hi[i] + 1) +
                                  " outside 1.." + std::to_string(dims[i]) +
                                  " (the grid's dimensions changed after BOX)");
  }
  return box;
}

std::string applyPropertyEdit(const PropertyEdit& edit, const std::array<int, 3>& dims,
                              std::map<std::string, std::vector<double>>& properties) {
  const auto cells = static_cast<std::size_t>(dims[0]) * dims[1] * dims[2];
  const auto existing = [&](const std::string& name) -> std::vector<double>* {
    const auto it = properties.find(name);
    return it == properties.end() || it->second.size() != cells ? nullptr : &it->second;
  };
  if (edit.keyword == "COPY") {
    const std::vector<double>* from = existing(edit.name);
    if (!from) return "COPY from " + edit.name + ", which has no value per cell yet";
    std::vector<double> copy = *from;  // `to` may be a new entry of the same map
    std::vector<double>& to = properties[edit.target];
    to.resize(cells, 0.0);
    forEachCell(edit.box, dims, [&](std::size_t c) { to[c] = copy[c]; });
    return {};
  }
  if (edit.keyword == "EQUALS") {
    std::vector<double>& to = properties[edit.name];
    to.resize(cells, 0.0);
    forEachCell(edit.box, dims, [&](std::size_t c) { to[c] = edit.value; });
    return {};
  }
  // The operation chosen once, not per cell.
  using Operation = double (*)(double value, double operand);
  Operation operation = nullptr;
  if (edit.keyword == "MULTIPLY") operation = [](double v, double x) { return v * x; };
  if (edit.keyword == "ADD") operation = [](double v, double x) { return v + x; };
  if (edit.keyword == "MINVALUE") operation = [](double v, double x) { return std::max(v, x); };
  if (edit.keyword == "MAXVALUE") operation = [](double v, double x) { return std::min(v, x); };
  if (!operation) return "unknown edit keyword " + edit.keyword;
  std::vector<double>* values = existing(edit.name);
  if (!values) return edit.keyword + " of " + edit.name + ", which has no value per cell yet";
  forEachCell(edit.box, dims, [&](std::size_t c) { (*values)[c] = operation((*values)[c], edit.value); });
  return {};
}

}  // namespace isovdb::reservoir
