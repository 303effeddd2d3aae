// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file openvdb_path.cc
/// @brief `isovdb-openvdb-path`: OpenVDB's own mask -> mesh path, the peer row of
///        bench/peers.py: the mask read as isovdb reads it (the same ingest, so only
///        the stages after it differ), then tools::topologyToLevelSet on the whole
///        mask, optionally tools::sdfToSdf, then tools::volumeToMesh, written as a
///        binary PLY. Prints one JSON line: seconds per stage and the peak RSS.
///
///   isovdb-openvdb-path IN [--dims X,Y,Z --type uint8] [--labels L] [--half-width 3]
///                       [--sweep] [--adaptivity A] [-o OUT.ply]
#include <sys/resource.h>

#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tools/TopologyToLevelSet.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <vector>

#include "isovdb/pipeline/load_volume.h"
#include "isovdb/volume/grids.h"

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Binary little-endian PLY of the points and of the triangles and quads (each quad as two triangles).
void writePly(const std::string& path, const std::vector<openvdb::Vec3s>& points,
              const std::vector<openvdb::Vec3I>& triangles, const std::vector<openvdb::Vec4I>& quads) {
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\ncomment OpenVDB volumeToMesh (bench/openvdb_path.cc)\n"
      << "element vertex " << points.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
      << "element face " << triangles.size() + 2 * quads.size() << "\nproperty list uchar int vertex_indices\n"
      << "end_header\n";
  out.write(reinterpret_cast<const char*>(points.data()), static_cast<std::streamsize>(points.size() * 12));
  auto triangle = [&out](unsigned a, unsigned b, unsigned c) {
    const unsigned char three = 3;
    const int ids[3] = {static_cast<int>(a), static_cast<int>(b), static_cast<int>(c)};
    out.write(reinterpret_cast<const char*>(&three), 1);
    out.write(reinterpret_cast<const char*>(ids), 12);
  };
  for (const auto& t : triangles) triangle(t[0], t[1], t[2]);
  for (const auto& q : quads) {
    triangle(q[0], q[1], q[2]);
    triangle(q[0], q[2], q[3]);
  }
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"OpenVDB's own mask -> level set -> mesh path (bench peer)"};
  std::string input, output, type;
  std::vector<std::int64_t> dims;
  std::vector<double> labels;
  int halfWidth = 3;
  bool sweep = false;
  double adaptivity = 0.0;
  app.add_option("IN", input, "Volume file")->required();
  app.add_option("--dims", dims, "Raw volume dimensions X,Y,Z")->delimiter(',');
  app.add_option("--type", type, "Raw sample type");
  app.add_option("--labels", labels, "Inside = one of these labels")->delimiter(',');
  app.add_option("--half-width", halfWidth, "Narrow-band half-width")->capture_default_str();
  app.add_flag("--sweep", sweep, "Also tools::sdfToSdf after topologyToLevelSet");
  app.add_option("--adaptivity", adaptivity, "volumeToMesh adaptivity")->capture_default_str();
  app.add_option("-o,--output", output, "Output .ply (none: the mesh is not written)");
  CLI11_PARSE(app, argc, argv);
  try {
    openvdb::initialize();
    isovdb::pipeline::InputOptions options;
    if (!dims.empty()) {
      if (dims.size() != 3 || type.empty()) throw std::runtime_error("--dims X,Y,Z needs --type");
      isovdb::io::RawOptions raw;
      raw.dims = {dims[0], dims[1], dims[2]};
      const auto parsed = isovdb::io::parseSampleType(type);
      if (!parsed) throw std::runtime_error("unknown --type " + type);
      raw.type = *parsed;
      options.raw = raw;
    }
    options.rule.labels = labels;
    auto start = std::chrono::steady_clock::now();
    const isovdb::volume::Volume mask = isovdb::pipeline::loadVolume(input, options);
    const double read = secondsSince(start);

    start = std::chrono::steady_clock::now();
    auto sdf = openvdb::tools::topologyToLevelSet(isovdb::volume::maskGrid(mask), halfWidth, 0, 0, 0);
    const double field = secondsSince(start);
    double sweepSeconds = 0.0;
    if (sweep) {
      start = std::chrono::steady_clock::now();
      sdf = openvdb::tools::sdfToSdf(*sdf, 0.f, 1);
      sweepSeconds = secondsSince(start);
    }
    start = std::chrono::steady_clock::now();
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(*sdf, points, triangles, quads, 0.0, adaptivity);
    const double contour = secondsSince(start);
    start = std::chrono::steady_clock::now();
    if (!output.empty()) writePly(output, points, triangles, quads);
    const double write = secondsSince(start);
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf(
        "{\"read\": %.6f, \"distance_field\": %.6f, \"sweep\": %.6f, \"contour\": %.6f, \"write\": %.6f, "
        "\"band_voxels\": %llu, \"triangles\": %zu, \"peak_rss_bytes\": %lld}\n",
        read, field, sweepSeconds, contour, write, static_cast<unsigned long long>(sdf->activeVoxelCount()),
        triangles.size() + 2 * quads.size(), static_cast<long long>(usage.ru_maxrss) * 1024);
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "isovdb-openvdb-path: %s\n", error.what());
    return 1;
  }
}
