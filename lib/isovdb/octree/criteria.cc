#include "isovdb/octree/criteria.h"

#include <cstddef>

namespace isovdb::octree {

namespace {

std::ptrdiff_t axisStride(const MetaCellSamples& samples, int axis) {
  const std::ptrdiff_t s = samples.stride();
  return axis == 0 ? 1 : axis == 1 ? s : s * s;
}

int findRoot(std::vector<std::int32_t>& parent, std::int32_t a) {
  while (parent[static_cast<std::size_t>(a)] != a) {
    const std::int32_t up = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(a)])];
    parent[static_cast<std::size_t>(a)] = up;  // path halving
    a = up;
  }
  return a;
}

}  // namespace

int countSignChanges(const MetaCellSamples& samples, std::array<int, 3> start, int axis, int length,
                     float iso) noexcept {
  const float* p = samples.values.data() + samples.indexOf(start[0], start[1], start[2]);
  const std::ptrdiff_t step = axisStride(samples, axis);
  bool prev = isInside(*p, iso);
  int changes = 0;
  for (int t = 1; t <= length; ++t) {
    p += step;
    const bool cur = isInside(*p, iso);
    changes += cur != prev;
    prev = cur;
  }
  return changes;
}

FaceLabeller::Result FaceLabeller::label(const MetaCellSamples& samples, std::array<int, 3> origin,
                                         int normalAxis, int size, float iso) {
  Result result;
  const auto uv = otherAxes(normalAxis);
  const int n = size + 1;
  const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  if (phase_.size() < count) {
    phase_.resize(count);
    parent_.resize(count);
    touches_.resize(count);
  }
  // Read the face's phases (row-major in (u, v)), noting whether it is uniform.
  const float* base = samples.values.data() + samples.indexOf(origin[0], origin[1], origin[2]);
  const std::ptrdiff_t su = axisStride(samples, uv[0]), sv = axisStride(samples, uv[1]);
  const std::uint8_t first = isInside(*base, iso) ? 1 : 0;
  result.inside = first != 0;
  bool uniform = true;
  for (int v = 0; v < n; ++v) {
    const float* row = base + v * sv;
    std::uint8_t* out = phase_.data() + static_cast<std::size_t>(v) * static_cast<std::size_t>(n);
    for (int u = 0; u < n; ++u) {
      const std::uint8_t ph = isInside(row[u * su], iso) ? 1 : 0;
      out[u] = ph;
      uniform &= ph == first;
    }
  }
  result.uniform = uniform;
  if (uniform) {
    result.components = 1;
    return result;
  }
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
  int components = 0;
  for (int v = 0; v < n; ++v) {
    for (int u = 0; u < n; ++u) {
      const std::int32_t id = v * n + u;
      const std::int32_t root = findRoot(parent_, id);
      if (root == id) ++components;
      if (u == 0 || v == 0 || u == n - 1 || v == n - 1) touches_[static_cast<std::size_t>(root)] = 1;
    }
  }
  result.components = components;
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

bool hasHiddenComponent(const MetaCellSamples& samples, std::array<int, 3> origin, int size, float iso) {
  if (size < 2) return false;  // no sample off the faces
  const int n = size + 1;
  const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  thread_local std::vector<std::uint8_t> state;  // bit 0: phase, bit 1: reached from a face
  thread_local std::vector<std::int32_t> queue;
  state.resize(count);
  queue.clear();
  std::size_t i = 0;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y) {
      const float* row = samples.values.data() + samples.indexOf(origin[0], origin[1] + y, origin[2] + z);
      const bool faceRow = z == 0 || y == 0 || z == size || y == size;
      for (int x = 0; x < n; ++x, ++i) {
        const bool onFace = faceRow || x == 0 || x == size;
        state[i] = static_cast<std::uint8_t>((isInside(row[x], iso) ? 1 : 0) | (onFace ? 2 : 0));
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
  const std::size_t interior = static_cast<std::size_t>(size - 1) * static_cast<std::size_t>(size - 1) *
                               static_cast<std::size_t>(size - 1);
  return queue.size() != interior;
}

std::uint8_t cellCornerSigns(const MetaCellSamples& samples, std::array<int, 3> origin, int size,
                             float iso) noexcept {
  std::uint8_t signs = 0;
  for (int c = 0; c < 8; ++c) {
    const float v = samples.value(origin[0] + (c & 1) * size, origin[1] + ((c >> 1) & 1) * size,
                                  origin[2] + ((c >> 2) & 1) * size);
    if (isInside(v, iso)) signs = static_cast<std::uint8_t>(signs | (1u << c));
  }
  return signs;
}

CellTopology classifyCell(const MetaCellSamples& samples, std::array<int, 3> origin, int size,
                          const CellClassifyOptions& options, FaceLabeller& labeller) {
  CellTopology topo;
  topo.cornerSigns = cellCornerSigns(samples, origin, size, options.iso);
  for (int e = 0; e < 12; ++e) {
    const int c0 = cellEdgeCorner(e, 0);
    const std::array<int, 3> start{origin[0] + (c0 & 1) * size, origin[1] + ((c0 >> 1) & 1) * size,
                                   origin[2] + ((c0 >> 2) & 1) * size};
    if (isComplexEdge(samples, start, cellEdgeAxis(e), size, options.iso))
      topo.complexEdges = static_cast<std::uint16_t>(topo.complexEdges | (1u << e));
  }
  if (topo.complexEdges != 0) return topo;  // complex already; the boundary is not uniform

  topo.facesEvaluated = true;
  bool uniform = true;
  bool phase = (topo.cornerSigns & 1) != 0;
  for (int f = 0; f < 6; ++f) {
    const int axis = f >> 1;
    std::array<int, 3> faceOrigin = origin;
    faceOrigin[axis] += (f & 1) * size;
    const FaceLabeller::Result r = labeller.label(samples, faceOrigin, axis, size, options.iso);
    if (r.isolatedComponent) topo.complexFaces = static_cast<std::uint8_t>(topo.complexFaces | (1u << f));
    uniform &= r.uniform && r.inside == phase;
  }
  topo.boundaryUniform = uniform;
  if (uniform && options.detectInteriorComponents && size > 1) {
    for (int k = 1; k < size && !topo.interiorComponent; ++k)
      for (int j = 1; j < size && !topo.interiorComponent; ++j) {
        const float* row = samples.values.data() + samples.indexOf(origin[0] + 1, origin[1] + j, origin[2] + k);
        for (int i = 0; i < size - 1; ++i)
          if (isInside(row[i], options.iso) != phase) {
            topo.interiorComponent = true;
            break;
          }
      }
  }
  return topo;
}

}  // namespace isovdb::octree

