// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/reservoir/corner_point_grid.h"

#include <tbb/parallel_for.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "isovdb/errors.h"
#include "isovdb/huge_pages.h"
#include "isovdb/union_find.h"

namespace isovdb::reservoir {
namespace {

std::string cellName(int i, int j, int k) {
  return "(" + std::to_string(i + 1) + "," + std::to_string(j + 1) + "," + std::to_string(k + 1) + ")";
}

void requireCount(const GrdeclDeck& deck, const char* keyword, std::size_t found, std::size_t expected,
                  const std::string& why) {
  if (found != expected)
    throw InputError(deck.path.string() + ": " + keyword + " has " + std::to_string(found) + " values, expected " +
                     std::to_string(expected) + " (" + why + ")");
}

void requireFinite(const GrdeclDeck& deck, const char* keyword, const std::vector<double>& values) {
  for (std::size_t n = 0; n < values.size(); ++n)
    if (!std::isfinite(values[n]))
      throw InputError(deck.path.string() + ": " + keyword + " value " + std::to_string(n + 1) +
                       " is not a finite number");
}

/// Determinant of the trilinear map's Jacobian at corner c (edges leaving c, in +u order).
double cornerJacobian(const std::array<Vec3d, 8>& p, int c) {
  Eigen::Matrix3d j;
  for (int a = 0; a < 3; ++a) {
    const int other = c ^ (1 << a);
    j.col(a) = ((c >> a) & 1) ? Vec3d(p[c] - p[other]) : Vec3d(p[other] - p[c]);
  }
  return j.determinant();
}

/// Where a cell has zero thickness at a pillar (a pinch-out), its top and bottom corners
/// there coincide, but they lie on nodes of two layers and were grouped apart (points are
/// grouped around each node): one point in the cells above and another below, each with its
/// own average, and a layer of zero thickness everywhere was two sheets in one place.
/// Such points become one (the lowest id), their cells' lists joined, and the ids are
/// numbered again in order. Nothing changes (and nothing is copied) where no pillar pinches.
void mergePinchedPillarPoints(CornerPointGrid& grid, double tolerance) {
  const std::size_t cells = grid.cellCount(), points = grid.points.size();
  std::vector<std::uint32_t> parent;
  for (std::size_t cell = 0; cell < cells; ++cell)
    for (int c = 0; c < 4; ++c) {
      const std::uint32_t a = grid.pointIds[cell][static_cast<std::size_t>(c)];
      const std::uint32_t b = grid.pointIds[cell][static_cast<std::size_t>(c | 4)];
      if (a == b || (grid.points[a] - grid.points[b]).norm() > tolerance) continue;
      if (parent.empty()) {
        parent.resize(points);
        for (std::uint32_t p = 0; p < points; ++p) parent[p] = p;
      }
      const std::uint32_t ra = findRoot(parent, a), rb = findRoot(parent, b);
      parent[std::max(ra, rb)] = std::min(ra, rb);
    }
  if (parent.empty()) return;
  std::vector<std::uint32_t> newId(points);
  std::uint32_t merged = 0;
  for (std::uint32_t p = 0; p < points; ++p)
    newId[p] = findRoot(parent, p) == p ? merged++ : newId[findRoot(parent, p)];
  std::vector<Vec3d> mergedPoints(merged);
  // The joined lists, flat: each merged point's range counted, filled in id order, then
  // (where points were joined) sorted and stripped of repeats (a cell holds both points it
  // joins), in place.
  std::vector<std::uint32_t> start(merged + std::size_t{1}, 0), joined(grid.pointCells.size());
  for (std::uint32_t p = 0; p < points; ++p) {
    if (findRoot(parent, p) == p) mergedPoints[newId[p]] = grid.points[p];
    start[newId[p] + std::size_t{1}] += static_cast<std::uint32_t>(grid.cellsOfPoint(p).size());
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t p = 0; p < points; ++p)
    for (const std::uint32_t cell : grid.cellsOfPoint(p)) joined[fill[newId[p]]++] = cell;
  std::vector<std::uint8_t> joinsSeveral(merged, 0);
  for (std::uint32_t p = 0; p < points; ++p) joinsSeveral[newId[p]] |= findRoot(parent, p) != p;
  std::uint32_t kept = 0;
  for (std::uint32_t q = 0; q < merged; ++q) {
    const auto first = joined.begin() + start[q], last = joined.begin() + start[q + 1];
    auto end = last;  // a point that joins none keeps its list as it was
    if (joinsSeveral[q]) {
      std::sort(first, last);
      end = std::unique(first, last);
    }
    start[q] = kept;
    kept = static_cast<std::uint32_t>(std::copy(first, end, joined.begin() + kept) - joined.begin());
  }
  start[merged] = kept;
  joined.resize(kept);
  for (auto& ids : grid.pointIds)
    for (auto& id : ids) id = newId[id];
  grid.points = std::move(mergedPoints);
  grid.pointCellStart = std::move(start);
  grid.pointCells = std::move(joined);
}

}  // namespace

CornerPointGrid buildCornerPointGrid(const GrdeclDeck& deck, const GridOptions& options) {
  const int nx = deck.dims[0], ny = deck.dims[1], nz = deck.dims[2];  // (lambdas cannot capture bindings)
  if (nx <= 0 || ny <= 0 || nz <= 0)
    throw InputError(deck.path.string() + ": no SPECGRID (or DIMENS) keyword: the grid size is unknown");
  const std::size_t cells = static_cast<std::size_t>(nx) * ny * nz;
  const std::string dimText = std::to_string(nx) + "x" + std::to_string(ny) + "x" + std::to_string(nz);
  requireCount(deck, "COORD", deck.coord.size(), 6 * static_cast<std::size_t>(nx + 1) * (ny + 1),
               "6 per pillar, (nx+1)(ny+1) pillars for SPECGRID " + dimText);
  requireCount(deck, "ZCORN", deck.zcorn.size(), 8 * cells, "8 per cell for SPECGRID " + dimText);
  if (!deck.actnum.empty())
    requireCount(deck, "ACTNUM", deck.actnum.size(), cells, "one per cell for SPECGRID " + dimText);
  requireFinite(deck, "COORD", deck.coord);
  requireFinite(deck, "ZCORN", deck.zcorn);

  CornerPointGrid grid;
  grid.dims = deck.dims;
  grid.warnings = deck.warnings;
  resizeHuge(grid.corners, cells);
  resizeHuge(grid.active, cells);
  tbb::parallel_for(0, nz, [&](int k) {  // layers of cells in parallel: each cell is written once
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const std::size_t cell = grid.cellIndex(i, j, k);
        grid.active[cell] = deck.actnum.empty() || deck.actnum[cell] != 0;
        for (int c = 0; c < 8; ++c) {
          const int ix = c & 1, iy = (c >> 1) & 1, iz = (c >> 2) & 1;
          const double z =
              deck.zcorn[((static_cast<std::size_t>(2 * k + iz) * 2 * ny + 2 * j + iy) * 2 * nx) + 2 * i + ix];
          const double* pillar = &deck.coord[6 * ((static_cast<std::size_t>(j + iy)) * (nx + 1) + i + ix)];
          const Vec3d top(pillar[0], pillar[1], pillar[2]), bottom(pillar[3], pillar[4], pillar[5]);
          const double dz = bottom.z() - top.z();
          const double t = std::abs(dz) > 0 ? (z - top.z()) / dz : 0.0;
          grid.corners[cell][c] = Vec3d(top.x() + t * (bottom.x() - top.x()), top.y() + t * (bottom.y() - top.y()), z);
        }
      }
  });

  // Tolerance from the bounding box.
  Vec3d lo = Vec3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const auto& cellCorners : grid.corners)
    for (const Vec3d& p : cellCorners) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  const double tolerance = std::max(1e-12, options.relativeTolerance * (hi - lo).norm());

  // Points: the corners around each grid node, grouped by position (node order: deterministic
  // ids). Each layer of nodes is grouped on its own, in parallel, its points numbered from 0;
  // the layers are then numbered in order, so the ids are those of one pass in node order.
  struct NodeLayer {
    std::vector<Vec3d> points;
    std::vector<std::uint32_t> cellCounts;  // per point: how many cells share it
    std::vector<std::uint32_t> cells;       // each point's cells, point after point
  };
  std::vector<NodeLayer> layers(static_cast<std::size_t>(nz) + 1);
  resizeHuge(grid.pointIds, cells);
  tbb::parallel_for(0, nz + 1, [&](int K) {
    NodeLayer& layer = layers[static_cast<std::size_t>(K)];
    for (int J = 0; J <= ny; ++J)
      for (int I = 0; I <= nx; ++I) {
        const std::size_t first = layer.points.size();
        std::array<std::pair<std::size_t, std::uint32_t>, 8> touching{};  // (point, cell)
        int count = 0;
        for (int c = 7; c >= 0; --c) {  // cell (I-ix, J-iy, K-iz) touches the node with its corner c
          const int i = I - (c & 1), j = J - ((c >> 1) & 1), k = K - ((c >> 2) & 1);
          if (i < 0 || j < 0 || k < 0 || i >= nx || j >= ny || k >= nz) continue;
          const std::size_t cell = grid.cellIndex(i, j, k);
          const Vec3d& p = grid.corners[cell][c];
          std::size_t id = first;
          while (id < layer.points.size() && (layer.points[id] - p).norm() > tolerance) ++id;
          if (id == layer.points.size()) layer.points.push_back(p);
          grid.pointIds[cell][c] = static_cast<std::uint32_t>(id);  // within the layer, for now
          touching[static_cast<std::size_t>(count++)] = {id, static_cast<std::uint32_t>(cell)};
        }
        // This node's points are the newest: their cells go last, each point's in corner order.
        for (std::size_t id = first; id < layer.points.size(); ++id) {
          std::uint32_t shared = 0;
          for (int n = 0; n < count; ++n)
            if (touching[static_cast<std::size_t>(n)].first == id) {
              layer.cells.push_back(touching[static_cast<std::size_t>(n)].second);
              ++shared;
            }
          layer.cellCounts.push_back(shared);
        }
      }
  });
  std::vector<std::size_t> layerFirst(layers.size() + 1, 0);
  std::size_t pointCells = 0;
  for (std::size_t K = 0; K < layers.size(); ++K) {
    layerFirst[K + 1] = layerFirst[K] + layers[K].points.size();
    pointCells += layers[K].cells.size();
  }
  if (layerFirst.back() >= std::numeric_limits<std::uint32_t>::max())
    throw InputError(deck.path.string() + ": more than 2^32 corner points");
  tbb::parallel_for(0, nz, [&](int k) {
    for (std::size_t cell = grid.cellIndex(0, 0, k); cell < grid.cellIndex(0, 0, k + 1); ++cell)
      for (int c = 0; c < 8; ++c)
        grid.pointIds[cell][c] += static_cast<std::uint32_t>(layerFirst[static_cast<std::size_t>(k + (c >> 2))]);
  });
  reserveHuge(grid.points, layerFirst.back());
  reserveHuge(grid.pointCells, pointCells);
  grid.pointCellStart.reserve(layerFirst.back() + 1);
  for (NodeLayer& layer : layers) {
    grid.points.insert(grid.points.end(), layer.points.begin(), layer.points.end());
    grid.pointCells.insert(grid.pointCells.end(), layer.cells.begin(), layer.cells.end());
    for (const std::uint32_t shared : layer.cellCounts)
      grid.pointCellStart.push_back(grid.pointCellStart.back() + shared);
    layer = NodeLayer{};  // its memory serves the next layer's copy
  }
  if (options.joinPinchOuts) mergePinchedPillarPoints(grid, tolerance);

  // Orientation and inverted cells.
  assignHuge(grid.cellShape, cells, std::uint8_t{0});
  std::vector<double> minDet, maxDet;
  resizeHuge(minDet, cells);
  resizeHuge(maxDet, cells);
  double sum = 0;
  for (std::size_t cell = 0; cell < cells; ++cell) {
    if (!grid.active[cell]) continue;
    ++grid.activeCells;
    double lo = std::numeric_limits<double>::max(), hi = -lo, smallest = lo;
    for (int c = 0; c < 8; ++c) {
      const double d = cornerJacobian(grid.corners[cell], c);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
      smallest = std::min(smallest, std::abs(d));
      sum += d;
    }
    minDet[cell] = lo;
    maxDet[cell] = hi;
    // A pinch-out: the cell's thickness (or another extent) is zero at some corners only.
    const double scale = std::max(std::abs(lo), std::abs(hi));
    if (scale > 0 && smallest <= 1e-9 * scale) {
      ++grid.pinchedCells;
      grid.cellShape[cell] |= CornerPointGrid::kPinchedCell;
    }
  }
  grid.orientation = sum < 0 ? -1 : 1;
  std::size_t firstInverted = cells;
  for (std::size_t cell = 0; cell < cells; ++cell) {
    if (!grid.active[cell]) continue;
    const double scale = std::max(std::abs(minDet[cell]), std::abs(maxDet[cell]));
    const bool inverted = grid.orientation > 0 ? minDet[cell] < -1e-9 * scale : maxDet[cell] > 1e-9 * scale;
    if (inverted) {
      ++grid.invertedCells;
      grid.cellShape[cell] |= CornerPointGrid::kInvertedCell;
      if (firstInverted == cells) firstInverted = cell;
    }
  }
  if (grid.invertedCells > 0) {
    const int i = static_cast<int>(firstInverted % nx), j = static_cast<int>((firstInverted / nx) % ny),
              k = static_cast<int>(firstInverted / (static_cast<std::size_t>(nx) * ny));
    grid.warnings.push_back(deck.path.string() + ": " + std::to_string(grid.invertedCells) +
                            " active cells are inverted (Jacobian of the other sign at a corner), first at cell " +
                            cellName(i, j, k) + "; their triangles may be folded");
  }
  return grid;
}

CornerField averageToCorners(const CornerPointGrid& grid, const std::vector<double>& cellValues,
                             const std::string& what) {
  if (cellValues.size() != grid.cellCount())
    throw InputError(what + " has " + std::to_string(cellValues.size()) + " values, expected " +
                     std::to_string(grid.cellCount()) + " (one per cell, active or not)");
  CornerField field;
  resizeHuge(field.usable, grid.cellCount());
  std::size_t nanCells = 0;
  for (std::size_t cell = 0; cell < grid.cellCount(); ++cell) {
    const bool finite = std::isfinite(cellValues[cell]);
    nanCells += grid.active[cell] && !finite;
    field.usable[cell] = grid.active[cell] && finite;
  }
  if (nanCells > 0)
    field.warnings.push_back(what + ": " + std::to_string(nanCells) +
                             " active cells have a NaN or infinite value; treated as inactive");
  assignHuge(field.pointValues, grid.points.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t id = 0; id < grid.points.size(); ++id) {
    double sum = 0;
    int count = 0;
    for (const std::uint32_t cell : grid.cellsOfPoint(id))
      if (field.usable[cell]) {
        sum += cellValues[cell];
        ++count;
      }
    if (count > 0) field.pointValues[id] = sum / count;
  }
  return field;
}

CornerField averageToCorners(const CornerPointGrid& grid, const GrdeclDeck& deck, const std::string& property) {
  const auto found = deck.properties.find(property);
  if (found == deck.properties.end()) {
    std::string names;
    for (const auto& [name, values] : deck.properties) names += (names.empty() ? "" : ", ") + name;
    throw InputError(deck.path.string() + ": no property " + property + " (found: " + (names.empty() ? "none" : names) +
                     ")");
  }
  return averageToCorners(grid, found->second, deck.path.string() + ": property " + property);
}

}  // namespace isovdb::reservoir
