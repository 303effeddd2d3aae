// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file huge_pages.h
/// @brief Large arrays backed by transparent huge pages (Linux), for the stages that
///        build whole-grid arrays at once (the reservoir reader, grid and marching cubes).
///
/// The first touch of fresh memory costs a page fault per 4 KiB page, and on a virtual
/// machine each fault is expensive: on a 1.5 M-cell deck (119 MB of text, 288 MB of
/// corners) reading took 3.0 s and the grid 2.2 s, mostly in faults; with 2 MiB pages
/// 1.0 s and 1.1 s. Debian's default THP mode is "madvise": a region must ask. The
/// request is advice only: nothing changes where the kernel or the build has no THP.
/// (The grid's per-point arrays once slowed the Marching Cubes stage after them by a third;
/// filled layer by layer into arrays reserved at their final size, they no longer do.)
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace isovdb {

/// Advises huge pages for the 2 MiB-aligned part of [data, data + bytes), before it is
/// first touched (arrays of a few MiB and more: glibc maps those fresh from the kernel).
inline void adviseHugePages(const void* data, std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHuge - 1);
  if (data != nullptr && end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

/// `values.reserve(count)` with the new storage advised huge pages (a std::vector or a
/// std::string).
template <class Container>
void reserveHuge(Container& values, std::size_t count) {
  if (count <= values.capacity()) return;
  values.reserve(count);
  adviseHugePages(values.data(), count * sizeof(typename Container::value_type));
}

/// Room for `extra` more values at the end of `values` (arrays appended to a cell at a
/// time): capacity doubled, from 64 KiB (a small grid's arrays never reach a huge page, whose
/// first touch clears 2 MiB), into new storage advised huge pages before the old values move
/// in (`vector::reserve` would copy them into 4 KiB pages first).
template <class Container>
void growHuge(Container& values, std::size_t extra) {
  if (values.size() + extra <= values.capacity()) return;
  using Value = typename Container::value_type;
  Container grown;
  reserveHuge(grown, std::max({values.size() + extra, 2 * values.capacity(), (std::size_t{64} << 10) / sizeof(Value)}));
  grown.insert(grown.end(), std::make_move_iterator(values.begin()), std::make_move_iterator(values.end()));
  values.swap(grown);
}

/// `values.resize(count)` (value-initialised) into storage advised huge pages first.
template <class Container>
void resizeHuge(Container& values, std::size_t count) {
  reserveHuge(values, count);
  values.resize(count);
}

/// `values.assign(count, fill)` into storage advised huge pages first.
template <class Container>
void assignHuge(Container& values, std::size_t count, const typename Container::value_type& fill) {
  reserveHuge(values, count);
  values.assign(count, fill);
}

}  // namespace isovdb
