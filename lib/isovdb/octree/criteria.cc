// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/octree/criteria.h"

#include <algorithm>
#include <cstddef>

#include "isovdb/union_find.h"

namespace isovdb::octree {

namespace {

/// The samples of `phase` (one row's bits) joined along the row to `seeds`.
std::uint64_t spreadAlongRow(std::uint64_t seeds, std::uint64_t phase) noexcept {
  for (;;) {
    const std::uint64_t grown = seeds | (((seeds << 1) | (seeds >> 1)) & phase);
    if (grown == seeds) return seeds;
    seeds = grown;
  }
}

/// Bit-parallel flood fill over rows of at most 64 samples: grows `reached`
/// (seeds, a subset of `phase`) to every sample of `phase` connected to it along
/// a row or to the same bit of a neighbouring row, and returns true if that is
/// all of `phase`. Rows are indexed y + rowsPerSlice * z: a face is one slice
/// (neighbours y +- 1), a cell is rowsPerSlice slices (and z +- 1). Forward and
/// backward sweeps until nothing grows; a sweep costs one word operation per row.
bool floodReachesAll(const std::uint64_t* phase, std::uint64_t* reached, int rowsPerSlice, int slices) {
  auto update = [&](int y, int z) {
    const int i = y + rowsPerSlice * z;
    std::uint64_t from = reached[i];
    if (y > 0) from |= reached[i - 1];
    if (y + 1 < rowsPerSlice) from |= reached[i + 1];
    if (z > 0) from |= reached[i - rowsPerSlice];
    if (z + 1 < slices) from |= reached[i + rowsPerSlice];
    const std::uint64_t grown = spreadAlongRow(from & phase[i], phase[i]);
    const bool changed = grown != reached[i];
    reached[i] = grown;
    return changed;
  };
  for (bool changed = true; changed;) {
    changed = false;
    for (int z = 0; z < slices; ++z)
      for (int y = 0; y < rowsPerSlice; ++y) changed |= update(y, z);
    for (int z = slices - 1; z >= 0; --z)
      for (int y = rowsPerSlice - 1; y >= 0; --y) changed |= update(y, z);
  }
  const int rows = rowsPerSlice * slices;
  for (int i = 0; i < rows; ++i)
    if (reached[i] != phase[i]) return false;
  return true;
}

/// Flood of both phases of `rows` (bit = inside; n rows of n bits per slice) from
/// their border samples: true if some sample of either phase is not connected to
/// the border. The border is the first and last row of each slice, the first and
/// last slice when there are several, and the first and last bit of every row.
bool hasUnreachedSamples(const std::vector<std::uint64_t>& rows, int n, int slices, std::vector<std::uint64_t>& phase,
                         std::vector<std::uint64_t>& reached) {
  const std::uint64_t full = SamplePhases::lowBits(n);
  const std::uint64_t ends = 1u | (std::uint64_t{1} << (n - 1));
  phase.resize(rows.size());
  reached.resize(rows.size());
  for (const bool inside : {true, false}) {
    std::size_t i = 0;
    for (int z = 0; z < slices; ++z)
      for (int y = 0; y < n; ++y, ++i) {
        const bool borderRow = y == 0 || y == n - 1 || (slices > 1 && (z == 0 || z == slices - 1));
        phase[i] = inside ? rows[i] : ~rows[i] & full;
        reached[i] = phase[i] & (borderRow ? full : ends);
      }
    if (!floodReachesAll(phase.data(), reached.data(), n, slices)) return true;
  }
  return false;
}

}  // namespace

int countSignChanges(const SamplePhases& phases, std::array<int, 3> start, int axis, int length) noexcept {
  return phases.changesAlong(start[0], start[1], start[2], axis, length + 1);
}

FaceLabeller::Result FaceLabeller::label(const SamplePhases& phases, std::array<int, 3> origin, int normalAxis,
                                         int size) {
  Result result;
  const auto uv = otherAxes(normalAxis);
  const int n = size + 1;
  if (n <= 64) {
    // One word per row of the face (along u: x unless the face is normal to x).
    rows_.resize(static_cast<std::size_t>(n));
    for (int v = 0; v < n; ++v) {
      std::array<int, 3> p = origin;
      p[static_cast<std::size_t>(uv[1])] += v;
      rows_[static_cast<std::size_t>(v)] = phases.line(p[0], p[1], p[2], uv[0], n);
    }
    const std::uint64_t firstRow = rows_[0];
    result.inside = (firstRow & 1u) != 0;
    result.uniform = (firstRow == 0 || firstRow == SamplePhases::lowBits(n)) &&
                     std::all_of(rows_.begin(), rows_.end(), [&](std::uint64_t r) { return r == firstRow; });
    if (!result.uniform) result.isolatedComponent = hasUnreachedSamples(rows_, n, 1, floodPhase_, floodReached_);
    return result;
  }
  // Faces wider than a word: Hoshen–Kopelman labelling.
  const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  if (phase_.size() < count) {
    phase_.resize(count);
    parent_.resize(count);
    touches_.resize(count);
  }
  // Read the face's phases (row-major in (u, v)), noting whether it is uniform.
  // u is x unless the face is normal to x: then rows are runs of bits.
  const std::uint8_t first = phases.inside(origin) ? 1 : 0;
  result.inside = first != 0;
  bool uniform = true;
  for (int v = 0; v < n; ++v) {
    std::array<int, 3> p = origin;
    p[static_cast<std::size_t>(uv[1])] += v;
    std::uint8_t* out = phase_.data() + static_cast<std::size_t>(v) * static_cast<std::size_t>(n);
    if (uv[0] == 0) {
      const int rowPhase = phases.runPhase(p[0], p[1], p[2], n);
      if (rowPhase >= 0) {
        std::fill(out, out + n, static_cast<std::uint8_t>(rowPhase));
        uniform &= rowPhase == first;
        continue;
      }
      uniform = false;
      for (int u = 0; u < n; u += 64) {
        const int chunk = std::min(64, n - u);
        const std::uint64_t bits = phases.row(p[0] + u, p[1], p[2], chunk);
        for (int t = 0; t < chunk; ++t) out[u + t] = static_cast<std::uint8_t>((bits >> t) & 1u);
      }
    } else {
      for (int u = 0; u < n; ++u, ++p[static_cast<std::size_t>(uv[0])]) {
        const std::uint8_t ph = phases.inside(p) ? 1 : 0;
        out[u] = ph;
        uniform &= ph == first;
      }
    }
  }
  result.uniform = uniform;
  if (uniform) return result;
  // Hoshen–Kopelman: raster scan, union with the left and lower neighbours of
  // the same phase (4-connectivity), union-find with path halving.
  for (int v = 0; v < n; ++v) {
    for (int u = 0; u < n; ++u) {
      const std::int32_t id = v * n + u;
      const std::uint8_t ph = phase_[static_cast<std::size_t>(id)];
      const bool left = u > 0 && phase_[static_cast<std::size_t>(id - 1)] == ph;
      const bool down = v > 0 && phase_[static_cast<std::size_t>(id - n)] == ph;
      std::int32_t label = id;
      if (left && down) {
        const std::int32_t a = findRoot(parent_, id - 1), b = findRoot(parent_, id - n);
        label = a < b ? a : b;
        parent_[static_cast<std::size_t>(a < b ? b : a)] = label;
      } else if (left) {
        label = findRoot(parent_, id - 1);
      } else if (down) {
        label = findRoot(parent_, id - n);
      }
      parent_[static_cast<std::size_t>(id)] = label;
    }
  }
  // Which roots touch the face's border?
  for (std::size_t i = 0; i < count; ++i) touches_[i] = 0;
  for (int v = 0; v < n; ++v) {
    for (int u = 0; u < n; ++u) {
      const std::int32_t id = v * n + u;
      const std::int32_t root = findRoot(parent_, id);
      if (u == 0 || v == 0 || u == n - 1 || v == n - 1) touches_[static_cast<std::size_t>(root)] = 1;
    }
  }
  for (int v = 1; v < n - 1 && !result.isolatedComponent; ++v)
    for (int u = 1; u < n - 1; ++u) {
      const std::int32_t id = v * n + u;
      if (parent_[static_cast<std::size_t>(id)] == id && !touches_[static_cast<std::size_t>(id)]) {
        result.isolatedComponent = true;
        break;
      }
    }
  return result;
}

bool hasHiddenComponent(const SamplePhases& phases, std::array<int, 3> origin, int size) {
  if (size < 2) return false;  // no sample off the faces
  if (size == 2) {
    // One interior sample, whose six neighbours are the faces' centres: it is a component of
    // its own iff they all read the other phase (the flood below, without its rows).
    const std::array<int, 3> centre{origin[0] + 1, origin[1] + 1, origin[2] + 1};
    const bool phase = phases.inside(centre);
    for (std::size_t a = 0; a < 3; ++a)
      for (const int d : {-1, 1}) {
        std::array<int, 3> p = centre;
        p[a] += d;
        if (phases.inside(p) == phase) return false;
      }
    return true;
  }
  const int n = size + 1;
  if (n <= 64) {
    // One word per row of x, rows indexed y + n z.
    thread_local std::vector<std::uint64_t> rows, phase, reached;
    rows.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
    for (int z = 0; z < n; ++z)
      for (int y = 0; y < n; ++y)
        rows[static_cast<std::size_t>(y + n * z)] = phases.row(origin[0], origin[1] + y, origin[2] + z, n);
    return hasUnreachedSamples(rows, n, n, phase, reached);
  }
  // Cells wider than a word: breadth-first flood over one byte per sample.
  const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  thread_local std::vector<std::uint8_t> state;  // bit 0: phase, bit 1: reached from a face
  thread_local std::vector<std::int32_t> queue;
  state.resize(count);
  queue.clear();
  std::size_t i = 0;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y) {
      const bool faceRow = z == 0 || y == 0 || z == size || y == size;
      for (int x0 = 0; x0 < n; x0 += 64) {
        const int chunk = std::min(64, n - x0);
        const std::uint64_t bits = phases.row(origin[0] + x0, origin[1] + y, origin[2] + z, chunk);
        for (int t = 0; t < chunk; ++t, ++i) {
          const int x = x0 + t;
          const bool onFace = faceRow || x == 0 || x == size;
          state[i] = static_cast<std::uint8_t>(((bits >> t) & 1u) | (onFace ? 2u : 0u));
        }
      }
    }
  // Face samples count as reached. Flood the interior from the samples of the outermost
  // interior shell that touch a face sample of their phase; an interior sample's six
  // neighbours all lie in the cell, so the flood needs no bounds checks.
  const std::array<std::int32_t, 6> steps{1, -1, n, -n, n * n, -n * n};
  for (int z = 1; z < size; ++z)
    for (int y = 1; y < size; ++y)
      for (int x = 1; x < size; ++x) {
        const bool shell = x == 1 || y == 1 || z == 1 || x == size - 1 || y == size - 1 || z == size - 1;
        if (!shell) continue;
        const std::int32_t at = (z * n + y) * n + x;
        const std::uint8_t reached = static_cast<std::uint8_t>((state[static_cast<std::size_t>(at)] & 1) | 2);
        for (const std::int32_t step : steps)
          if (state[static_cast<std::size_t>(at + step)] == reached) {
            state[static_cast<std::size_t>(at)] = reached;
            queue.push_back(at);
            break;
          }
      }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::int32_t at = queue[head];
    const std::uint8_t phase = state[static_cast<std::size_t>(at)] & 1;
    for (const std::int32_t step : steps) {
      const auto j = static_cast<std::size_t>(at + step);
      if (state[j] == phase) {  // same phase, not reached yet (an interior sample: faces are reached)
        state[j] = static_cast<std::uint8_t>(phase | 2);
        queue.push_back(static_cast<std::int32_t>(j));
      }
    }
  }
  const std::size_t interior =
      static_cast<std::size_t>(size - 1) * static_cast<std::size_t>(size - 1) * static_cast<std::size_t>(size - 1);
  return queue.size() != interior;
}

std::uint8_t cellCornerSigns(const SamplePhases& phases, std::array<int, 3> origin, int size) noexcept {
  std::uint8_t signs = 0;
  for (int c = 0; c < 8; ++c)
    if (phases.inside(origin[0] + (c & 1) * size, origin[1] + ((c >> 1) & 1) * size, origin[2] + ((c >> 2) & 1) * size))
      signs = static_cast<std::uint8_t>(signs | (1u << c));
  return signs;
}

CellTopology classifyCell(const SamplePhases& phases, std::array<int, 3> origin, int size,
                          const CellClassifyOptions& options, FaceLabeller& labeller) {
  CellTopology topo;
  topo.cornerSigns = cellCornerSigns(phases, origin, size);
  if (size == 1) {
    // The corners are all the samples: an edge changes sign at most once and a
    // face has no sample off its edges, so only uniformity is left to find.
    topo.facesEvaluated = true;
    topo.boundaryUniform = topo.cornerSigns == 0 || topo.cornerSigns == 0xFF;
    return topo;
  }
  bool edgesCrossed = false;
  for (int e = 0; e < 12; ++e) {
    const int c0 = cellEdgeCorner(e, 0);
    const std::array<int, 3> start{origin[0] + (c0 & 1) * size, origin[1] + ((c0 >> 1) & 1) * size,
                                   origin[2] + ((c0 >> 2) & 1) * size};
    const int changes = countSignChanges(phases, start, cellEdgeAxis(e), size);
    edgesCrossed |= changes > 0;
    if (changes > 1) topo.complexEdges = static_cast<std::uint16_t>(topo.complexEdges | (1u << e));
  }
  if (topo.complexEdges != 0) return topo;  // complex already; the boundary is not uniform

  topo.facesEvaluated = true;
  const bool phase = (topo.cornerSigns & 1) != 0;
  if (!edgesCrossed && phases.boxPhase(origin, size + 1) == (phase ? 1 : 0)) {
    // Most cells away from the surface: every sample is one phase, so no face
    // needs labelling and there is no interior component (one pass of words).
    topo.boundaryUniform = true;
    return topo;
  }
  bool uniform = true;
  for (int f = 0; f < 6; ++f) {
    const int axis = f >> 1;
    std::array<int, 3> faceOrigin = origin;
    faceOrigin[axis] += (f & 1) * size;
    if (size == 2) {
      // 3 x 3 samples: only the centre is off the edges, and it is isolated iff
      // its four neighbours all have the other phase.
      const auto uv = otherAxes(axis);
      auto at = [&](int u, int v) {
        std::array<int, 3> p = faceOrigin;
        p[static_cast<std::size_t>(uv[0])] += u;
        p[static_cast<std::size_t>(uv[1])] += v;
        return phases.inside(p);
      };
      const bool centre = at(1, 1);
      if (at(0, 1) != centre && at(2, 1) != centre && at(1, 0) != centre && at(1, 2) != centre)
        topo.complexFaces = static_cast<std::uint8_t>(topo.complexFaces | (1u << f));
      for (int v = 0; v <= 2 && uniform; ++v)
        for (int u = 0; u <= 2; ++u) uniform &= at(u, v) == phase;
      continue;
    }
    const FaceLabeller::Result r = labeller.label(phases, faceOrigin, axis, size);
    if (r.isolatedComponent) topo.complexFaces = static_cast<std::uint8_t>(topo.complexFaces | (1u << f));
    uniform &= r.uniform && r.inside == phase;
  }
  topo.boundaryUniform = uniform;
  if (uniform && options.detectInteriorComponents && size > 1) {
    const int phaseBit = phase ? 1 : 0;
    for (int k = 1; k < size && !topo.interiorComponent; ++k)
      for (int j = 1; j < size; ++j)
        if (phases.runPhase(origin[0] + 1, origin[1] + j, origin[2] + k, size - 1) != phaseBit) {
          topo.interiorComponent = true;
          break;
        }
  }
  return topo;
}

}  // namespace isovdb::octree
