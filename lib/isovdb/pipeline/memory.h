/// @file memory.h
/// @brief Resident memory of this process, from /proc/self/status (Linux).
#pragma once

#include <cstdint>

namespace isovdb::pipeline {

/// Peak resident set size (VmHWM) in bytes; 0 when unavailable.
std::int64_t peakRssBytes();
/// Current resident set size (VmRSS) in bytes; 0 when unavailable.
std::int64_t currentRssBytes();

}  // namespace isovdb::pipeline
