// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/morph/reconstruct.h"

#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <cmath>

#include "isovdb/errors.h"
#include "isovdb/morph/slice_sdf.h"
#include "isovdb/morph/stack_assembly.h"

namespace isovdb::morph {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Reconstruction reconstruct(const SliceStack& stack, const ReconstructOptions& options, Interrupter* interrupter) {
  if (stack.slices.empty()) throw InputError("slice stack: no slices");
  if (!(stack.zStep > 0) || !std::isfinite(stack.zStep)) throw InputError("--z-step must be a finite number > 0");
  if (!(options.halfWidth >= 1 && options.halfWidth <= 64))
    throw InputError("--half-width " + std::to_string(options.halfWidth) + " is out of range, expected 1..64 voxels");
  if (options.maxPlanes < 1) throw InputError("--max-planes must be >= 1");
  const std::size_t n = stack.slices.size();
  const double base = stack.slices.front().height;
  Reconstruction out;
  for (std::size_t i = 0; i < n; ++i) {
    // In double first: a height far above the first one must not overflow the plane index.
    const double steps = std::round((stack.slices[i].height - base) / stack.zStep);
    if (!(steps < options.maxPlanes))
      throw InputError("'" + stack.slices[i].source + "': height " + std::to_string(stack.slices[i].height) + " lies " +
                       std::to_string(steps) + " z steps above the first slice; the completed stack " +
                       "would exceed --max-planes " + std::to_string(options.maxPlanes) +
                       " (check the heights and --z-step, or raise --max-planes)");
    const int plane = static_cast<int>(steps);
    if (i > 0 && plane <= out.originalPlane.back())
      throw InputError("'" + stack.slices[i].source + "': height " + std::to_string(stack.slices[i].height) +
                       " is less than one z step (" + std::to_string(stack.zStep) + ") above the previous slice");
    out.originalPlane.push_back(plane);
  }
  const int planeCount = out.originalPlane.back() + 1;
  out.planes.resize(planeCount);
  for (int z = 0; z < planeCount; ++z) out.planeHeights.push_back(base + z * stack.zStep);

  {
    ProgressStage stage(interrupter, "slice distances");
    const auto start = std::chrono::steady_clock::now();
    tbb::parallel_for(std::size_t(0), n,
                      [&](std::size_t i) { out.planes[out.originalPlane[i]] = signedDistance(stack.slices[i].mask); });
    out.sdfSeconds = secondsSince(start);
  }
  {
    ProgressStage stage(interrupter, options.pair.interpolation == Interpolation::LevelSet
                                         ? (options.pair.particles ? "particle level set morph" : "level set morph")
                                         : "interpolation");
    const auto start = std::chrono::steady_clock::now();
    out.pairs.resize(n - 1);
    std::atomic<int> done{0};
    std::atomic<bool> cancelled{false};
    tbb::parallel_for(std::size_t(0), n - 1, [&](std::size_t i) {
      if (cancelled) return;
      const int za = out.originalPlane[i], zb = out.originalPlane[i + 1];
      const double ha = stack.slices[i].height, hb = stack.slices[i + 1].height;
      std::vector<double> fractions;
      for (int z = za + 1; z < zb; ++z)
        fractions.push_back(std::clamp((out.planeHeights[z] - ha) / (hb - ha), 0.0, 1.0));
      PairOptions pair = options.pair;
      pair.particleOptions.seed = options.pair.particleOptions.seed * 0x9E3779B97F4A7C15ull + i;
      PairResult result =
          morphPair(stack.slices[i].mask, stack.slices[i + 1].mask, out.planes[za], out.planes[zb], fractions, pair);
      for (std::size_t j = 0; j < result.slices.size(); ++j) out.planes[za + 1 + j] = std::move(result.slices[j]);
      out.pairs[i] = result.stats;
      const int finished = ++done;
      if (interrupter && interrupter->wasInterrupted(static_cast<int>(100.0 * finished / (n - 1)))) cancelled = true;
    });
    if (cancelled) throw Interrupted();
    out.morphSeconds = secondsSince(start);
  }
  {
    ProgressStage stage(interrupter, "stack assembly");
    const auto start = std::chrono::steady_clock::now();
    volume::Geometry geometry;
    geometry.spacing = {stack.pixelSize, stack.pixelSize, stack.zStep};
    geometry.origin = {stack.origin.x, stack.origin.y, base};
    out.volume = assembleStack(out.planes, options.halfWidth, geometry, "morph");
    out.assemblySeconds = secondsSince(start);
  }
  return out;
}

}  // namespace isovdb::morph
