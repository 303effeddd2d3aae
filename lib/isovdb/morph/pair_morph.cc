// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/morph/pair_morph.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "isovdb/morph/area_match.h"
#include "isovdb/morph/arrival.h"
#include "isovdb/morph/centring.h"

namespace isovdb::morph {

namespace {

struct Box {
  double minX = 1e300, minY = 1e300, maxX = -1e300, maxY = -1e300;
};

/// Extends `box` by the inside pixels of `mask`, as offsets from `centre`.
void extendBox(Box& box, const Mask2& mask, Vec2 centre) {
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x)
      if (mask.at(x, y)) {
        box.minX = std::min(box.minX, x - centre.x);
        box.maxX = std::max(box.maxX, x - centre.x);
        box.minY = std::min(box.minY, y - centre.y);
        box.maxY = std::max(box.maxY, y - centre.y);
      }
}

Field2 lerp(const Field2& a, const Field2& b, double s) {
  Field2 out = a;
  for (std::size_t i = 0; i < out.size(); ++i)
    out.values[i] = static_cast<float>((1 - s) * a.values[i] + s * b.values[i]);
  return out;
}

/// The field of a slice with nothing inside, next to a slice with field `other`:
/// `other` raised until only a seed around its deepest point (within half a pixel
/// of the deepest value) is inside, so the section grows from that seed. The level-set
/// equation only moves the levels φ already has: from an empty slice's field (no zero
/// level) the morph leaves every plane empty up to the other slice.
Field2 seededField(const Field2& other) {
  float deepest = 0.0f;
  for (float v : other.values) deepest = std::min(deepest, v);
  Field2 out = other;
  for (float& v : out.values) v -= deepest + 0.5f;
  return out;
}

/// Pixels inside both `a` and `b` shifted by (dx, dy) (b read at p + (dx, dy)).
std::int64_t overlap(const Mask2& a, const Mask2& b, int dx, int dy) {
  std::int64_t n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const int bx = x + dx, by = y + dy;
      n += a.at(x, y) && bx >= 0 && by >= 0 && bx < b.width && by < b.height && b.at(bx, by);
    }
  return n;
}

/// Centring assumes the section translates from one slice to the next; it is worth
/// doing when the translation between the centroids makes the two slices overlap
/// more than where they lie. Where a component appears or vanishes the hull
/// centroid jumps, and centring would drag the components that stay.
bool centringHelps(const Mask2& a, const Mask2& b, Vec2 ca, Vec2 cb) {
  const int dx = static_cast<int>(std::lround(cb.x - ca.x)), dy = static_cast<int>(std::lround(cb.y - ca.y));
  if (dx == 0 && dy == 0) return true;
  return overlap(a, b, dx, dy) > overlap(a, b, 0, 0);
}

std::int64_t countDifferent(const Mask2& a, const Mask2& b) {
  std::int64_t n = 0;
  for (std::size_t i = 0; i < a.inside.size(); ++i) n += a.inside[i] != b.inside[i];
  return n;
}

/// Runs the morph (with particles when asked), calling visit(previous, current, n)
/// after every step n = 1..K. Deterministic, so a second run replays the first.
template <typename Visit>
void runMorph(const Field2& source, const Field2& target, const PairOptions& options, PairStats& stats, Visit&& visit) {
  LevelSetMorph morph(source, target, options.evolution);
  std::optional<ParticleLevelSet> particles;
  if (options.particles) {
    particles.emplace(source, options.particleOptions);
    stats.particles = static_cast<std::int64_t>(particles->particles().size());
    stats.discardedParticles = particles->discarded();
  }
  stats.escapedParticles = 0;
  Field2 previous = morph.phi();
  for (bool more = true; more;) {
    const int before = morph.iteration();
    more = morph.step();
    if (morph.iteration() == before) break;
    if (particles) {
      particles->advect(target, morph.timeStep());
      stats.escapedParticles += particles->correct(morph.phi());
      morph.corrected();
    }
    visit(previous, morph.phi(), morph.iteration());
    previous = morph.phi();
  }
  stats.iterations = morph.iteration();
  stats.hitMaxIterations = morph.hitMaxIterations();
  stats.timeStep = morph.timeStep();
  stats.finalCriterion = morph.criterion();
}

}  // namespace

PairResult morphPair(const Mask2& a, const Mask2& b, const Field2& sdfA, const Field2& sdfB,
                     const std::vector<double>& fractions, const PairOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  PairResult result;
  const auto finish = [&] {
    result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::move(result);
  };
  if (options.interpolation == Interpolation::Nearest) {
    for (double s : fractions) result.slices.push_back(s <= 0.5 ? sdfA : sdfB);
    return finish();
  }
  if (options.interpolation == Interpolation::Linear) {
    for (double s : fractions) result.slices.push_back(lerp(sdfA, sdfB, s));
    return finish();
  }

  // A structure that ends between the two slices tapers to a seed at the empty one.
  const bool emptyA = a.area() == 0, emptyB = b.area() == 0;
  const Field2 seeded = emptyA != emptyB ? seededField(emptyA ? sdfB : sdfA) : Field2{};
  const Field2& fieldA = emptyA && !emptyB ? seeded : sdfA;
  const Field2& fieldB = emptyB && !emptyA ? seeded : sdfB;

  std::optional<Vec2> ca = hullCentroid(a), cb = hullCentroid(b);
  result.stats.centred = options.centre && ca && cb && centringHelps(a, b, *ca, *cb);
  if (!result.stats.centred && ca && cb) ca = cb = Vec2{0.5 * (ca->x + cb->x), 0.5 * (ca->y + cb->y)};
  if (!ca && !cb) {
    for (std::size_t j = 0; j < fractions.size(); ++j) result.slices.push_back(sdfA);
    return finish();
  }
  if (!ca) ca = cb;
  if (!cb) cb = ca;

  // Working grid: both contours centred on their centroids (offset 0 = centroid).
  Box box;
  extendBox(box, a, *ca);
  extendBox(box, b, *cb);
  const int loX = static_cast<int>(std::floor(box.minX)) - options.margin;
  const int loY = static_cast<int>(std::floor(box.minY)) - options.margin;
  const int w = std::max(2, static_cast<int>(std::ceil(box.maxX)) + options.margin - loX + 1);
  const int h = std::max(2, static_cast<int>(std::ceil(box.maxY)) + options.margin - loY + 1);
  const Field2 source = resample(fieldA, w, h, {ca->x + loX, ca->y + loY});
  const Field2 target = resample(fieldB, w, h, {cb->x + loX, cb->y + loY});
  result.stats.workWidth = w;
  result.stats.workHeight = h;

  // Pass 1: how many iterations K (eq. 3.13 on the level-set morph), and (arrival)
  // when the front crosses each pixel. With particles, the corrected morph runs the
  // same K steps: its corrections change φ from step to step, so eq. 3.13 on it
  // would measure the corrections rather than the approach to the target.
  ArrivalRecorder arrival(source);
  PairOptions run = options;
  const auto record = [&](const Field2& previous, const Field2& current, int n) {
    if (options.progress == Progress::Arrival) arrival.record(previous, current, n);
  };
  if (options.particles) {
    PairOptions plain = options;
    plain.particles = false;
    runMorph(source, target, plain, result.stats, [](const Field2&, const Field2&, int) {});
    const PairStats converged = result.stats;
    run.evolution.tolerance = 0;
    run.evolution.maxIterations = converged.iterations;
    runMorph(source, target, run, result.stats, record);
    result.stats.hitMaxIterations = converged.hitMaxIterations;
    result.stats.finalCriterion = converged.finalCriterion;
  } else {
    runMorph(source, target, run, result.stats, record);
  }
  const int iterations = result.stats.iterations;
  const Field2 scale = options.progress == Progress::Arrival ? arrivalScale(arrival.times(), target, iterations)
                                                             : Field2::filled(w, h, static_cast<float>(iterations + 1));
  // Exponential progress (pair_morph.h): one time per slice, t(s) = -ln(1 - s (1 - e^{-T})).
  std::vector<double> warped(fractions.size(), -1.0);
  if (options.progress == Progress::Exponential && result.stats.timeStep > 0 && iterations > 0) {
    const double totalTime = iterations * result.stats.timeStep;
    for (std::size_t j = 0; j < fractions.size(); ++j)
      warped[j] = -std::log(1 - fractions[j] * (1 - std::exp(-totalTime))) / result.stats.timeStep;
  }
  const auto want = [&](std::size_t j, std::size_t i) -> double {
    return warped[j] >= 0 ? warped[j] : fractions[j] * scale.values[i];
  };

  // Pass 2 (replay): slice j shows, at pixel x, the iterate of (fractional) number
  // fractions[j] * scale(x); iterate K + 1 is the target itself.
  std::vector<Field2> work(fractions.size(), source);
  Field2 last = source;
  const PairStats counted = result.stats;
  runMorph(source, target, run, result.stats, [&](const Field2& previous, const Field2& current, int n) {
    for (std::size_t j = 0; j < fractions.size(); ++j)
      for (std::size_t i = 0; i < current.size(); ++i) {
        const double wanted = want(j, i);
        if (wanted > n - 1 && wanted <= n) {
          const double t = wanted - (n - 1);
          work[j].values[i] = static_cast<float>((1 - t) * previous.values[i] + t * current.values[i]);
        }
      }
    if (n == iterations) last = current;
  });
  result.stats = counted;
  for (std::size_t j = 0; j < fractions.size(); ++j)
    for (std::size_t i = 0; i < last.size(); ++i) {
      const double wanted = want(j, i);
      if (wanted > iterations) {
        const double t = std::min(1.0, wanted - iterations);
        work[j].values[i] = static_cast<float>((1 - t) * last.values[i] + t * target.values[i]);
      }
    }

  const Mask2 insideA = insideOf(source), insideB = insideOf(target);
  if (options.matchArea) {
    const double areaA = static_cast<double>(insideA.area()), areaB = static_cast<double>(insideB.area());
    for (std::size_t j = 0; j < fractions.size(); ++j)
      shiftToArea(work[j], std::llround((1 - fractions[j]) * areaA + fractions[j] * areaB));
  }

  // Uniformity of progress: fraction of the swept area covered by each slice.
  const std::int64_t swept = countDifferent(insideA, insideB);
  double error = 0;
  for (std::size_t j = 0; j < fractions.size(); ++j) {
    const double covered =
        swept > 0 ? static_cast<double>(countDifferent(insideOf(work[j]), insideA)) / swept : fractions[j];
    error += std::abs(covered - fractions[j]);
  }
  result.stats.progressError = fractions.empty() ? 0 : error / fractions.size();

  // De-centre along the line between the centroids.
  for (std::size_t j = 0; j < fractions.size(); ++j) {
    const double s = fractions[j];
    const Vec2 c{ca->x + s * (cb->x - ca->x), ca->y + s * (cb->y - ca->y)};
    result.slices.push_back(resample(work[j], sdfA.width, sdfA.height, {-c.x - loX, -c.y - loY}));
  }
  return finish();
}

}  // namespace isovdb::morph
