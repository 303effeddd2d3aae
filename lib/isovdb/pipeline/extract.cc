// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/extract.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <utility>

#include "isovdb/contour/vdb_mesher.h"
#include "isovdb/errors.h"
#include "isovdb/pipeline/load_volume.h"
#include "isovdb/volume/background.h"
#include "isovdb/volume/ingest.h"
#include "isovdb/volume/meta_cells.h"
#include "isovdb/volume/sampled_box.h"

namespace isovdb::pipeline {

cell::RegularTopology regularTopologyFor(const std::optional<cell::RegularTopology>& chosen, volume::VolumeKind kind) {
  if (chosen) return *chosen;
  return kind == volume::VolumeKind::Mask ? cell::RegularTopology::Voxels : cell::RegularTopology::Mdmc;
}

volume::Volume toContourable(const volume::Volume& volume, const volume::DistanceFieldOptions& options,
                             Interrupter* interrupter, Statistics* stats) {
  if (volume.kind() != volume::VolumeKind::Mask) return volume;
  volume::Volume sdf;
  {
    Statistics::StageTimer timer(stats, "distance_field");
    sdf = volume::distanceField(volume, options, interrupter);
  }
  if (stats) {
    Statistics::Json section = distanceFieldSection(options);
    recordGridStats(sdf, section);
    (*stats)["distance_field"] = section;
  }
  return sdf;
}

volume::Volume withInsideAboveIso(const volume::Volume& volume, ScalarInside inside, float& iso) {
  if (volume.kind() != volume::VolumeKind::Scalar || inside == ScalarInside::Above) return volume;
  iso = -iso;
  return volume::negatedScalar(volume);
}

void indexToWorld(mesh::Mesh& mesh, const volume::Geometry& geometry) {
  const auto& s = geometry.spacing;
  const auto& o = geometry.origin;
  if (s == std::array<double, 3>{1, 1, 1} && o == std::array<double, 3>{0, 0, 0}) return;
  tbb::parallel_for(std::size_t{0}, mesh.positions.size(), [&](std::size_t i) {
    mesh::Vec3f& p = mesh.positions[i];
    for (int a = 0; a < 3; ++a) p[a] = static_cast<float>(o[a] + s[a] * static_cast<double>(p[a]));
  });
  // Normals transform with the inverse transpose of the (diagonal) scale.
  tbb::parallel_for(std::size_t{0}, mesh.normals.size(), [&](std::size_t i) {
    mesh::Vec3f& n = mesh.normals[i];
    double v[3], len = 0;
    for (int a = 0; a < 3; ++a) {
      v[a] = n[a] / s[a];
      len += v[a] * v[a];
    }
    len = std::sqrt(len);
    if (len > 0)
      for (int a = 0; a < 3; ++a) n[a] = static_cast<float>(v[a] / len);
  });
}

namespace {

/// The smallest and largest value of a field. The background counts where it stands for samples:
/// inactive voxels inside the sampled box (a sparse grid's pruned values, SEG-Y's dead band), or
/// everywhere when the grid records no box (a .vdb level set).
std::pair<float, float> valueRange(const volume::Volume& volume) {
  return valueRangeOf(sampleRangeOf(volume), volume::sampledBox(volume));
}

/// An isovalue that cannot meet any surface is refused with the reason, instead of an empty
/// mesh without a word (scikit-image's marching_cubes refuses the same).
/// `range`: the field's valueRange (unused for a mask).
void checkIsoReachesSurface(const volume::Volume& volume, float iso, int halfWidth,
                            const std::optional<std::pair<float, float>>& range) {
  if (!std::isfinite(iso)) throw InputError("--iso: expected a finite number, got " + std::to_string(iso));
  const auto number = [](float v) {
    std::ostringstream text;
    text << v;
    return text.str();
  };
  if (volume.kind() == volume::VolumeKind::Mask) {
    // The mask's distance field exists within the band only: |iso| >= half-width meets none of it.
    if (std::abs(iso) >= static_cast<float>(halfWidth))
      throw InputError("'" + volume.name() + "' is a mask, so --iso " + number(iso) +
                       " is a distance in voxels from its boundary and must lie inside the distance field's band, "
                       "|iso| < --half-width " +
                       std::to_string(halfWidth) +
                       "; to contour the samples' values at an isovalue, read them as a scalar field (--scalar; "
                       "from Python, an array of floats) or make the mask value > ISO (--threshold ISO)");
    return;
  }
  const auto [lo, hi] = *range;
  if (iso < lo || iso > hi)
    throw InputError("'" + volume.name() + "': --iso " + number(iso) + " lies outside the values' range [" +
                     number(lo) + ", " + number(hi) + "]: no surface");
}

/// isoFor with the field's valueRange already walked (`range`, needed only for a scalar
/// field without options.iso).
float isoFor(const volume::Volume& volume, const ExtractOptions& options,
             const std::optional<std::pair<float, float>>& range) {
  if (options.iso) return *options.iso;
  if (volume.kind() != volume::VolumeKind::Scalar) return 0.0f;
  const auto [lo, hi] = *range;
  if (!(lo < hi)) {
    std::ostringstream message;
    message << "'" << volume.name() << "': every value is " << lo
            << ", so no isovalue meets a surface (give --iso to choose one)";
    throw InputError(message.str());
  }
  return lo + 0.5f * (hi - lo);  // not (lo + hi) / 2: that overflows near the float range's ends
}

}  // namespace

float isoFor(const volume::Volume& volume, const ExtractOptions& options) {
  const bool needsRange = !options.iso && volume.kind() == volume::VolumeKind::Scalar;
  return isoFor(volume, options, needsRange ? std::optional(valueRange(volume)) : std::nullopt);
}

SampleRange& SampleRange::operator+=(const SampleRange& other) {
  if (other.active > 0) {
    min = active > 0 ? std::min(min, other.min) : other.min;
    max = active > 0 ? std::max(max, other.max) : other.max;
  }
  active += other.active;
  return *this;
}

SampleRange sampleRangeOf(const volume::Volume& field) {
  const volume::GridStats stats = field.stats();
  return {.active = stats.activeVoxels, .min = stats.minValue, .max = stats.maxValue, .background = stats.background};
}

std::pair<float, float> valueRangeOf(const SampleRange& samples, const std::optional<volume::IndexBox>& box) {
  bool backgroundSampled = samples.active == 0;
  if (box) {
    double count = 1.0;
    for (int a = 0; a < 3; ++a) count *= static_cast<double>(box->max[a]) - box->min[a] + 1.0;
    backgroundSampled = backgroundSampled || static_cast<double>(samples.active) < count;
  } else {
    backgroundSampled = true;
  }
  if (!backgroundSampled) return {samples.min, samples.max};
  return {std::min(samples.active > 0 ? samples.min : samples.background, samples.background),
          std::max(samples.active > 0 ? samples.max : samples.background, samples.background)};
}

int slabHalo(const ExtractOptions& options) {
  constexpr int kLeaf = 8;
  // A layer's samples reach its apron (regular mode: a finest cell) beyond it; the band's
  // values depend on the mask within half-width + 4 voxels (interface_band.h), a closing
  // on 2 x its steps more; the band's partition looks at leaves two leaves beyond.
  const int apron = std::max(1, octree::finestLeafSize(options.octree, std::max(options.metaCellSize, 16)));
  const int reach = apron + options.distance.halfWidth + 4 + 2 * options.distance.closingSteps + 2 * kLeaf;
  return (reach + kLeaf - 1) / kLeaf * kLeaf;
}

void extractInto(volume::Volume volume, const ExtractOptions& options, mesh::MeshSink& sink, Interrupter* interrupter,
                 Statistics* stats, const ExtractPart* part) {
  if (part && (options.contour.method == ContourMethod::Vdb || options.metaCellSize == 0 ||
               options.distance.method != volume::DistanceMethod::Interface))
    throw InputError("'" + volume.name() +
                     "': a distributed run contours in meta-cells with the regular or adaptive method (and a mask's "
                     "interface distance field)");
  if (part && volume.kind() != volume::VolumeKind::Mask && !part->valueRange)
    throw InputError("'" + volume.name() + "': a part of a field's run needs the whole field's value range");
  if (options.threads < 0)
    throw InputError("--threads: expected 0 (every core) or more, got " + std::to_string(options.threads));
  // NaN would compare false everywhere and quietly turn the bound (or the criterion) off.
  if (std::isnan(options.octree.maxError))
    throw InputError("--max-error: expected a number of voxels (<= 0: no bound), got nan");
  if (std::isnan(options.octree.qefTolerance))
    throw InputError("--qef-tolerance: expected a number of voxels (< 0: off), got nan");
  std::optional<tbb::global_control> threads;
  if (options.threads > 0) threads.emplace(tbb::global_control::max_allowed_parallelism, options.threads);
  // The field's range is walked once (a tree walk): the default iso and its check both read it.
  std::optional<std::pair<float, float>> range;
  if (part && part->valueRange)
    range = part->valueRange;
  else if (volume.kind() != volume::VolumeKind::Mask)
    range = valueRange(volume);
  float iso = isoFor(volume, options, range);
  const float givenIso = iso;  // before withInsideAboveIso negates it
  checkIsoReachesSurface(volume, iso, options.distance.halfWidth, range);
  const float deadBand = volume::deadBandOf(volume);
  if (volume.kind() == volume::VolumeKind::Scalar && std::abs(iso) < deadBand) {
    std::ostringstream message;
    message << "'" << volume.name() << "': --iso " << iso << " lies inside the dead band |value| < " << deadBand
            << " (--clip): choose |iso| >= clip or a smaller --clip";
    throw InputError(message.str());
  }
  const volume::VolumeKind kind = volume.kind();
  volume = withInsideAboveIso(volume, options.scalarInside, iso);
  const std::optional<volume::IndexBox> box = volume::sampledBox(volume);
  const ContourMethod method = options.contour.method;
  // A mask contoured by meta-cells gets its distance field layer by layer, as the
  // meta-cells need it; otherwise the whole field is made first.
  const bool byLayers = kind == volume::VolumeKind::Mask && method != ContourMethod::Vdb && options.metaCellSize > 0 &&
                        options.distance.method == volume::DistanceMethod::Interface;
  volume::Volume field;
  if (byLayers) {
    volume::checkDistanceFieldOptions(options.distance);
  } else {
    field = toContourable(volume, options.distance, interrupter, stats);
    // The contouring reads only the field: a mask is freed here unless the caller keeps it.
    volume = volume::Volume();
  }
  // Caps are flattened piece by piece (the mesh still streams); dropping them
  // (Open) needs the whole mesh, so it is collected first.
  const bool open = box && options.boundary == BoundaryMode::Open;
  // The octree methods make their caps while contouring, beside the box's faces: beyond the
  // box they read far outside where they contour by minimal edges (adaptive mode, regular
  // mode in Wenger's reading) and in the voxel reading where the background lies inside the
  // surface (a numpy field 40 - r at iso 0: else the background beyond the array made a box
  // around it); regular mode's others keep the field as it is (capBox). Only the
  // vdb method's caps are flattened onto the box afterwards.
  cell::ContourSettings settings = options.contour;
  settings.iso = iso;
  settings.topology = regularTopologyFor(options.regularTopology, kind);
  // Adaptive mode reads a mask as the voxel object too where its finest leaves are one voxel
  // (a meta-cell size that is no power of two is refused further on, with its own message).
  const int metaCell = options.metaCellSize;
  const int finestLeaf = metaCell > 0 && (metaCell & (metaCell - 1)) == 0
                             ? octree::finestLeafSize(options.octree, metaCell)
                             : options.octree.finestCellSize;
  settings.adaptiveVoxelReading = settings.topology == cell::RegularTopology::Voxels && finestLeaf == 1;
  const bool capsMade = box && (settings.contoursByMinimalEdges() || (method == ContourMethod::Regular && !byLayers &&
                                                                      volume::backgroundInside(field, iso)));
  mesh::MeshCollector whole;
  const bool flattened = box && method == ContourMethod::Vdb;
  CappingSink capped(open ? static_cast<mesh::MeshSink&>(whole) : sink, flattened ? box : std::nullopt);
  if (method == ContourMethod::Vdb) {
    Statistics::StageTimer timer(stats, "contour");
    // volumeToMesh meshes every crossing, the background's too: a background inside the
    // surface (a numpy field 40 - r at iso 0) closed a box around the array. Beyond the
    // sampled box is outside, as in the octree methods: the background moves a step
    // outside (a copy); caps where the body leaves the data are flattened onto the box.
    if (box && volume::backgroundInside(field, iso)) {
      const float step = std::max(1.0f, std::abs(iso) * 1e-3f);  // a float step at any |iso|
      field = volume::withBackground(field, kind == volume::VolumeKind::Scalar ? iso - step : iso + step);
    }
    const mesh::Mesh mesh =
        contour::contourWithOpenVdb(field, {.iso = iso, .adaptivity = options.adaptivity}, interrupter);
    capped.addVertices(mesh.positions);
    capped.addTriangles(mesh.triangles);
  } else {
    octree::OctreeOptions tree = options.octree;
    if (capsMade) settings.dataBox = {{box->min, box->max}};
    if (box && !capsMade) settings.capBox = {{box->min, box->max}};
    if (part && part->received) {
      SeamedMeshAssembler assembler(settings, options.metaCellSize, capped);
      volume::MetaCellIndex index{};
      contour::MetaCellMesh block;
      while (part->received(index, block)) assembler.add(index, std::move(block));
      assembler.finish(interrupter, stats);
    } else if (part && byLayers) {
      contourMaskMetaCellsInto(volume, options.distance, settings, tree, options.metaCellSize, *part->pieces,
                               part->layers, interrupter, stats);
    } else if (part) {
      // The far-outside value beyond the box derives from the whole field's largest |value|.
      const float bound =
          std::max({std::abs(range->first), std::abs(range->second), std::abs(field.stats().background)});
      contourMetaCellsInto(field, settings, tree, options.metaCellSize, *part->pieces, part->layers, bound, interrupter,
                           stats);
    } else if (byLayers)
      contourMaskWithOctree(volume, options.distance, settings, tree, options.metaCellSize, capped, interrupter, stats);
    else
      contourWithOctree(field, settings, tree, options.metaCellSize, capped, interrupter, stats);
  }
  std::int64_t dropped = 0;
  if (open) {
    dropped = applyDataBoundary(whole.mesh, *box, BoundaryMode::Open, flattened);
    sink.addVertices(whole.mesh.positions);
    sink.addTriangles(whole.mesh.triangles);
  }
  if (stats) {
    Statistics::Json& section = (*stats)["contour"];
    if (box) {
      section["boundary"] = std::string(boundaryModeName(options.boundary));
      section["cap_triangles_dropped"] = dropped;
    }
    section["method"] = std::string(contourMethodName(method));
    section["iso"] = givenIso;
    if (!options.iso && kind == volume::VolumeKind::Scalar) section["iso_rule"] = "middle of the values' range";
    if (kind == volume::VolumeKind::Scalar)
      section["inside"] = std::string(nameOf(kScalarInsideNames, options.scalarInside));
    if (method == ContourMethod::Vdb) section["adaptivity"] = options.adaptivity;
    if (method == ContourMethod::Adaptive && options.octree.maxError > 0.0f) {
      section["max_error"] = options.octree.maxError;
      // The bound is kept by splitting leaves down to one voxel: coarser finest cells may stay beyond it.
      section["finest_cell_voxels"] = finestLeaf;
    }
    section["vertices"] = sink.vertexCount();
    section["triangles"] = sink.triangleCount();
  }
}

mesh::Mesh extractMesh(volume::Volume volume, const ExtractOptions& options, Interrupter* interrupter,
                       Statistics* stats) {
  mesh::MeshCollector collector;
  const volume::Geometry geometry = volume.geometry();
  extractInto(std::move(volume), options, collector, interrupter, stats);
  indexToWorld(collector.mesh, geometry);
  return std::move(collector.mesh);
}

}  // namespace isovdb::pipeline
