// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include <cstdio>

#include "commands.h"

namespace isovdb::cli {

namespace {

void printValue(const std::string& key, const pipeline::Statistics::Json& value) {
  if (value.is_object()) {
    for (const auto& [name, child] : value.items()) printValue(key.empty() ? name : key + "." + name, child);
    return;
  }
  if (value.is_array() && !value.empty() && value.front().is_object()) {
    for (std::size_t i = 0; i < value.size(); ++i) printValue(key + "[" + std::to_string(i) + "]", value[i]);
    return;
  }
  std::printf("%s: %s\n", key.c_str(), value.is_string() ? value.get<std::string>().c_str() : value.dump().c_str());
}

}  // namespace

void printStatistics(const pipeline::Statistics& stats) { printValue("", stats.json()); }

void reportStatistics(pipeline::Statistics& stats, const std::string& statsPath) {
  stats.recordMemory();
  if (!statsPath.empty()) stats.write(statsPath);
  printStatistics(stats);
}

}  // namespace isovdb::cli
