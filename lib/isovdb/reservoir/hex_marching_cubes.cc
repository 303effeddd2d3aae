// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/reservoir/hex_marching_cubes.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "isovdb/huge_pages.h"
#include "isovdb/reservoir/hex_cell_contour.h"

namespace isovdb::reservoir {
namespace {

using hex::BlockOutput;
using hex::kCentreKey;
using hex::kCornerKey;
using hex::kFaceKey;
using hex::kLoneEdgeKey;
using hex::kSpecialKeys;
using hex::ThreadOutput;

/// Cells per block: blocks are the unit of parallel work and their outputs are merged in
/// order, so the mesh does not depend on the thread count. Reek's 35,838 cells made 35
/// blocks of 1024, and the last one kept a thread busy alone: 256 is 2 % faster there.
constexpr std::size_t kBlockCells = 256;

/// A crossing on a fault face moved into its own side (`side`: the sum of its cells' vectors
/// from the face's centre to the cell's) by a hundredth of that, and at least 16 float
/// steps of its largest coordinate, so that the move shows in the float positions. The
/// faces on the two sides of a fault are different bilinear patches, rarely one plane.
/// A hundredth once folded Emerald's FACIES 0.5 (1 -> 17 pairs: its vertices sit a
/// thousandth of an edge from corners at the iso-value) and a thousandth was used; with
/// fans chosen by their depth in the cell (hex_cell_contour.cc) it no longer folds, and
/// self-intersecting pairs over nine iso-values on Reek and six on Emerald are 89 with a
/// thousandth, 62 with three thousandths, 57 with a hundredth (Reek PORO 0.2: 7 -> 0).
Eigen::Vector3f offFault(const Eigen::Vector3f& position, const Vec3d& side) {
  const double length = side.norm();
  if (!(length > 0)) return position;
  const float largest = position.cwiseAbs().maxCoeff();
  const double ulp = std::bit_cast<float>(std::bit_cast<std::uint32_t>(largest) + 1) - largest;
  const double step = std::min(std::max(1e-2 * length, 16.0 * ulp), 0.05 * length);
  return (position.cast<double>() + step / length * side).cast<float>();
}

/// A vertex record: its weld key and its slot (the blocks' records numbered in order).
struct Record {
  std::uint64_t key;
  std::uint32_t slot;
};

/// The blocks' records ordered by key, then by slot. Edge crossings (all but a few) are
/// counted out by their lower point id, in slot order (a counting sort: linear in the
/// records and the points), then ordered by the upper id inside each point's bucket (a
/// handful of records); the corner and centre records follow, sorted.
std::vector<Record> weldOrder(const std::vector<BlockOutput>& outputs, const std::vector<std::size_t>& firstSlot,
                              std::size_t points) {
  std::vector<std::uint32_t> bucketStart;  // bucket p: [bucketStart[p], bucketStart[p + 1])
  assignHuge(bucketStart, points + 1, 0U);
  std::vector<Record> special;
  for (std::size_t block = 0; block < outputs.size(); ++block)
    for (std::size_t n = 0; n < outputs[block].keyCount; ++n) {
      const std::uint64_t key = outputs[block].keys()[n];
      if (key & kSpecialKeys)
        special.push_back({key, static_cast<std::uint32_t>(firstSlot[block] + n)});
      else
        ++bucketStart[(key >> 32) + 1];
    }
  std::partial_sum(bucketStart.begin(), bucketStart.end(), bucketStart.begin());
  const std::size_t crossings = bucketStart.back();
  std::vector<Record> records;
  resizeHuge(records, crossings + special.size());  // the mesh's arrays are fresh memory: huge pages (huge_pages.h)
  {
    std::vector<std::uint32_t> next;
    reserveHuge(next, points);
    next.assign(bucketStart.begin(), bucketStart.end() - 1);
    for (std::size_t block = 0; block < outputs.size(); ++block)
      for (std::size_t n = 0; n < outputs[block].keyCount; ++n)
        if (const std::uint64_t key = outputs[block].keys()[n]; !(key & kSpecialKeys))
          records[next[key >> 32]++] = {key, static_cast<std::uint32_t>(firstSlot[block] + n)};
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t point = r.begin(); point != r.end(); ++point) {
      // Insertion sort by key: stable, so slots stay in order among equal keys.
      const auto first = records.begin() + bucketStart[point];
      const auto last = records.begin() + bucketStart[point + 1];
      for (auto it = first; it != last; ++it)
        for (auto at = it; at != first && (at - 1)->key > at->key; --at) std::iter_swap(at - 1, at);
    }
  });
  std::sort(special.begin(), special.end(),
            [](const Record& a, const Record& b) { return a.key != b.key ? a.key < b.key : a.slot < b.slot; });
  std::copy(special.begin(), special.end(), records.begin() + static_cast<std::ptrdiff_t>(crossings));
  return records;
}

/// Crossings on fault faces, each with the sum of its cells' sides (in block order), by key.
std::vector<std::pair<std::uint64_t, Vec3d>> mergedFaultSides(const std::vector<BlockOutput>& outputs) {
  std::vector<std::pair<std::uint64_t, Vec3d>> faultSides;
  for (const BlockOutput& made : outputs)
    faultSides.insert(faultSides.end(), made.faultSides().begin(), made.faultSides().end());
  std::stable_sort(faultSides.begin(), faultSides.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::size_t kept = 0;
  for (std::size_t n = 0; n < faultSides.size(); ++n)
    if (kept > 0 && faultSides[kept - 1].first == faultSides[n].first)
      faultSides[kept - 1].second += faultSides[n].second;
    else
      faultSides[kept++] = faultSides[n];
  faultSides.resize(kept);
  return faultSides;
}

/// Placed points by key: both cells of a face computed a face point's position alike; one
/// of each key is kept (a lone crossing has one cell).
std::vector<std::pair<std::uint64_t, Eigen::Vector3f>> mergedPlacedPoints(const std::vector<BlockOutput>& outputs) {
  std::vector<std::pair<std::uint64_t, Eigen::Vector3f>> placedPoints;
  for (const BlockOutput& made : outputs)
    placedPoints.insert(placedPoints.end(), made.placedPoints().begin(), made.placedPoints().end());
  std::stable_sort(placedPoints.begin(), placedPoints.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  placedPoints.erase(std::unique(placedPoints.begin(), placedPoints.end(),
                                 [](const auto& x, const auto& y) { return x.first == y.first; }),
                     placedPoints.end());
  return placedPoints;
}

/// Drops each pair of triangles with the same three vertices wound opposite ways, keeping
/// the order of the others; returns the pairs dropped. Such a pair lies in a face of two
/// cells: where a corner at the iso-value became the grid point's own vertex (crossEdge),
/// the loops of both cells can run through it and the face's two crossings, each cell
/// making the face's triangle facing out of it (Reek PORO 0.22: one pair, whose three
/// edges had four triangles each). The two cancel: without them, each edge keeps one
/// triangle of each cell, wound consistently. Only triangles at such a vertex (the
/// vertices [firstCorner, endCorner): ordered by key, the grid points' are consecutive) can
/// pair, so only those are compared, and none when there is none.
std::size_t cancelOpposedTwins(std::vector<mesh::Triangle>& triangles, std::vector<std::uint32_t>& triangleCells,
                               std::uint32_t firstCorner, std::uint32_t endCorner) {
  if (firstCorner == endCorner) return 0;
  const auto atCorner = [&](std::uint32_t v) { return v >= firstCorner && v < endCorner; };
  struct Candidate {
    std::array<std::uint32_t, 3> sorted;
    bool even;  // the triangle's order is a rotation of the sorted one
    std::uint32_t index;
  };
  std::vector<Candidate> candidates;
  for (std::size_t n = 0; n < triangles.size(); ++n) {
    const mesh::Triangle& t = triangles[n];
    if (!(atCorner(t[0]) || atCorner(t[1]) || atCorner(t[2]))) continue;
    Candidate c{{t[0], t[1], t[2]}, true, static_cast<std::uint32_t>(n)};
    // Three compare-and-swaps sort the triple; each swap flips the permutation's parity.
    for (const auto& [i, j] : {std::pair{0, 1}, std::pair{1, 2}, std::pair{0, 1}})
      if (c.sorted[i] > c.sorted[j]) {
        std::swap(c.sorted[i], c.sorted[j]);
        c.even = !c.even;
      }
    candidates.push_back(c);
  }
  if (candidates.size() < 2) return 0;
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.sorted != b.sorted ? a.sorted < b.sorted : a.index < b.index;
  });
  std::vector<std::uint8_t> dropped(triangles.size(), 0);
  std::size_t pairs = 0;
  for (std::size_t first = 0; first < candidates.size();) {
    std::size_t end = first + 1;
    while (end < candidates.size() && candidates[end].sorted == candidates[first].sorted) ++end;
    // In index order, each triangle pairs with the first unpaired one of the other winding.
    for (std::size_t a = first; a < end; ++a) {
      if (dropped[candidates[a].index]) continue;
      for (std::size_t b = a + 1; b < end; ++b)
        if (!dropped[candidates[b].index] && candidates[b].even != candidates[a].even) {
          dropped[candidates[a].index] = dropped[candidates[b].index] = 1;
          ++pairs;
          break;
        }
    }
    first = end;
  }
  if (pairs > 0) {
    std::size_t kept = 0;
    const bool cells = !triangleCells.empty();
    for (std::size_t n = 0; n < triangles.size(); ++n)
      if (!dropped[n]) {
        if (cells) triangleCells[kept] = triangleCells[n];
        triangles[kept++] = triangles[n];
      }
    triangles.resize(kept);
    if (cells) triangleCells.resize(kept);
  }
  return pairs;
}

}  // namespace

HexContourResult contourHexahedra(const CornerPointGrid& grid, const CornerField& field,
                                  const HexContourOptions& options, Interrupter* interrupter) {
  const std::size_t cells = grid.cellCount();
  std::vector<BlockOutput> outputs((cells + kBlockCells - 1) / kBlockCells);
  tbb::enumerable_thread_specific<ThreadOutput> threadOutputs;
  // Groups of blocks in parallel; progress and cancellation between groups, on this thread.
  constexpr std::size_t kGroupBlocks = 256;
  const ProgressStage progress(interrupter, "marching cubes");
  const auto nx = static_cast<std::size_t>(grid.dims[0]), ny = static_cast<std::size_t>(grid.dims[1]);
  for (std::size_t group = 0; group < outputs.size(); group += kGroupBlocks) {
    progress.update(static_cast<double>(group), static_cast<double>(outputs.size()));
    const std::size_t last = std::min(outputs.size(), group + kGroupBlocks);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(group, last), [&](const tbb::blocked_range<std::size_t>& r) {
      ThreadOutput& out = threadOutputs.local();
      for (std::size_t block = r.begin(); block != r.end(); ++block) {
        BlockOutput& made = outputs[block];
        made.thread = &out;
        made.firstKey = out.keys.size();
        made.firstCentre = out.centres.size();
        made.firstTriangle = out.triangles.size();
        made.firstFaultSide = out.faultSides.size();
        made.firstPlacedPoint = out.placedPoints.size();
        const std::size_t first = block * kBlockCells, end = std::min(cells, first + kBlockCells);
        // (i, j, k) stepped along with the cell index: no division per cell.
        std::array<int, 3> ijk{static_cast<int>(first % nx), static_cast<int>(first / nx % ny),
                               static_cast<int>(first / (nx * ny))};
        for (std::size_t cell = first; cell < end; ++cell) {
          if (field.usable[cell]) hex::contourCell(grid, field, cell, ijk, options, out, made);
          if (++ijk[0] == grid.dims[0]) {
            ijk[0] = 0;
            if (++ijk[1] == grid.dims[1]) {
              ijk[1] = 0;
              ++ijk[2];
            }
          }
        }
        made.keyCount = out.keys.size() - made.firstKey;
        made.centreCount = out.centres.size() - made.firstCentre;
        made.triangleCount = out.triangles.size() - made.firstTriangle;
        made.faultSideCount = out.faultSides.size() - made.firstFaultSide;
        made.placedPointCount = out.placedPoints.size() - made.firstPlacedPoint;
      }
    });
  }
  progress.update(1, 1);

  // Welding: every record (key, slot) ordered by key, then by slot, so each distinct vertex
  // is a run of records in the order the blocks made them: its index is its rank among
  // the keys, and its gradients are summed in block order (normals independent of the
  // thread count).
  HexContourResult result;
  std::vector<std::size_t> firstSlot(outputs.size() + 1, 0);
  for (std::size_t block = 0; block < outputs.size(); ++block) {
    result.cutCells += outputs[block].cutCells;
    result.ambiguousFaces += outputs[block].ambiguousFaces;
    firstSlot[block + 1] = firstSlot[block] + outputs[block].keyCount;
  }
  const std::size_t slots = firstSlot.back();
  if (slots >= std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("marching cubes: more than 2^32 vertex records; mesh indices are 32-bit");
  // The fault sides and placed points are gathered while the records are ordered.
  std::vector<Record> records;
  std::vector<std::pair<std::uint64_t, Vec3d>> faultSides;
  std::vector<std::pair<std::uint64_t, Eigen::Vector3f>> placedPoints;
  tbb::parallel_invoke([&] { records = weldOrder(outputs, firstSlot, grid.points.size()); },
                       [&] {
                         faultSides = mergedFaultSides(outputs);
                         placedPoints = mergedPlacedPoints(outputs);
                       });
  std::vector<std::uint32_t> vertexOfSlot, runStart;
  resizeHuge(vertexOfSlot, slots);
  reserveHuge(runStart, slots + 1);
  for (std::size_t n = 0; n < slots; ++n) {
    if (n == 0 || records[n].key != records[n - 1].key) runStart.push_back(static_cast<std::uint32_t>(n));
    vertexOfSlot[records[n].slot] = static_cast<std::uint32_t>(runStart.size() - 1);
  }
  const std::size_t vertices = runStart.size();
  runStart.push_back(static_cast<std::uint32_t>(slots));

  result.faultVertices = static_cast<std::int64_t>(faultSides.size());
  result.facePoints = std::count_if(placedPoints.begin(), placedPoints.end(),
                                    [](const auto& point) { return (point.first & kFaceKey) != 0; });

  mesh::Mesh& m = result.mesh;
  resizeHuge(m.positions, vertices);
  std::vector<Vec3d> gradients;
  if (options.normals) resizeHuge(gradients, vertices);
  // Each slot's gradient, found without a search for its block.
  std::vector<const Vec3d*> gradientOfSlot;
  if (options.normals) {
    resizeHuge(gradientOfSlot, slots);
    tbb::parallel_for(std::size_t{0}, outputs.size(), [&](std::size_t block) {
      const Vec3d* first = outputs[block].gradients().data();
      for (std::size_t n = 0; n < outputs[block].keyCount; ++n) gradientOfSlot[firstSlot[block] + n] = first + n;
    });
  }
  tbb::parallel_for(std::size_t{0}, vertices, [&](std::size_t v) {
    const std::uint64_t key = records[runStart[v]].key;
    Eigen::Vector3f position;
    if (key & kCentreKey) {
      const auto centres = outputs[((key & ~kCentreKey) >> 4) / kBlockCells].centres();
      position = std::lower_bound(centres.begin(), centres.end(), key, [](const auto& centre, std::uint64_t k) {
                   return centre.first < k;
                 })->second;
    } else if (key & kCornerKey) {
      position = grid.points[key & 0xffffffffU].cast<float>();
    } else {
      if (key & (kFaceKey | kLoneEdgeKey)) {
        position =
            std::lower_bound(placedPoints.begin(), placedPoints.end(), key, [](const auto& point, std::uint64_t k) {
              return point.first < k;
            })->second;
      } else {
        const hex::EdgeCrossing crossing =
            hex::crossEdge(grid, field, options.iso, static_cast<std::uint32_t>(key >> 32),
                           static_cast<std::uint32_t>(key & 0xffffffffU));
        position = hex::crossingPosition(grid, crossing);
      }
    }
    m.positions[v] = {position.x(), position.y(), position.z()};
    if (!options.normals) return;
    Vec3d sum = Vec3d::Zero();
    for (std::uint32_t n = runStart[v]; n < runStart[v + 1]; ++n) sum += *gradientOfSlot[records[n].slot];
    gradients[v] = sum;
  });

  // The first record, and so the first vertex, whose key is not below `key`.
  const auto firstRecordFrom = [&](std::uint64_t key) {
    return std::lower_bound(records.begin(), records.end(), key,
                            [](const Record& r, std::uint64_t k) { return r.key < k; });
  };
  // Crossings off fault faces: each found among the records, a few thousand searches where
  // one per vertex among the fault sides took longer.
  tbb::parallel_for(std::size_t{0}, faultSides.size(), [&](std::size_t n) {
    const auto& [key, side] = faultSides[n];
    const auto record = firstRecordFrom(key);
    if (record == records.end() || record->key != key) return;
    auto& at = m.positions[vertexOfSlot[record->slot]];
    const Eigen::Vector3f moved = offFault(Eigen::Vector3f(at[0], at[1], at[2]), side);
    at = {moved.x(), moved.y(), moved.z()};
  });

  // Triangles in block order, those that welding collapsed dropped: counted, then written.
  std::vector<std::size_t> firstTriangle(outputs.size() + 1, 0);
  const auto welded = [&](std::size_t block, const std::array<std::uint32_t, 3>& t) {
    const std::size_t base = firstSlot[block];
    return mesh::Triangle{vertexOfSlot[base + t[0]], vertexOfSlot[base + t[1]], vertexOfSlot[base + t[2]]};
  };
  const auto kept = [](const mesh::Triangle& t) { return t[0] != t[1] && t[1] != t[2] && t[0] != t[2]; };
  tbb::parallel_for(std::size_t{0}, outputs.size(), [&](std::size_t block) {
    for (const auto& t : outputs[block].triangles()) firstTriangle[block + 1] += kept(welded(block, t));
  });
  for (std::size_t block = 0; block < outputs.size(); ++block) firstTriangle[block + 1] += firstTriangle[block];
  resizeHuge(m.triangles, firstTriangle.back());
  if (options.triangleCells) resizeHuge(result.triangleCells, firstTriangle.back());
  tbb::parallel_for(std::size_t{0}, outputs.size(), [&](std::size_t block) {
    std::size_t next = firstTriangle[block];
    const auto triangles = outputs[block].triangles();
    const auto cells = outputs[block].triangleCells();
    for (std::size_t n = 0; n < triangles.size(); ++n)
      if (const mesh::Triangle tri = welded(block, triangles[n]); kept(tri)) {
        if (options.triangleCells) result.triangleCells[next] = cells[n];
        m.triangles[next++] = tri;
      }
  });
  {
    // Corner keys sort after the crossings', face points' and lone crossings', before the centres'.
    const auto firstVertexFrom = [&](std::uint64_t key) {
      const auto record = firstRecordFrom(key);
      return record == records.end() ? static_cast<std::uint32_t>(vertices) : vertexOfSlot[record->slot];
    };
    static_assert(kCornerKey > (kFaceKey | kLoneEdgeKey) && kCentreKey > kCornerKey);
    result.cancelledTwins = static_cast<std::int64_t>(cancelOpposedTwins(
        m.triangles, result.triangleCells, firstVertexFrom(kCornerKey), firstVertexFrom(kCentreKey)));
  }
  if (options.normals) {
    // Fallback for vertices without a usable gradient (collapsed cells): area-weighted face
    // normals, summed only when some vertex needs them.
    const auto usable = [](const Vec3d& normal) { return normal.norm() > 0 && normal.allFinite(); };
    std::vector<Vec3d> faceNormals;
    if (!std::all_of(gradients.begin(), gradients.end(), usable)) {
      assignHuge(faceNormals, vertices, Vec3d::Zero());
      for (const auto& t : m.triangles) {
        const Vec3d a(m.positions[t[0]][0], m.positions[t[0]][1], m.positions[t[0]][2]);
        const Vec3d b(m.positions[t[1]][0], m.positions[t[1]][1], m.positions[t[1]][2]);
        const Vec3d c(m.positions[t[2]][0], m.positions[t[2]][1], m.positions[t[2]][2]);
        const Vec3d n = (b - a).cross(c - a);
        for (int k = 0; k < 3; ++k) faceNormals[t[k]] += n;
      }
    }
    resizeHuge(m.normals, vertices);
    tbb::parallel_for(std::size_t{0}, vertices, [&](std::size_t v) {
      Vec3d normal = -gradients[v];
      if (!usable(normal)) normal = faceNormals[v];
      if (normal.norm() > 0) normal.normalize();
      m.normals[v] = {static_cast<float>(normal.x()), static_cast<float>(normal.y()), static_cast<float>(normal.z())};
    });
  }
  return result;
}

}  // namespace isovdb::reservoir
