// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/memory.h"

#include <malloc.h>

#include <fstream>
#include <string>

namespace isovdb::pipeline {

namespace {

std::int64_t statusField(const char* key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::string prefix = std::string(key) + ":";
  while (std::getline(status, line)) {
    if (line.rfind(prefix, 0) == 0) return std::stoll(line.substr(prefix.size())) * 1024;  // kB
  }
  return 0;
}

}  // namespace

std::int64_t peakRssBytes() { return statusField("VmHWM"); }
std::int64_t currentRssBytes() { return statusField("VmRSS"); }

void keepFreedHeapMemory() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
}

}  // namespace isovdb::pipeline
