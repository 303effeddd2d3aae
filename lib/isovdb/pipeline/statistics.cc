// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/statistics.h"

#include "isovdb/io/atomic_file.h"
#include "isovdb/pipeline/memory.h"

namespace isovdb::pipeline {

void Statistics::recordMemory() {
  json_["memory"]["peak_rss_bytes"] = peakRssBytes();
  json_["memory"]["current_rss_bytes"] = currentRssBytes();
}

void Statistics::recordStageMemory(const std::string& stage) {
  json_["memory"]["peak_rss_after_" + stage + "_bytes"] = peakRssBytes();
}

void Statistics::write(const std::filesystem::path& path) const {
  io::AtomicFile file(path);
  file.write(json_.dump(2) + "\n");
  file.commit();
}

}  // namespace isovdb::pipeline
