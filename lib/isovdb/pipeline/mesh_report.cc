// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/mesh_report.h"

#include "isovdb/io/dense_volume.h"
#include "isovdb/store/vdb_file.h"
#include "isovdb/volume/digital_topology.h"
#include "isovdb/volume/distance_field.h"

namespace isovdb::pipeline {

Statistics::Json toJson(const mesh::MeshReport& report) {
  Statistics::Json json = Statistics::Json::object();
  json["vertices"] = report.vertices;
  json["referenced_vertices"] = report.referencedVertices;
  json["triangles"] = report.triangles;
  json["edges"] = report.edges;
  json["closed"] = report.closed;
  json["manifold"] = report.manifold;
  json["boundary_edges"] = report.boundaryEdges;
  json["non_manifold_edges"] = report.nonManifoldEdges;
  json["non_manifold_vertices"] = report.nonManifoldVertices;
  json["inconsistently_oriented_edges"] = report.inconsistentlyOrientedEdges;
  json["degenerate_triangles"] = report.degenerateTriangles;
  json["self_intersecting_pairs"] = report.selfIntersectingPairs;
  json["components"] = report.components;
  json["euler_characteristic"] = report.eulerCharacteristic;
  json["signed_volume"] = report.signedVolume;
  Statistics::Json components = Statistics::Json::array();
  for (const mesh::ComponentReport& c : report.componentReports) {
    components.push_back({{"triangles", c.triangles},
                          {"vertices", c.vertices},
                          {"euler_characteristic", c.eulerCharacteristic},
                          {"closed", c.closed},
                          {"genus", c.genus},
                          {"signed_volume", c.signedVolume}});
  }
  // Thousands of specks would drown the report: keep the largest 10 in the JSON.
  if (components.size() > 10) {
    std::stable_sort(components.begin(), components.end(),
                     [](const auto& a, const auto& b) { return a["triangles"] > b["triangles"]; });
    components.erase(components.begin() + 10, components.end());
  }
  json["largest_components"] = components;
  return json;
}

Statistics::Json meshReportJson(const mesh::Mesh& mesh, const mesh::ValidateOptions& options) {
  return toJson(mesh::validateMesh(mesh, options));
}

bool passesGuarantees(const mesh::MeshReport& report) {
  return report.closed && report.manifold && report.selfIntersectingPairs <= 0;
}

std::int64_t solidEulerCharacteristic(const std::filesystem::path& path, const InputOptions& options,
                                      volume::Adjacency adjacency, Interrupter* interrupter) {
  if (!isVdbPath(path)) {
    std::unique_ptr<io::SliceStream> stream = io::openDenseVolume(path, options.raw);
    return volume::eulerCharacteristic(*stream, options.rule, interrupter, adjacency);
  }
  const volume::Volume volume = store::readVdb(path, options.gridName);
  switch (volume.kind()) {
    case volume::VolumeKind::Mask:
      return volume::eulerCharacteristic(volume, interrupter, adjacency);
    case volume::VolumeKind::DistanceField:
      return volume::eulerCharacteristic(volume::interiorMask(volume), interrupter, adjacency);
    case volume::VolumeKind::Scalar:
      break;
  }
  throw InputError("'" + path.string() + "': a scalar grid has no solid to compare with; use a mask or level set");
}

}  // namespace isovdb::pipeline
