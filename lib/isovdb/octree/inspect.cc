// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/octree/inspect.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

#include "isovdb/errors.h"

namespace isovdb::octree {

namespace {

template <class T>
void appendBinary(std::string& out, T value) {
  if constexpr (std::endian::native == std::endian::big) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    std::reverse(b, b + sizeof(T));
    out.append(reinterpret_cast<const char*>(b), sizeof(T));
  } else {
    out.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
}

}  // namespace

OctreeSummary summarizeOctree(const LinearOctree& octree) {
  OctreeSummary s;
  const std::size_t depths = static_cast<std::size_t>(octree.finestDepth()) + 1;
  s.leavesPerDepth.assign(depths, 0);
  s.surfaceLeavesPerDepth.assign(depths, 0);
  s.minLeafDepth = octree.finestDepth();
  for (const OctreeLeaf& l : octree.leaves()) {
    ++s.leavesPerDepth[l.depth];
    ++s.leaves;
    if (l.surface) {
      ++s.surfaceLeavesPerDepth[l.depth];
      ++s.surfaceLeaves;
    }
    s.complexLeaves += l.complex;
    s.minLeafDepth = std::min<int>(s.minLeafDepth, l.depth);
    s.maxLeafDepth = std::max<int>(s.maxLeafDepth, l.depth);
  }
  if (s.leaves == 0) s.minLeafDepth = 0;
  return s;
}

void writeLeafWireframe(const LinearOctree& octree, const std::filesystem::path& path,
                        const WireframeOptions& options) {
  std::size_t count = 0;
  for (const OctreeLeaf& l : octree.leaves()) count += !options.surfaceLeavesOnly || l.surface;
  std::ostringstream header;
  header << "ply\nformat " << (options.binary ? "binary_little_endian" : "ascii") << " 1.0\n"
         << "comment isovdb octree leaves (voxel index space)\n"
         << "element vertex " << count * 8 << "\nproperty float x\nproperty float y\nproperty float z\n"
         << "property uchar depth\n"
         << "element edge " << count * 12 << "\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  std::string body = header.str();
  const auto& o = octree.origin();
  for (const OctreeLeaf& l : octree.leaves()) {
    if (options.surfaceLeavesOnly && !l.surface) continue;
    for (int c = 0; c < 8; ++c) {
      const float p[3] = {static_cast<float>(o[0] + l.origin[0] + (c & 1) * l.size),
                          static_cast<float>(o[1] + l.origin[1] + ((c >> 1) & 1) * l.size),
                          static_cast<float>(o[2] + l.origin[2] + ((c >> 2) & 1) * l.size)};
      if (options.binary) {
        for (float v : p) appendBinary(body, v);
        appendBinary(body, static_cast<std::uint8_t>(l.depth));
      } else {
        body += std::to_string(p[0]) + ' ' + std::to_string(p[1]) + ' ' + std::to_string(p[2]) + ' ' +
                std::to_string(l.depth) + '\n';
      }
    }
  }
  std::int32_t base = 0;
  for (const OctreeLeaf& l : octree.leaves()) {
    if (options.surfaceLeavesOnly && !l.surface) continue;
    for (int e = 0; e < 12; ++e) {
      const std::int32_t a = base + cellEdgeCorner(e, 0), b = base + cellEdgeCorner(e, 1);
      if (options.binary) {
        appendBinary(body, a);
        appendBinary(body, b);
      } else {
        body += std::to_string(a) + ' ' + std::to_string(b) + '\n';
      }
    }
    base += 8;
  }
  // Temporary beside the target, then rename: no partial file on failure.
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw IoError("octree wireframe: cannot open " + tmp.string() + " for writing");
    out.write(body.data(), static_cast<std::streamsize>(body.size()));
    out.close();
    if (!out) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      throw IoError("octree wireframe: write failed for " + tmp.string());
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw IoError("octree wireframe: cannot rename " + tmp.string() + " to " + path.string());
  }
}

}  // namespace isovdb::octree
