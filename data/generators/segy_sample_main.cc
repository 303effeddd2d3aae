// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file segy_sample_main.cc
/// @brief `isovdb-segy-sample`: writes a synthetic SEG-Y amplitude cube with a
///        salt-like body, for benchmarks (and any size of test).
///
///   isovdb-segy-sample -o CUBE.sgy [--inlines 1000] [--crosslines 1000] [--samples 500]
///                      [--format 5] [--little-endian] [--crossline-sorted]
///
/// Amplitudes: inside the salt-dome body of `isovdb-sample salt-dome` (its z axis
/// up, so the cap lies at small times) 5000..7000; two thin, gently dipping
/// reflectors of +-2500; everywhere else quiet ripples with |a| <= 600. A clip of
/// 1000 keeps the body and the reflectors, about 10 % of the samples at any size
/// (90 % lie in the dead band); the tool prints the exact fraction. One inline is
/// computed at a time (in parallel), then written trace by trace.
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "generators/segy_writer.h"
#include "generators/shapes.h"

namespace {

using isovdb::samples::SegyCubeSpec;

constexpr float kClip = 1000.f;

/// Amplitude of one sample: salt body, reflector or quiet ripple.
float amplitude(const SegyCubeSpec& spec, const isovdb::samples::ShapeOptions& shape, int i, int j, int k) {
  const double size = shape.size;
  const double x = (i + 0.5) * size / spec.inlines - 0.5;
  const double y = (j + 0.5) * size / spec.crosslines - 0.5;
  const double z = (spec.samples - 1 - k + 0.5) * size / spec.samples - 0.5;
  if (isovdb::samples::inside(isovdb::samples::ShapeKind::SaltDome, shape, x, y, z))
    return static_cast<float>(6000.0 + 1000.0 * std::sin(0.3 * k + 0.02 * i));
  const double t = static_cast<double>(k) / spec.samples;  // 0 at the top, 1 at the bottom
  const double dip = 0.005 * std::sin(6.0 * i / spec.inlines) * std::cos(5.0 * j / spec.crosslines);
  const double phase = std::fmod(t + 0.2 + dip + 10.0, 0.5) / 0.5;  // two reflectors over the cube
  // Each reflector (a peak over a trough) fills 0.2 % of its period: with the body
  // (about 9.8 % of the cube) about 10 % of the samples lie outside the dead band.
  if (phase < 0.002) return phase < 0.001 ? 2500.f : -2500.f;
  return static_cast<float>(600.0 * std::sin(0.21 * k + 0.05 * i) * std::cos(0.13 * j + 0.4));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Writes a synthetic SEG-Y amplitude cube: a salt-like body in a quiet background."};
  SegyCubeSpec spec;
  spec.inlines = 1000;
  spec.crosslines = 1000;
  spec.samples = 500;
  std::string output;
  app.add_option("-o,--output", output, "Output SEG-Y file")->required();
  app.add_option("--inlines", spec.inlines, "Inlines (grid x)")->capture_default_str()->check(CLI::Range(1, 100000));
  app.add_option("--crosslines", spec.crosslines, "Crosslines (grid y)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  app.add_option("--samples", spec.samples, "Samples per trace (grid z)")
      ->capture_default_str()
      ->check(CLI::Range(1, 32767));
  app.add_option("--format", spec.formatCode, "SEG-Y sample format: 1 IBM float, 2 int32, 3 int16, 5 IEEE float")
      ->capture_default_str()
      ->check(CLI::IsMember({1, 2, 3, 5}));
  app.add_flag("--little-endian", spec.littleEndian, "Byte-swap the whole file");
  app.add_flag("--crossline-sorted", spec.crosslineSorted, "Order traces crossline by crossline");
  CLI11_PARSE(app, argc, argv);
  try {
    const isovdb::samples::ShapeOptions shape{.size = std::max({spec.inlines, spec.crosslines, spec.samples, 16})};
    std::vector<float> line;  // the traces of one inline, computed together
    int lineInline = -1;
    long long active = 0, total = 0;
    isovdb::samples::writeSegyCube(output, spec, [&](int i, int j, float* trace) {
      if (i != lineInline) {
        line.resize(static_cast<std::size_t>(spec.crosslines) * spec.samples);
        tbb::parallel_for(0, spec.crosslines, [&](int jj) {
          for (int k = 0; k < spec.samples; ++k)
            line[static_cast<std::size_t>(jj) * spec.samples + k] = amplitude(spec, shape, i, jj, k);
        });
        lineInline = i;
      }
      const float* source = line.data() + static_cast<std::size_t>(j) * spec.samples;
      for (int k = 0; k < spec.samples; ++k) {
        trace[k] = source[k];
        active += std::abs(source[k]) >= kClip;
      }
      total += spec.samples;
      return true;
    });
    std::printf("wrote %s: %d x %d x %d, %.1f %% of samples with |a| >= %g (outside the dead band)\n", output.c_str(),
                spec.inlines, spec.crosslines, spec.samples, 100.0 * active / total, kClip);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "isovdb-segy-sample: error: %s\n", e.what());
    return 2;
  }
  return 0;
}
