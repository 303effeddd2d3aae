// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb extract IN -o OUT.ply`: the main job, volume -> closed triangle mesh.
#include "commands.h"
#include "input_flags.h"
#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/io/mesh_file.h"
#include "isovdb/pipeline/extract.h"
#include "isovdb/pipeline/extract_to_file.h"
#include "isovdb/pipeline/load_volume.h"
#include "isovdb/pipeline/mesh_report.h"

namespace isovdb::cli {

void addExtractCommand(CLI::App& app, Context& context) {
  struct State {
    std::string input, output, statsPath, method = "vdb", boundary = "cap", topology = "auto";
    InputFlags flags;
    DistanceFlags distanceFlags;
    pipeline::ExtractOptions options;
    bool check = false;
    bool noSelfIntersections = false;
  };
  auto state = std::make_shared<State>();
  CLI::App* command = app.add_subcommand("extract", "Volume -> triangle mesh (.ply or .obj)");
  command->add_option("IN", state->input, "Volume file (.raw, .nrrd, .nhdr, .mhd, .mha, .sgy, .segy, .vdb)")
      ->required();
  command->add_option("-o,--output", state->output, "Output mesh (.ply binary, or .obj)")->required();
  command
      ->add_option("--method", state->method,
                   "Contouring method: vdb (OpenVDB volumeToMesh), regular (manifold DMC), adaptive (DC + Ju-Udeshi)")
      ->capture_default_str();
  command
      ->add_option("--topology", state->topology,
                   "regular: reading of ambiguous cells. voxels: the voxel object's topology (26-connected "
                   "inside, 6-connected outside; Euler characteristic 2x the mask's), mdmc: Wenger's manifold "
                   "DMC (inside corners of ambiguous faces separated, doubled faces regrouped), auto: voxels "
                   "for masks, mdmc for fields")
      ->capture_default_str();
  command
      ->add_option("--iso", state->options.iso,
                   "Isovalue: voxels on distance fields (0 = mask boundary), field units on scalars")
      ->capture_default_str();
  command->add_option("--adaptivity", state->options.adaptivity, "vdb method: OpenVDB adaptivity in [0,1]")
      ->capture_default_str();
  state->distanceFlags.add(*command, state->options.distance, /*streamed=*/false);
  command
      ->add_option("--meta-cell", state->options.octree.metaCellSize,
                   "regular/adaptive: meta-cell size in voxels (power of two, 16..512; 0 = one block around "
                   "the whole volume, no stitching)")
      ->capture_default_str();
  command->add_option("--threads", state->options.threads, "Worker threads (0 = every core); the output is the same")
      ->capture_default_str();
  command
      ->add_option("--min-level", state->options.octree.minLevel,
                   "regular/adaptive: uniform subdivision down to this depth under the meta-cell "
                   "(-1: --max-cell-size decides)")
      ->capture_default_str();
  command
      ->add_option("--max-cell-size", state->options.octree.maxCellSize,
                   "regular/adaptive: largest cell in voxels when --min-level is -1")
      ->capture_default_str();
  command
      ->add_option("--max-level", state->options.octree.maxLevel,
                   "regular/adaptive: deepest level under the meta-cell (-1: --finest-size decides)")
      ->capture_default_str();
  command
      ->add_option("--finest-size", state->options.octree.finestCellSize,
                   "regular/adaptive: smallest cell in voxels (1, 2, 4, ...)")
      ->capture_default_str();
  command
      ->add_option("--qef-tolerance", state->options.octree.qefTolerance,
                   "adaptive: split cells whose QEF residual (RMS, voxels) exceeds this; <0 off")
      ->capture_default_str();
  command->add_flag("!--no-intersection-free", state->options.octree.intersectionFree,
                    "adaptive: plain dual contouring without Ju-Udeshi fans (for comparison)");
  command->add_flag("--sharp-features", state->options.octree.sharpFeatures,
                    "Adaptive mode: keep the sharp edges and corners of an exact distance field "
                    "(e.g. a CAD level set .vdb). "
                    "Off by default: a field made from a voxel mask has a crease at every staircase step, and "
                    "following them costs 35-50% more triangles");
  command
      ->add_option("--boundary", state->boundary,
                   "Surfaces reaching the data boundary (survey edge): cap (closed mesh, caps on the boundary) "
                   "or open (caps dropped, the mesh ends on the boundary)")
      ->capture_default_str();
  command->add_flag("--check", state->check, "Validate the mesh (closed, manifold, self-intersections, Euler)");
  command->add_flag("--no-self-intersections", state->noSelfIntersections,
                    "With --check: skip the self-intersection test");
  command->add_option("--stats", state->statsPath, "Write every figure shown as JSON");
  state->flags.add(*command);
  command->callback([state, &context] {
    mesh::Mesh mesh;
    const auto method = pipeline::parseContourMethod(state->method);
    if (!method)
      throw InputError("--method: unknown method '" + state->method + "', expected vdb, regular or adaptive");
    state->options.method = *method;
    state->distanceFlags.apply(state->options.distance);
    if (state->topology != "auto") {
      state->options.regularTopology = pipeline::parseRegularTopology(state->topology);
      if (!state->options.regularTopology)
        throw InputError("--topology: unknown reading '" + state->topology + "', expected auto, voxels or mdmc");
    }
    const auto boundary = pipeline::parseBoundaryMode(state->boundary);
    if (!boundary) throw InputError("--boundary: unknown mode '" + state->boundary + "', expected cap or open");
    state->options.boundary = *boundary;
    if (!io::isMeshPath(state->output))
      throw InputError("'" + state->output + "': unknown mesh format, expected .ply or .obj");
    io::AtomicFile::checkWritable(state->output);
    if (!state->statsPath.empty()) io::AtomicFile::checkWritable(state->statsPath);

    pipeline::Statistics stats;
    volume::Volume input =
        pipeline::loadVolume(state->input, state->flags.toOptions(state->input), context.interrupter(), &stats);
    // Without --check the octree methods stream a .ply meta-cell by meta-cell (the mesh
    // is never held whole); --check needs the mesh in memory. The input is moved in so
    // that a mask is freed once its distance field exists.
    std::uint64_t triangles = 0;
    if (!state->check) {
      triangles =
          pipeline::extractToFile(std::move(input), state->options, state->output, context.interrupter(), &stats);
    } else {
      mesh = pipeline::extractMesh(std::move(input), state->options, context.interrupter(), &stats);
      triangles = mesh.triangles.size();
      pipeline::Statistics::StageTimer timer(&stats, "write");
      io::writeMesh(state->output, mesh);
    }
    if (triangles == 0)
      std::fprintf(stderr, "isovdb: warning: '%s': no surface at iso %g (empty mesh)\n", state->input.c_str(),
                   state->options.iso);
    stats["output"]["path"] = state->output;
    bool passed = true;
    if (state->check) {
      pipeline::Statistics::StageTimer timer(&stats, "check");
      const mesh::MeshReport report = mesh::validateMesh(mesh, {.selfIntersections = !state->noSelfIntersections});
      stats["check"] = pipeline::toJson(report);
      // --boundary open asks for a mesh that ends on the data boundary: not closed by design.
      passed = pipeline::passesGuarantees(report) || (state->options.boundary == pipeline::BoundaryMode::Open &&
                                                      report.manifold && report.selfIntersectingPairs <= 0);
      stats["passed"] = passed;
    }
    stats.recordMemory();
    if (!state->statsPath.empty()) stats.write(state->statsPath);
    printStatistics(stats);
    // Like `isovdb check`: a mesh that fails the check is written, and the run exits 1.
    context.exitCode = passed ? 0 : 1;
  });
}

}  // namespace isovdb::cli
