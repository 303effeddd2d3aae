// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/morph/reconstruction_report.h"

#include <string>

#include "isovdb/errors.h"

namespace isovdb::morph {

void checkReconstructOptions(const ReconstructOptions& options) {
  if (options.pair.particles && options.pair.interpolation != Interpolation::LevelSet)
    throw InputError("pls: the particle level set needs the levelset interpolation");
  if (!(options.pair.evolution.tolerance > 0)) throw InputError("tolerance: must be > 0");
  if (options.pair.evolution.maxIterations < 1) throw InputError("max-iterations: must be >= 1");
}

nlohmann::ordered_json reconstructionReport(const Reconstruction& r, const ReconstructOptions& options) {
  using Json = nlohmann::ordered_json;
  const bool pls = options.pair.particles;
  Json report = Json::object();
  Json& m = report["morph"];
  m["interpolation"] = interpolationName(options.pair.interpolation);
  m["particle_level_set"] = pls;
  m["centring"] = options.pair.centre;
  m["area_match"] = options.pair.matchArea;
  m["progress"] = progressName(options.pair.progress);
  m["tolerance"] = options.pair.evolution.tolerance;
  m["original_slices"] = r.originalPlane.size();
  m["planes"] = r.planes.size();
  m["intermediate_slices"] = r.planes.size() - r.originalPlane.size();
  std::int64_t iterations = 0, capped = 0, centred = 0;
  double pairSeconds = 0, progressError = 0;
  auto pairs = Json::array();
  for (std::size_t i = 0; i < r.pairs.size(); ++i) {
    const PairStats& p = r.pairs[i];
    iterations += p.iterations;
    capped += p.hitMaxIterations;
    centred += p.centred;
    pairSeconds += p.seconds;
    progressError += p.progressError;
    Json j;
    j["intermediate_slices"] = r.originalPlane[i + 1] - r.originalPlane[i] - 1;
    j["iterations"] = p.iterations;
    j["time_step"] = p.timeStep;
    j["criterion"] = p.finalCriterion;
    j["grid"] = std::to_string(p.workWidth) + "x" + std::to_string(p.workHeight);
    j["centred"] = p.centred;
    if (pls) {
      j["particles"] = p.particles;
      j["particles_discarded"] = p.discardedParticles;
      j["particles_escaped"] = p.escapedParticles;
    }
    j["progress_error"] = p.progressError;
    j["seconds"] = p.seconds;
    pairs.push_back(j);
  }
  m["iterations_total"] = iterations;
  m["pairs_at_max_iterations"] = capped;
  m["pairs_centred"] = centred;
  m["progress_error_mean"] = r.pairs.empty() ? 0.0 : progressError / r.pairs.size();
  const auto intermediate = r.planes.size() - r.originalPlane.size();
  m["seconds_per_intermediate_slice"] = intermediate ? pairSeconds / intermediate : 0.0;
  m["seconds_per_iteration"] = iterations ? pairSeconds / iterations : 0.0;
  m["pairs"] = pairs;
  report["timings_s"]["slice_sdf"] = r.sdfSeconds;
  report["timings_s"]["morph"] = r.morphSeconds;
  report["timings_s"]["assembly"] = r.assemblySeconds;
  return report;
}

}  // namespace isovdb::morph
