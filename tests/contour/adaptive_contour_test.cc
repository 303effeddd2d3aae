// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/contour/adaptive_contour.h: octree dual contouring on
// minimal edges with Ju–Udeshi fans (paper 000, section 4.2.3.2), on analytic
// SDFs and on the sample shapes' distance fields, checked with the exact
// validator (mesh/validate.h).
#include "isovdb/contour/adaptive_contour.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "generators/shapes.h"
#include "isovdb/contour/vdb_mesher.h"
#include "isovdb/errors.h"
#include "isovdb/mesh/validate.h"
#include "isovdb/octree/build.h"
#include "isovdb/volume/distance_field.h"
#include "isovdb/volume/grids.h"
#include "isovdb/volume/ingest.h"
#include "isovdb/volume/mask_rule.h"
#include "support/analytic_sdf.h"
#include "support/mesh_distance.h"

namespace isovdb::contour {
namespace {

using cell::makeMetaCellSamples;
using cell::MetaCellSamples;
using octree::LinearOctree;
using V3 = std::array<double, 3>;

V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double len(const V3& a) { return std::sqrt(dot(a, a)); }
V3 toV3(const mesh::Vec3f& p) { return {p[0], p[1], p[2]}; }

// ---- analytic signed distances (negative inside), global index coordinates ----

double sphereSdf(const V3& p, const V3& c, double r) { return len(sub(p, c)) - r; }

double boxSdf(const V3& p, const V3& c, const V3& half) {
  V3 q;
  for (int a = 0; a < 3; ++a) q[a] = std::abs(p[a] - c[a]) - half[a];
  const V3 outside{std::max(q[0], 0.0), std::max(q[1], 0.0), std::max(q[2], 0.0)};
  return len(outside) + std::min(std::max({q[0], q[1], q[2]}), 0.0);
}

using test::cylinderSdf;

/// The sample shape's distance field (mask -> OpenVDB SDF), in a padded whole-volume meta-cell.
cell::MetaCellSamples shapeSamples(samples::ShapeKind kind, int shapeSize, int metaCellSize, int pad) {
  auto stream = samples::makeShapeStream(kind, samples::ShapeOptions{.size = shapeSize});
  const volume::Volume mask = volume::ingestMask(*stream, volume::MaskRule{});
  const volume::Volume sdf = volume::distanceField(mask);
  auto accessor = volume::fieldGrid(sdf).getConstAccessor();
  return cell::makeMetaCellSamples(metaCellSize, {-pad, -pad, -pad},
                                   [&](int x, int y, int z) { return accessor.getValue(openvdb::Coord(x, y, z)); });
}

/// Trilinear interpolation of the samples at a global position.
double trilinear(const cell::MetaCellSamples& s, const V3& p) {
  V3 q = sub(p, {double(s.origin[0]), double(s.origin[1]), double(s.origin[2])});
  std::array<int, 3> i0;
  V3 f;
  for (int a = 0; a < 3; ++a) {
    i0[a] = std::clamp(static_cast<int>(std::floor(q[a])), -1, s.size);
    f[a] = std::clamp(q[a] - i0[a], 0.0, 1.0);
  }
  double v = 0;
  for (int c = 0; c < 8; ++c) {
    const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
    const double w = (dx ? f[0] : 1 - f[0]) * (dy ? f[1] : 1 - f[1]) * (dz ? f[2] : 1 - f[2]);
    v += w * s.value(i0[0] + dx, i0[1] + dy, i0[2] + dz);
  }
  return v;
}

float testTolerance();

/// Adaptive mode's settings (iso 0, Ju–Udeshi fans, manifold fix): the octree and the contouring read the same.
constexpr cell::ContourSettings kAdaptive{.method = cell::ContourMethod::Adaptive};

octree::OctreeOptions adaptiveTree(float qefTolerance = testTolerance()) {
  // minDepth 3: 16-voxel cells at S = 128. With minDepth 2 (32-voxel cells) the
  // sample sphere stays 8 leaves (12 triangles, mean distance 3 voxels): 3-4
  // crossings fit their tangent planes almost exactly, so the QEF criterion
  // never splits a smooth cell.
  return octree::OctreeOptions{.minDepth = 3, .qefTolerance = qefTolerance};
}

/// Signed volume (outward orientation gives a positive volume).
double signedVolume(const mesh::Mesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) {
    const V3 a = toV3(m.positions[t[0]]), b = toV3(m.positions[t[1]]), c = toV3(m.positions[t[2]]);
    v +=
        (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) /
        6;
  }
  return v;
}

struct ContourRun {
  mesh::Mesh mesh;
  AdaptiveContourStats stats;
  mesh::MeshReport report;
};

ContourRun contourAndValidate(const cell::MetaCellSamples& samples, const LinearOctree& tree, bool intersectionFree) {
  ContourRun run;
  cell::ContourSettings settings = kAdaptive;
  settings.intersectionFree = intersectionFree;
  run.mesh = contourAdaptive(samples, tree, settings, &run.stats);
  run.report = mesh::validateMesh(run.mesh);
  return run;
}

std::size_t complexLeavesAtMaxLevel(const LinearOctree& tree) {
  std::size_t n = 0;
  for (const auto& l : tree.leaves()) n += l.complex ? 1 : 0;
  return n;
}

// ---------------------------------------------------------------------------

TEST(AdaptiveContour, SphereIsClosedOutwardAndIntersectionFree) {
  const V3 c{32.3, 31.8, 32.1};
  const cell::MetaCellSamples s = cell::makeMetaCellSamples(64, {0, 0, 0}, [&](int x, int y, int z) {
    return sphereSdf({double(x), double(y), double(z)}, c, 20.4);
  });
  // minDepth 4 (4-voxel cells): on a smooth sphere the QEF criterion alone barely refines.
  octree::OctreeOptions options = adaptiveTree();
  options.minDepth = 4;
  const LinearOctree tree = octree::buildOctree(s, kAdaptive, options);
  const ContourRun run = contourAndValidate(s, tree, true);
  EXPECT_TRUE(run.report.closed);
  EXPECT_TRUE(run.report.manifold);
  EXPECT_EQ(run.report.eulerCharacteristic, 2);
  EXPECT_EQ(run.report.selfIntersectingPairs, 0);
  EXPECT_EQ(run.report.inconsistentlyOrientedEdges, 0);
  EXPECT_EQ(run.stats.boundaryEdges, 0);
  EXPECT_EQ(run.stats.edgesWithoutVertex, 0);
  EXPECT_GT(signedVolume(run.mesh), 0.9 * 4.0 / 3.0 * M_PI * 20.4 * 20.4 * 20.4);
  double sum = 0;
  for (const auto& p : run.mesh.positions) sum += std::abs(sphereSdf(toV3(p), c, 20.4));
  const double mean = sum / static_cast<double>(run.mesh.positions.size());
  std::printf(
      "sphere: %zu leaves, %zu tris, %lld minimal edges (%lld quads, %lld tris), %lld fanned, +%lld tris, "
      "mean |d| %.4f\n",
      tree.leafCount(), run.mesh.triangles.size(), (long long)run.stats.minimalEdges, (long long)run.stats.quads,
      (long long)run.stats.triangles3, (long long)run.stats.fannedEdges, (long long)run.stats.trianglesAddedByFans,
      mean);
  EXPECT_LT(mean, 0.5);
}

/// QEF tolerance (RMS voxels) of the geometric refinement used by these tests:
/// the default of adaptive mode (OctreeContourOptions::qefTolerance). On the
/// interface distance field it keeps adaptive meshes of analytic solids as close
/// to the surface as 0.25 did on topologyToLevelSet's noisier field, with as
/// many vertices (bench/field_accuracy.py).
constexpr float kQefTolerance = 0.15f;

float testTolerance() { return kQefTolerance; }

struct ShapeCase {
  samples::ShapeKind kind;
  const char* name;
};

constexpr ShapeCase kShapes[] = {{samples::ShapeKind::Sphere, "sphere"},
                                 {samples::ShapeKind::Torus, "torus"},
                                 {samples::ShapeKind::Genus2, "genus2"},
                                 {samples::ShapeKind::GyroidSlab, "gyroid-slab"},
                                 {samples::ShapeKind::SaltDome, "salt-dome"}};

double meanDistance(const mesh::Mesh& m, const cell::MetaCellSamples& s) {
  double sum = 0;
  for (const auto& p : m.positions) sum += std::abs(trilinear(s, toV3(p)));
  return m.positions.empty() ? 0.0 : sum / static_cast<double>(m.positions.size());
}

TEST(AdaptiveContour, ShapesClosedIntersectionFreeWithFewFans) {
  std::int64_t plainIntersections = 0;
  for (const ShapeCase& shape : kShapes) {
    SCOPED_TRACE(shape.name);
    const cell::MetaCellSamples s = shapeSamples(shape.kind, 64, 128, 32);
    octree::OctreeBuildStats buildStats;
    const LinearOctree tree = octree::buildOctree(s, kAdaptive, adaptiveTree(testTolerance()), &buildStats);
    const ContourRun fans = contourAndValidate(s, tree, true);
    const ContourRun plain = contourAndValidate(s, tree, false);
    const std::size_t complexLeaves = complexLeavesAtMaxLevel(tree);
    const int chi = 2 * samples::knownEulerCharacteristic(shape.kind);  // surface of a solid: twice its chi
    const double overhead = static_cast<double>(fans.mesh.triangles.size()) / plain.mesh.triangles.size() - 1.0;
    std::printf(
        "%-12s leaves %7zu complex@max %3zu | fans: tris %7zu verts %7zu fanned %5lld (uncrossed %lld) (+%lld tris, "
        "%.2f%%) "
        "closed %d manifold %d chi %lld (expected %d) selfX %lld | plain: tris %7zu closed %d chi %lld selfX %lld "
        "| mean|d| %.3f\n",
        shape.name, tree.leafCount(), complexLeaves, fans.mesh.triangles.size(), fans.mesh.positions.size(),
        (long long)fans.stats.fannedEdges, (long long)fans.stats.uncrossedFaceEdges,
        (long long)fans.stats.trianglesAddedByFans, 100 * overhead, fans.report.closed, fans.report.manifold,
        (long long)fans.report.eulerCharacteristic, chi, (long long)fans.report.selfIntersectingPairs,
        plain.mesh.triangles.size(), plain.report.closed, (long long)plain.report.eulerCharacteristic,
        (long long)plain.report.selfIntersectingPairs, meanDistance(fans.mesh, s));
    EXPECT_TRUE(fans.report.closed);
    EXPECT_EQ(fans.report.selfIntersectingPairs, 0);
    EXPECT_EQ(fans.report.inconsistentlyOrientedEdges, 0);
    EXPECT_EQ(fans.stats.boundaryEdges, 0);
    EXPECT_EQ(fans.stats.edgesWithoutVertex, 0);
    EXPECT_GT(signedVolume(fans.mesh), 0.0);
    if (complexLeaves == 0) {
      EXPECT_EQ(fans.report.eulerCharacteristic, chi);
    }
    EXPECT_LT(overhead, 0.15);
    EXPECT_EQ(plain.mesh.triangles.size(), static_cast<std::size_t>(2 * plain.stats.quads + plain.stats.triangles3));
    plainIntersections += plain.report.selfIntersectingPairs;
  }
  // The fans matter: plain dual contouring self-intersects on at least one input.
  EXPECT_GT(plainIntersections, 0);
}

TEST(AdaptiveContour, SaltDomeThreeTimesFewerTrianglesThanRegularWithinHalfAVoxel) {
  const cell::MetaCellSamples s = shapeSamples(samples::ShapeKind::SaltDome, 64, 128, 32);
  const LinearOctree adaptive = octree::buildOctree(s, kAdaptive, adaptiveTree(testTolerance()));
  // Regular reference: plain DC on the regular tree = 2 triangles per bipolar minimal edge.
  constexpr cell::ContourSettings regularSettings{.method = cell::ContourMethod::Regular, .intersectionFree = false};
  octree::OctreeOptions regularOptions = adaptiveTree();
  regularOptions.qefTolerance = -1;
  const LinearOctree regular = octree::buildOctree(s, regularSettings, regularOptions);
  const ContourRun a = contourAndValidate(s, adaptive, true);
  AdaptiveContourStats regularStats;
  const mesh::Mesh r = contourAdaptive(s, regular, regularSettings, &regularStats);
  const double ratio = static_cast<double>(r.triangles.size()) / a.mesh.triangles.size();
  const double mean = meanDistance(a.mesh, s);
  std::printf("salt dome: adaptive %zu tris (%zu leaves), regular %zu tris (%zu leaves), ratio %.2f, mean|d| %.3f\n",
              a.mesh.triangles.size(), adaptive.leafCount(), r.triangles.size(), regular.leafCount(), ratio, mean);
  EXPECT_GE(ratio, 3.0);
  EXPECT_LT(mean, 0.5);
  EXPECT_EQ(a.report.selfIntersectingPairs, 0);
}

// ---- sharp features ---------------------------------------------------------

using test::distanceToMesh;

double nearestVertex(const mesh::Mesh& m, const V3& p) {
  double best = std::numeric_limits<double>::max();
  for (const auto& q : m.positions) best = std::min(best, len(sub(p, toV3(q))));
  return best;
}

/// Feature errors of a mesh: max distance from the corners to the nearest vertex and
/// max distance from points along the feature lines (0.5 voxel off the corners) to the surface.
struct FeatureError {
  double corner = 0;
  double line = 0;
};

/// The mesh vertex strictly inside each listed leaf (the leaf's dual vertex; face and
/// edge points lie on cell boundaries), or none.
std::vector<V3> leafVertices(const mesh::Mesh& m, const LinearOctree& tree, const std::vector<std::size_t>& leaves) {
  std::vector<V3> out;
  for (std::size_t index : leaves) {
    const octree::OctreeLeaf& l = tree.leaf(index);
    for (const auto& q : m.positions) {
      bool inside = true;
      for (int a = 0; a < 3 && inside; ++a) {
        const double lo = tree.origin()[a] + l.origin[a];
        inside = q[a] > lo + 1e-4 && q[a] < lo + l.size - 1e-4;
      }
      if (inside) {
        out.push_back(toV3(q));
        break;
      }
    }
  }
  return out;
}

/// Leaves containing the points (meta-cell offsets = global coordinates here, origin 0).
std::vector<std::size_t> leavesOnFeature(const LinearOctree& tree, const std::vector<V3>& points) {
  std::vector<std::size_t> leaves;
  for (const V3& p : points) {
    const std::int64_t l = tree.findLeafContaining(
        std::array<float, 3>{static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])});
    if (l != LinearOctree::kNone) leaves.push_back(static_cast<std::size_t>(l));
  }
  std::sort(leaves.begin(), leaves.end());
  leaves.erase(std::unique(leaves.begin(), leaves.end()), leaves.end());
  return leaves;
}

/// Octree options of the sharp-feature tests: 8-voxel cells at least (minDepth 3
/// at S = 64; at minDepth 2 the whole shape is 8 cells), adaptive below. With
/// 4-voxel cells the Prewitt normals of crossings within ~1 voxel of a feature
/// are blended, the QEF minimiser leaves the cell and the dual vertex falls back
/// to the mass point (errors up to 2.5 voxels; dual_vertex.cc, not contouring).
octree::OctreeOptions featureTree() {
  octree::OctreeOptions o = adaptiveTree();
  o.minDepth = 3;
  return o;
}

/// `sharp`: ContourSettings::sharpFeatures (crease crossings and the feature gap criterion),
/// read by the octree and the contouring alike.
cell::ContourSettings featureSettings(bool sharp) {
  cell::ContourSettings settings = kAdaptive;
  settings.sharpFeatures = sharp;
  return settings;
}

/// A sharp-feature test's tree and mesh (Ju–Udeshi fans), checked closed, intersection-free, genus 0.
struct FeatureRun {
  octree::OctreeBuildStats build;
  LinearOctree tree;
  ContourRun run;
};

FeatureRun contourFeatures(const cell::MetaCellSamples& samples, bool sharp) {
  FeatureRun f;
  const cell::ContourSettings settings = featureSettings(sharp);
  f.tree = octree::buildOctree(samples, settings, featureTree(), &f.build);
  f.run.mesh = contourAdaptive(samples, f.tree, settings, &f.run.stats);
  f.run.report = mesh::validateMesh(f.run.mesh);
  EXPECT_TRUE(f.run.report.closed);
  EXPECT_EQ(f.run.report.selfIntersectingPairs, 0);
  EXPECT_EQ(f.run.report.eulerCharacteristic, 2);
  return f;
}

/// The same SDF as an OpenVDB level set (narrow band 3) for the reference mesher.
using test::levelSetVolume;

TEST(AdaptiveContour, SharpCubeKeepsEdgesAndCornersUnlikeMarchingCubes) {
  const V3 c{32.37, 31.71, 32.23}, h{12.3, 11.6, 10.9};
  auto sdf = [&](const V3& p) { return boxSdf(p, c, h); };
  const cell::MetaCellSamples s = cell::makeMetaCellSamples(64, {0, 0, 0}, [&](int x, int y, int z) {
    return sdf({double(x), double(y), double(z)});
  });
  const mesh::Mesh mc = contourWithOpenVdb(levelSetVolume(64, sdf));
  // Prewitt normals already do on a cube's 8-voxel cells; crease crossings too.
  for (const bool sharp : {false, true}) {
    SCOPED_TRACE(sharp ? "sharp features" : "Prewitt normals");
    const FeatureRun f = contourFeatures(s, sharp);
    const LinearOctree& tree = f.tree;
    const ContourRun& run = f.run;
    FeatureError dc, ref;
    // Distance from a point to the cube's 12 edges.
    auto edgeDistance = [&](const V3& p) {
      double best = std::numeric_limits<double>::max();
      for (int axis = 0; axis < 3; ++axis)
        for (int q = 0; q < 4; ++q) {
          const int u = (axis + 1) % 3, v = (axis + 2) % 3;
          const double du = p[u] - (c[u] + ((q & 1) ? h[u] : -h[u])), dv = p[v] - (c[v] + ((q & 2) ? h[v] : -h[v]));
          const double da = std::max(std::abs(p[axis] - c[axis]) - h[axis], 0.0);
          best = std::min(best, std::sqrt(du * du + dv * dv + da * da));
        }
      return best;
    };
    std::vector<V3> featurePoints;
    for (int corner = 0; corner < 8; ++corner) {
      V3 p;
      for (int a = 0; a < 3; ++a) p[a] = c[a] + (((corner >> a) & 1) ? h[a] : -h[a]);
      dc.corner = std::max(dc.corner, nearestVertex(run.mesh, p));
      ref.corner = std::max(ref.corner, nearestVertex(mc, p));
    }
    for (int axis = 0; axis < 3; ++axis)
      for (int q = 0; q < 4; ++q) {
        V3 p = c;
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        p[u] += (q & 1) ? h[u] : -h[u];
        p[v] += (q & 2) ? h[v] : -h[v];
        for (double t = -h[axis] + 0.5; t <= h[axis] - 0.5; t += 0.25) {
          p[axis] = c[axis] + t;
          featurePoints.push_back(p);
          dc.line = std::max(dc.line, distanceToMesh(run.mesh, p));
          ref.line = std::max(ref.line, distanceToMesh(mc, p));
        }
      }
    // The dual vertex of every leaf the edges cross lies on the edges.
    double vertexError = 0;
    const std::vector<std::size_t> featureLeaves = leavesOnFeature(tree, featurePoints);
    const std::vector<V3> featureVertices = leafVertices(run.mesh, tree, featureLeaves);
    EXPECT_EQ(featureVertices.size(), featureLeaves.size());
    for (const V3& v : featureVertices) vertexError = std::max(vertexError, edgeDistance(v));
    std::printf(
        "cube%s: %zu tris; corner error %.4f (OpenVDB MC-style %.4f), edge-to-surface %.4f (OpenVDB %.4f), "
        "max vertex-to-edge %.4f over %zu feature leaves\n",
        sharp ? " (sharp features)" : "", run.mesh.triangles.size(), dc.corner, ref.corner, dc.line, ref.line,
        vertexError, featureLeaves.size());
    EXPECT_LT(vertexError, 0.1);
    EXPECT_LT(dc.corner, 0.1);
    EXPECT_LT(dc.line, 0.1);
    EXPECT_GT(ref.line, 0.1);  // Marching-Cubes-like meshing cuts the edges
  }
}

// With Prewitt normals the dual vertex of a leaf on a curved rim sits where the
// tangent planes of its crossings meet, outside the circle by about
// r (1 / cos(theta / 2) - 1) for crossings theta apart (0.66 voxel median on
// 8-voxel cells here), with an almost exact QEF fit; refining by the QEF
// residual cannot see it, and on small cells the Prewitt normals blend the two
// faces. With sharp features (cell::ContourSettings::sharpFeatures) the rim's
// leaves are refined until their vertex is on the zero level (octree/surface_gap.h)
// and crossings near the crease come from their own face (crease_crossing.h):
// every leaf the rim passes through has its vertex within 0.1 voxel of the rim.
TEST(AdaptiveContour, SharpCylinderKeepsItsRimsWithSharpFeatures) {
  const int size = 64;
  const V3 c{32.41, 31.63, 32.27};
  const double r = 14.3, hh = 11.2;
  auto sdf = [&](const V3& p) { return cylinderSdf(p, c, r, hh); };
  const cell::MetaCellSamples s = cell::makeMetaCellSamples(size, {0, 0, 0}, [&](int x, int y, int z) {
    return sdf({double(x), double(y), double(z)});
  });
  const mesh::Mesh mc = contourWithOpenVdb(levelSetVolume(size, sdf));
  auto rimDistance = [&](const V3& p) {
    const double rho = std::hypot(p[0] - c[0], p[1] - c[1]) - r;
    const double dz = std::min(std::abs(p[2] - (c[2] - hh)), std::abs(p[2] - (c[2] + hh)));
    return std::hypot(rho, dz);
  };
  std::vector<V3> featurePoints;
  for (int side = -1; side <= 1; side += 2)
    for (int i = 0; i < 720; ++i) {
      const double a = 2 * M_PI * i / 720;
      featurePoints.push_back({c[0] + r * std::cos(a), c[1] + r * std::sin(a), c[2] + side * hh});
    }
  double refLine = 0;
  for (const V3& p : featurePoints) refLine = std::max(refLine, distanceToMesh(mc, p));
  for (const bool sharp : {false, true}) {
    SCOPED_TRACE(sharp ? "sharp features" : "Prewitt normals");
    const FeatureRun f = contourFeatures(s, sharp);
    const LinearOctree& tree = f.tree;
    const ContourRun& run = f.run;
    double dcLine = 0;
    for (const V3& p : featurePoints) dcLine = std::max(dcLine, distanceToMesh(run.mesh, p));
    // The vertices that represent the rim: those of the leaves it passes through.
    const std::vector<std::size_t> featureLeaves = leavesOnFeature(tree, featurePoints);
    const std::vector<V3> featureVertices = leafVertices(run.mesh, tree, featureLeaves);
    EXPECT_EQ(featureVertices.size(), featureLeaves.size());
    std::vector<double> errors;
    for (const V3& v : featureVertices) errors.push_back(rimDistance(v));
    std::sort(errors.begin(), errors.end());
    ASSERT_FALSE(errors.empty());
    const double median = errors[errors.size() / 2], p90 = errors[errors.size() * 9 / 10], max = errors.back();
    std::printf(
        "cylinder%s: %zu tris (%zu feature splits); rim vertex errors over %zu feature leaves: median %.4f, "
        "90%% %.4f, max %.4f; rim-to-surface %.4f (OpenVDB MC-style %.4f)\n",
        sharp ? " (sharp features)" : "", run.mesh.triangles.size(), f.build.featureSplits, featureLeaves.size(),
        median, p90, max, dcLine, refLine);
    EXPECT_LT(dcLine, 0.5 * refLine);
    EXPECT_GT(refLine, 0.1);
    if (sharp) {
      EXPECT_LT(median, 0.1);
      EXPECT_LT(max, 0.1);
      EXPECT_LT(dcLine, 0.1);
    } else {
      EXPECT_LT(median, refLine);
    }
  }
}

// ---- topology: several sheets in one cell, hidden components ------------------

/// Adaptive tree down to 1-voxel cells from the root (no QEF criterion), contoured and validated.
ContourRun contourRandom(const cell::MetaCellSamples& samples, bool manifoldFix,
                         octree::OctreeBuildStats* buildStats = nullptr) {
  cell::ContourSettings settings = kAdaptive;
  settings.manifoldFix = manifoldFix;
  const LinearOctree tree =
      octree::buildOctree(samples, settings, octree::OctreeOptions{.minDepth = 0, .qefTolerance = -1.0f}, buildStats);
  ContourRun run;
  run.mesh = contourAdaptive(samples, tree, settings, &run.stats);
  run.report = mesh::validateMesh(run.mesh);
  return run;
}

TEST(AdaptiveContour, RandomSignFieldsGiveClosedManifoldMeshes) {
  // Sign noise is full of 1-voxel ambiguous faces, several sheets per cell and doubled
  // faces: one vertex per leaf would make non-manifold edges here.
  std::mt19937 rng(11);
  std::int64_t multiVertex = 0, fixes = 0, brokenWithoutFix = 0, multiSheetSplits = 0, selfIntersections = 0;
  for (int trial = 0; trial < 30; ++trial) {
    std::bernoulli_distribution inside(trial % 2 ? 0.3 : 0.5);
    std::uniform_real_distribution<float> magnitude(0.1f, 1.0f);
    const cell::MetaCellSamples s = cell::makeMetaCellSamples(16, {0, 0, 0}, [&](int x, int y, int z) {
      if (x < 1 || y < 1 || z < 1 || x > 15 || y > 15 || z > 15) return 1.0f;
      return inside(rng) ? -magnitude(rng) : magnitude(rng);
    });
    octree::OctreeBuildStats build;
    const ContourRun r = contourRandom(s, true, &build);
    EXPECT_TRUE(r.report.closed) << trial;
    EXPECT_EQ(r.report.nonManifoldEdges, 0) << trial;
    EXPECT_EQ(r.report.inconsistentlyOrientedEdges, 0) << trial;
    EXPECT_EQ(r.stats.edgesWithoutVertex, 0) << trial;
    multiVertex += r.stats.multiVertexCells;
    fixes += r.stats.manifoldFixes;
    multiSheetSplits += static_cast<std::int64_t>(build.multiSheetSplits);
    selfIntersections += r.report.selfIntersectingPairs;
    brokenWithoutFix += contourRandom(s, false).report.nonManifoldEdges > 0;
  }
  EXPECT_GT(multiVertex, 0);
  EXPECT_GT(multiSheetSplits, 0);
  EXPECT_GT(fixes, 0);
  EXPECT_GT(brokenWithoutFix, 0) << "Wenger's fix matters in adaptive mode too";
  std::printf(
      "[random adaptive] multiVertexCells=%lld manifoldFixes=%lld multiSheetSplits=%lld "
      "nonManifoldWithoutFix=%lld/30 selfIntersectingPairs=%lld\n",
      static_cast<long long>(multiVertex), static_cast<long long>(fixes), static_cast<long long>(multiSheetSplits),
      static_cast<long long>(brokenWithoutFix), static_cast<long long>(selfIntersections));
}

TEST(AdaptiveContour, BubbleHiddenInACoarseCellIsKept) {
  // A sphere whose inside holds a 1-voxel outside bubble away from every coarse face:
  // without the hidden-component criterion the coarse leaf around it swallows it.
  cell::MetaCellSamples s = cell::makeMetaCellSamples(64, {0, 0, 0}, [](int x, int y, int z) {
    return static_cast<float>(std::sqrt((x - 30.3) * (x - 30.3) + (y - 31.1) * (y - 31.1) + (z - 29.7) * (z - 29.7)) -
                              20.0);
  });
  // The bubble: a voxel 1.5+ voxels inside, odd coordinates (off the faces of every
  // cell of 2 voxels or more), in an 8-voxel cell whose corners the surface separates.
  std::array<int, 3> bubble{-1, -1, -1};
  for (int z = 1; z < 64 && bubble[0] < 0; z += 2)
    for (int y = 1; y < 64 && bubble[0] < 0; y += 2)
      for (int x = 1; x < 64 && bubble[0] < 0; x += 2) {
        if (s.value(x, y, z) > -1.5f) continue;
        const int cx = x / 8 * 8, cy = y / 8 * 8, cz = z / 8 * 8;
        bool anyOutside = false;
        for (int c = 0; c < 8; ++c)
          anyOutside |= s.value(cx + (c & 1) * 8, cy + ((c >> 1) & 1) * 8, cz + ((c >> 2) & 1) * 8) > 0.0f;
        if (anyOutside) bubble = {x, y, z};
      }
  ASSERT_GE(bubble[0], 0);
  s.value(bubble[0], bubble[1], bubble[2]) = 0.5f;
  octree::OctreeBuildStats build;
  const LinearOctree tree = octree::buildOctree(s, kAdaptive, adaptiveTree(), &build);
  EXPECT_GT(build.hiddenComponentSplits, 0u);
  const ContourRun r = contourAndValidate(s, tree, true);
  EXPECT_TRUE(r.report.closed);
  EXPECT_EQ(r.report.components, 2);
  EXPECT_EQ(r.report.eulerCharacteristic, 4);
  EXPECT_EQ(r.report.selfIntersectingPairs, 0);
}

// ---- determinism, options, boundary -------------------------------------------

TEST(AdaptiveContour, DeterministicForOneAndEightThreads) {
  const cell::MetaCellSamples s = shapeSamples(samples::ShapeKind::GyroidSlab, 64, 128, 32);
  const LinearOctree tree = octree::buildOctree(s, kAdaptive, adaptiveTree(testTolerance()));
  mesh::Mesh meshes[2];
  AdaptiveContourStats stats[2];
  const int threads[2] = {1, 8};
  for (int i = 0; i < 2; ++i) {
    tbb::task_arena arena(threads[i]);
    arena.execute([&] { meshes[i] = contourAdaptive(s, tree, kAdaptive, &stats[i]); });
  }
  EXPECT_EQ(meshes[0].positions, meshes[1].positions);
  EXPECT_EQ(meshes[0].triangles, meshes[1].triangles);
  EXPECT_EQ(stats[0].fannedEdges, stats[1].fannedEdges);
  EXPECT_GT(meshes[0].triangles.size(), 1000u);
}

TEST(AdaptiveContour, SizeMismatchThrows) {
  const cell::MetaCellSamples s = cell::makeMetaCellSamples(16, {0, 0, 0}, [](int x, int, int) { return x - 7.5; });
  const cell::MetaCellSamples t = cell::makeMetaCellSamples(32, {0, 0, 0}, [](int x, int, int) { return x - 7.5; });
  const LinearOctree tree = octree::buildOctree(t, kAdaptive, adaptiveTree());
  EXPECT_THROW(contourAdaptive(s, tree, kAdaptive), InputError);
}

TEST(AdaptiveContour, EdgesOnTheMetaCellBoundaryAreSkipped) {
  // A plane crossing the whole meta-cell: its polygons along the boundary are left to stitching.
  const cell::MetaCellSamples s =
      cell::makeMetaCellSamples(16, {0, 0, 0}, [](int x, int y, int z) { return 0.3 * x + 0.2 * y + 0.1 * z - 4.1; });
  AdaptiveContourStats stats;
  const mesh::Mesh m = contourAdaptive(s, octree::buildOctree(s, kAdaptive, adaptiveTree()), kAdaptive, &stats);
  EXPECT_GT(stats.boundaryEdges, 0);
  EXPECT_GT(m.triangles.size(), 0u);
  const mesh::MeshReport report = mesh::validateMesh(m);
  EXPECT_FALSE(report.closed);
  EXPECT_EQ(report.selfIntersectingPairs, 0);
}

}  // namespace
}  // namespace isovdb::contour
