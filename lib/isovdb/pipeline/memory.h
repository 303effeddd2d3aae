// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file memory.h
/// @brief Resident memory of this process, from /proc/self/status (Linux).
#pragma once

#include <cstdint>

namespace isovdb::pipeline {

/// Peak resident set size (VmHWM) in bytes; 0 when unavailable.
std::int64_t peakRssBytes();
/// Current resident set size (VmRSS) in bytes; 0 when unavailable.
std::int64_t currentRssBytes();

/// Asks glibc's malloc to keep freed memory for reuse: blocks under 32 MiB come from
/// the heap instead of fresh mmaps (glibc's own ceiling for its adaptive threshold)
/// and up to 256 MiB of free heap stays mapped per arena. Without it every meta-cell
/// re-faults the pages of the octree and mesh buffers the previous one freed (the
/// worker threads' arenas are trimmed at each free): 173,000 page faults and a
/// third of the run in the kernel on 512^3 blobs, regular mode (47,000 with it).
/// Process-wide; front ends call it once at start-up.
void keepFreedHeapMemory();

}  // namespace isovdb::pipeline
