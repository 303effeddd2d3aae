// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/extract_settings.h"

#include <algorithm>

#include "isovdb/errors.h"
#include "isovdb/octree/build.h"

namespace isovdb::pipeline {

namespace {

std::string settingName(std::string_view name, bool keywords) {
  return keywords ? keywordOf(name) : "--" + std::string(name);
}

}  // namespace

std::string keywordOf(std::string_view name) {
  std::string keyword(name);
  std::replace(keyword.begin(), keyword.end(), '-', '_');
  return keyword;
}

ExtractOptions ExtractChoices::resolve(bool keywords) const {
  ExtractOptions result = options;
  result.contour.method = parseNamed(cell::kContourMethodNames, method, settingName("method", keywords), "method");
  result.regularTopology.reset();
  if (topology != "auto") {
    result.regularTopology = parseRegularTopology(topology);
    if (!result.regularTopology)
      throw InputError(settingName("topology", keywords) + ": unknown reading '" + topology + "', expected auto, " +
                       nameList(cell::kRegularTopologyNames));
  }
  result.boundary = parseNamed(kBoundaryModeNames, boundary, settingName("boundary", keywords), "mode");
  result.scalarInside = parseNamed(kScalarInsideNames, inside, settingName("inside", keywords), "side");
  result.distance = DistanceChoices{options.distance, distance}.resolve(keywords);
  return result;
}

volume::DistanceFieldOptions DistanceChoices::resolve(bool keywords) const {
  volume::DistanceFieldOptions result = options;
  result.method = parseNamed(volume::kDistanceMethodNames, method, settingName("distance", keywords), "method");
  return result;
}

std::vector<Setting> distanceSettings(volume::DistanceFieldOptions& o, std::string& method) {
  return {
      {"distance",
       "Distance field of a mask. interface: sub-voxel distances at the mask's interface from a small Gaussian "
       "blur, the band along the nearest interface voxel's tangent plane (fast; every sign the mask's). tracker: "
       "OpenVDB's topologyToLevelSet + sdfToSdf (slow; for comparison)",
       &method},
      {"half-width", "Distance-field band half-width (voxels)", &o.halfWidth},
      {"sdf-chunk",
       "Distance field computed in cubes of this many voxels (multiple of 8; sdf writes each to the file as it "
       "finishes); 0 = tracker: the whole band at once, in memory",
       &o.chunkSize},
      {"closing", "Morphological closing steps before the distance field, 0..64 (changes topology)", &o.closingSteps},
  };
}

// --qef-tolerance's help states the share.
static_assert(octree::kBoundedQefShare == 0.45f);

std::vector<Setting> extractSettings(ExtractChoices& c) {
  ExtractOptions& o = c.options;
  std::vector<Setting> result{
      {"method",
       "Contouring method: adaptive (adaptive octree + dual contouring with Ju-Udeshi fans: closed, "
       "manifold, free of self-intersections, the mask's topology, far fewer triangles, within --max-error of "
       "the full-resolution surface), regular (octree + "
       "manifold DMC: closed, manifold, the mask's topology, free of self-intersections), vdb (OpenVDB's "
       "volumeToMesh, the reference)",
       &c.method},
      {"iso",
       "Isovalue: voxels on distance fields (0 = the mask boundary, > 0 grows the surface), field units on "
       "scalars. Not given: 0 on masks and distance fields, the middle of the values' range on scalar fields "
       "(scikit-image's rule)",
       &o.iso},
      {"inside",
       "Scalar fields: the object's side of the isovalue, above (density, CT, amplitude) or below (a signed "
       "distance negative inside); masks and distance fields keep their own",
       &c.inside},
      {"adaptivity", "vdb method: OpenVDB's adaptivity in [0, 1]", &o.adaptivity},
  };
  // Then the distance field's, then the octree methods'.
  const std::vector<Setting> field = distanceSettings(o.distance, c.distance);
  result.insert(result.end(), field.begin(), field.end());
  result.insert(
      result.end(),
      {
          {"meta-cell",
           "regular/adaptive: meta-cell size in voxels (power of two, 16..512; 0 = one block around the whole "
           "volume, no stitching)",
           &o.metaCellSize},
          {"threads", "Worker threads (0 = every core); the output is the same", &o.threads},
          {"min-level",
           "regular/adaptive: uniform subdivision down to this depth under the meta-cell (-1: --max-cell-size decides)",
           &o.octree.minDepth},
          {"max-cell-size", "regular/adaptive: largest cell in voxels when --min-level is -1", &o.octree.maxCellSize},
          {"max-level", "regular/adaptive: deepest level under the meta-cell (-1: --finest-size decides)",
           &o.octree.maxDepth},
          {"finest-size", "regular/adaptive: smallest cell in voxels (1, 2, 4, ...) when --max-level is -1",
           &o.octree.finestCellSize},
          {"qef-tolerance",
           "adaptive: split cells whose QEF residual (RMS, voxels) exceeds this; < 0 off. With --max-error E, cells "
           "use 0.45 E where that is larger, also when this is off (the bound needs the criterion on seams)",
           &o.octree.qefTolerance},
          {"max-error",
           "adaptive: error bound in voxels: the mesh stays within this distance of the full-resolution surface "
           "(regular mode's mesh), both ways (isovdb compare measures it); 1 keeps most of adaptive mode's savings "
           "on smooth bodies; <= 0 off",
           &o.octree.maxError},
          {"intersection-free",
           "adaptive and regular: Ju-Udeshi fans where plain dual contouring would self-intersect (off: plain DC, "
           "regular: the better quad diagonal and polygons fanned from a corner, for comparison)",
           &o.contour.intersectionFree, /*negatable=*/true},
          {"sharp-features",
           "adaptive: keep the sharp edges and corners of an exact distance field (e.g. a CAD level set .vdb). Off by "
           "default: a field made from a voxel mask has a crease at every staircase step, and following them costs "
           "35-50% more triangles",
           &o.contour.sharpFeatures},
          {"boundary",
           "Surfaces reaching the data boundary (survey edge): cap (closed mesh, caps on the boundary) or open (caps "
           "dropped, the mesh ends on the boundary)",
           &c.boundary},
          {"topology",
           "regular and adaptive: reading of ambiguous cells. voxels: the voxel object's topology (26-connected "
           "inside, 6-connected "
           "outside; Euler characteristic 2x the mask's), mdmc: Wenger's manifold DMC, auto: voxels for masks, mdmc "
           "for fields",
           &c.topology},
      });
  return result;
}

}  // namespace isovdb::pipeline
