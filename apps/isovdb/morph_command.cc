// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb morph SLICES -o OUT.ply`: a sparse stack of planar slices (a folder of
// PNG/BMP images, or a binary volume with only some z-slices labelled) → level-set
// metamorphosis fills the gaps → the completed stack is contoured like any volume.
#include <tbb/global_control.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "commands.h"
#include "input_flags.h"
#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/io/mesh_file.h"
#include "isovdb/store/vdb_file.h"
#include "isovdb/morph/reconstruct.h"
#include "isovdb/morph/reconstruction_report.h"
#include "isovdb/morph/slice_image.h"
#include "isovdb/pipeline/extract.h"
#include "isovdb/pipeline/load_volume.h"
#include "isovdb/pipeline/mesh_report.h"

namespace isovdb::cli {

void addMorphCommand(CLI::App& app, Context& context) {
  struct State {
    std::string input, output, statsPath, vdbPath, saveSlices, heights, method = "adaptive";
    std::string interpolation = "levelset", progress = "exponential";
    double spacing = 0, pixelSize = 1, zStep = 0;
    std::int64_t maxPixels = morph::SliceDirectoryOptions{}.maxPixels;
    bool pls = false, check = false;
    int threads = 0;
    morph::VolumeSliceOptions volumeSlices;
    morph::ReconstructOptions options;
    InputFlags flags;
  };
  auto state = std::make_shared<State>();
  CLI::App* command =
      app.add_subcommand("morph",
                         "Sparse planar slices (folder of PNG/BMP, or a volume with some z-slices labelled) -> "
                         "level-set metamorphosis between them -> mesh");
  command->add_option("SLICES", state->input, "Folder of slice images (.png/.bmp), or a binary volume file")
      ->required();
  command->add_option("-o,--output", state->output, "Output mesh (.ply, .obj, .stl or .glb)")->required();
  command->add_option("--heights", state->heights, "Folder input: text file with one height per slice image");
  command->add_option("--spacing", state->spacing, "Folder input: uniform spacing between slices (world units)");
  command->add_option("--pixel-size", state->pixelSize, "Folder input: pixel size (world units)")
      ->capture_default_str();
  command
      ->add_option("--max-pixels", state->maxPixels,
                   "Folder input: most pixels per image, checked in its header before decoding")
      ->capture_default_str();
  command->add_option("--z-step", state->zStep,
                      "Distance between the planes of the completed stack (default: the pixel size; "
                      "volume input: its z spacing)");
  command
      ->add_option("--slice-step", state->volumeSlices.step,
                   "Volume input: labelled slices are every K-th z-slice (0 = every non-empty z-slice)")
      ->capture_default_str();
  command->add_option("--slice-offset", state->volumeSlices.offset, "Volume input: first labelled z-slice")
      ->capture_default_str();
  command->add_option("--method", state->method, "Contouring: adaptive, regular or vdb (OpenVDB's volumeToMesh)")
      ->capture_default_str();
  command->add_flag("--pls", state->pls,
                    "Particle level set correction (Enright et al.; paper 002 Alg. 3.2-3.3; much slower)");
  command->add_flag("!--no-centring", state->options.pair.centre,
                    "Never centre: by default both contours are centred on their convex-hull centroids when "
                    "that makes them overlap more (one moving object), else morphed where they lie");
  command->add_flag("!--no-area-match", state->options.pair.matchArea,
                    "Keep each morphed slice's own area instead of setting it to the linear blend of the two "
                    "originals' areas (one offset of its distance)");
  command
      ->add_option("--interpolate", state->interpolation,
                   "levelset (metamorphosis), nearest (copy the nearer slice) or linear (shape-based: "
                   "blend of the two signed distances)")
      ->capture_default_str();
  command
      ->add_option("--progress", state->progress,
                   "Which iterate each intermediate slice shows (uniform progress): exponential (time of "
                   "arrival from the exponential approach, one time warp), arrival (measured per pixel) or "
                   "iterations (evenly spaced iterations, paper 002; bunches near the target)")
      ->capture_default_str();
  command
      ->add_option("--tolerance", state->options.pair.evolution.tolerance,
                   "Convergence (paper 002 eq. 3.13, Frobenius norm scaled to 64x64)")
      ->capture_default_str();
  command->add_option("--max-iterations", state->options.pair.evolution.maxIterations, "Per pair")
      ->capture_default_str();
  command->add_option("--seed", state->options.pair.particleOptions.seed, "Particle random seed")
      ->capture_default_str();
  command
      ->add_option("--half-width", state->options.halfWidth,
                   "Band half-width of the output distance field (voxels, 1..64)")
      ->capture_default_str();
  command
      ->add_option("--max-planes", state->options.maxPlanes,
                   "Most planes the completed stack may have (heights / z step); a guard against mistyped heights")
      ->capture_default_str();
  command->add_option("--threads", state->threads, "Worker threads (0 = every core); the output is the same")
      ->capture_default_str();
  command->add_option("--save-slices", state->saveSlices,
                      "Write every plane of the completed stack as PNG (plane_NNNN.png) + heights.txt here");
  command->add_option("--vdb", state->vdbPath, "Also write the completed stack's distance field (.vdb)");
  command->add_option("--stats", state->statsPath, "Write every figure shown as JSON");
  command->add_flag("--check", state->check, "Validate the mesh (closed, manifold, genus per component)");
  state->flags.add(*command, /*rawSpacing=*/false);
  command->callback([state, &context] {
    pipeline::ExtractOptions extract;
    extract.contour.method = parseNamed(cell::kContourMethodNames, state->method, "--method", "method");
    extract.threads = state->threads;
    morph::ReconstructOptions& options = state->options;
    options.pair.interpolation =
        parseNamed(morph::kInterpolationNames, state->interpolation, "--interpolate", "interpolation");
    options.pair.progress = parseNamed(morph::kProgressNames, state->progress, "--progress", "progress mode");
    options.pair.particles = state->pls;
    morph::checkReconstructOptions(options);
    io::checkMeshPath(state->output);
    checkFilesBeforeWork({{"the input", state->input}, {"--heights", state->heights}},
                         {{"-o", state->output}, {"--stats", state->statsPath}, {"--vdb", state->vdbPath}});
    if (!state->saveSlices.empty()) {
      // The folder is made at the end: the nearest folder of its path that exists must take files now.
      std::filesystem::path existing = std::filesystem::absolute(state->saveSlices);
      std::error_code ec;
      while (!std::filesystem::exists(existing, ec) && existing.has_parent_path() && existing != existing.parent_path())
        existing = existing.parent_path();
      if (!std::filesystem::is_directory(existing, ec))
        throw InputError("'" + state->saveSlices + "': --save-slices: '" + existing.string() +
                         "' is a file, not a folder");
      io::AtomicFile::checkWritable(existing / "heights.txt");
    }

    pipeline::Statistics stats;
    morph::SliceStack stack;
    {
      pipeline::Statistics::StageTimer timer(&stats, "read");
      std::error_code ec;
      if (std::filesystem::is_directory(state->input, ec)) {
        stack = morph::loadSliceDirectory(state->input, {.heightsFile = state->heights,
                                                         .spacing = state->spacing,
                                                         .pixelSize = state->pixelSize,
                                                         .maxPixels = state->maxPixels});
      } else {
        if (!state->heights.empty() || state->spacing > 0)
          throw InputError("'" + state->input +
                           "': --heights and --spacing apply to a folder of slice images; "
                           "a volume's heights are its z positions");
        const volume::Volume input =
            pipeline::loadVolume(state->input, state->flags.toOptions(state->input), context.interrupter(), &stats);
        stack = morph::sliceStackFromVolume(input, state->volumeSlices);
      }
      if (state->zStep > 0) stack.zStep = state->zStep;
      stats["input"]["slices"] = stack.slices.size();
      stats["input"]["canvas"] = std::to_string(stack.width) + "x" + std::to_string(stack.height);
    }
    std::unique_ptr<tbb::global_control> limit;
    if (state->threads > 0)
      limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, state->threads);
    const morph::Reconstruction result = morph::reconstruct(stack, options, context.interrupter());
    stats.json().merge_patch(morph::reconstructionReport(result, options));
    pipeline::recordGridStats(result.volume, stats["volume"]);

    mesh::Mesh mesh = pipeline::extractMesh(result.volume, extract, context.interrupter(), &stats);
    if (mesh.triangles.empty())
      std::fprintf(stderr, "isovdb: warning: '%s': the slices hold no object (empty mesh)\n", state->input.c_str());
    {
      pipeline::Statistics::StageTimer timer(&stats, "write");
      if (!state->vdbPath.empty()) store::writeVdb(state->vdbPath, result.volume, {.gridName = "sdf"});
      io::writeMesh(state->output, mesh);
      if (!state->saveSlices.empty()) {
        std::filesystem::create_directories(state->saveSlices);
        std::string heights;
        for (std::size_t z = 0; z < result.planes.size(); ++z) {
          char name[32];
          std::snprintf(name, sizeof name, "plane_%04zu.png", z);
          morph::writeSliceImage(std::filesystem::path(state->saveSlices) / name, morph::insideOf(result.planes[z]));
          heights += std::to_string(result.planeHeights[z]) + "\n";
        }
        io::AtomicFile file(std::filesystem::path(state->saveSlices) / "heights.txt");
        file.write(heights);
        file.commit();
      }
    }
    stats["output"]["path"] = state->output;
    stats["output"]["triangles"] = mesh.triangles.size();
    if (state->check) {
      pipeline::Statistics::StageTimer timer(&stats, "check");
      stats["check"] = pipeline::meshReportJson(mesh, {.selfIntersections = false});
    }
    reportStatistics(stats, state->statsPath, context);
  });
}

}  // namespace isovdb::cli
