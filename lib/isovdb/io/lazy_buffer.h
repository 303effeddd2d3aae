// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file lazy_buffer.h
/// @brief A vector whose resize() leaves trivial elements uninitialised.
///
/// Slice and slab buffers are sized from the dimensions a file declares. A
/// std::vector zero-fills them, touching every page before one byte of data is
/// read: a 94-byte gzip NRRD declaring 30000 x 30000 samples cost 11.6 GB that
/// way. Left uninitialised, a large buffer's pages stay untouched until data is
/// written into them, so memory follows the bytes actually present.
#pragma once

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace isovdb::io {

/// std::allocator, except that construction without arguments default-initialises.
/// (value_type comes from std::allocator; C++20's allocator_traits rebinds the template
/// itself, so no `rebind` member is needed.)
template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  DefaultInitAllocator() noexcept = default;
  template <class U>
  explicit DefaultInitAllocator(const DefaultInitAllocator<U>& /*other*/) noexcept {}

  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;  // default-, not value-initialised: no zero fill
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

/// A buffer of samples to be overwritten by reading: see the file comment.
template <class T>
using LazyBuffer = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace isovdb::io
