// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/weld.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "isovdb/errors.h"
#include "isovdb/mesh/mesh_checks.h"

namespace isovdb::mesh {

namespace {

struct PositionBits {
  std::uint32_t x, y, z;
  bool operator==(const PositionBits&) const = default;
};

PositionBits bitsOf(const Vec3f& p) {
  return {std::bit_cast<std::uint32_t>(p[0]), std::bit_cast<std::uint32_t>(p[1]), std::bit_cast<std::uint32_t>(p[2])};
}

/// splitmix64's finaliser over the three bit patterns.
std::uint64_t hashBits(const PositionBits& b) {
  std::uint64_t h = (std::uint64_t{b.x} << 32 | b.y) ^ (std::uint64_t{b.z} * 0x9E3779B97F4A7C15ull);
  h ^= h >> 30;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 27;
  h *= 0x94D049BB133111EBull;
  h ^= h >> 31;
  return h;
}

}  // namespace

std::size_t weldVertices(Mesh& mesh) {
  detail::checkIndices(mesh, "weldVertices");
  const std::size_t n = mesh.positions.size();
  if (n == 0) return 0;

  // Open addressing, linear probing; a slot holds 1 + the NEW index of a
  // vertex. New positions are compacted in place in first-occurrence order:
  // entries below `count` are final, so the table may compare against them.
  const std::size_t tableSize = std::bit_ceil(2 * n);
  const std::size_t mask = tableSize - 1;
  std::vector<std::uint32_t> table(tableSize, 0);
  std::vector<std::uint32_t> remap(n);
  const bool hasNormals = !mesh.normals.empty();
  std::uint32_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3f p = mesh.positions[i];
    const PositionBits bits = bitsOf(p);
    std::size_t slot = hashBits(bits) & mask;
    while (true) {
      const std::uint32_t entry = table[slot];
      if (entry == 0) {
        table[slot] = count + 1;
        remap[i] = count;
        mesh.positions[count] = p;
        if (hasNormals) mesh.normals[count] = mesh.normals[i];
        ++count;
        break;
      }
      if (bitsOf(mesh.positions[entry - 1]) == bits) {
        remap[i] = entry - 1;
        break;
      }
      slot = (slot + 1) & mask;
    }
  }

  const std::size_t removed = n - count;
  if (removed == 0) return 0;
  mesh.positions.resize(count);
  mesh.positions.shrink_to_fit();
  if (hasNormals) {
    mesh.normals.resize(count);
    mesh.normals.shrink_to_fit();
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.triangles.size(), 1 << 14),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t t = r.begin(); t != r.end(); ++t)
                        for (std::uint32_t& v : mesh.triangles[t]) v = remap[v];
                    });
  return removed;
}

}  // namespace isovdb::mesh
