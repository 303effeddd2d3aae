// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// libFuzzer harness of the whole extract path on tiny masks, checking the mesh
// guarantees on every run. The first bytes choose the dims (2..13 per axis), the
// method (regular or adaptive) and the meta-cell size (16: seams inside every volume
// larger than 16 voxels along an axis, or 0: one block); the rest are the voxels, one
// bit each (missing bytes are empty). A mesh that is not closed and manifold, or, in
// adaptive mode, that self-intersects, aborts: that is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "fuzz_support.h"
#include "isovdb/mesh/validate.h"
#include "isovdb/pipeline/extract.h"
#include "isovdb/pipeline/load_volume.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace isovdb;
  if (size < 4) return 0;
  io::RawOptions raw;
  for (int a = 0; a < 3; ++a) raw.dims[a] = 2 + data[a] % 12;
  const bool adaptive = (data[3] & 1) != 0;
  const int metaCell = (data[3] & 2) != 0 ? 0 : 16;
  const std::size_t voxels = static_cast<std::size_t>(raw.dims[0] * raw.dims[1] * raw.dims[2]);
  std::vector<std::uint8_t> mask(voxels, 0);
  for (std::size_t i = 0; i < voxels && 4 + i / 8 < size; ++i) mask[i] = (data[4 + i / 8] >> (i % 8)) & 1;
  const auto path = fuzz::writeInput(mask.data(), mask.size(), ".raw");
  pipeline::InputOptions input;
  input.raw = raw;
  input.rule.threshold = 0.5;
  pipeline::ExtractOptions options;
  options.contour.method = adaptive ? pipeline::ContourMethod::Adaptive : pipeline::ContourMethod::Regular;
  options.metaCellSize = metaCell;
  options.threads = 1;
  const mesh::Mesh mesh = pipeline::extractMesh(pipeline::loadVolume(path, input), options);
  const mesh::MeshReport report = mesh::validateMesh(mesh);
  if (!report.closed || !report.manifold || (adaptive && report.selfIntersectingPairs != 0)) {
    std::fprintf(stderr, "%s mesh of a %lldx%lldx%lld mask, meta-cell %d: closed %d, manifold %d, %lld pairs\n",
                 adaptive ? "adaptive" : "regular", static_cast<long long>(raw.dims[0]),
                 static_cast<long long>(raw.dims[1]), static_cast<long long>(raw.dims[2]), metaCell, report.closed,
                 report.manifold, static_cast<long long>(report.selfIntersectingPairs));
    std::abort();
  }
  return 0;
}
