// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/io/segy_reader.h (SegyReader suite) on the real F3 crop of
// data/seismic/ and on cubes built in code with data/generators/segy_writer.h,
// and of io/sample_statistics.h (SampleStatistics suite).
#include "isovdb/io/segy_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "generators/segy_writer.h"
#include "io/reader_test_support.h"
#include "isovdb/errors.h"
#include "isovdb/io/sample_statistics.h"
#include "isovdb/volume/grids.h"
#include "isovdb/volume/ingest.h"
#include "isovdb/volume/sampled_box.h"

namespace isovdb::io {
namespace {

using namespace test;  // TempDir, writeFile, readFile, readAll, expectError
using samples::SegyCubeSpec;

std::filesystem::path f3(const std::string& name) { return dataDir() / "seismic" / name; }

/// A value every (inline index, crossline index, sample) of a generated cube gets.
float cubeValue(int i, int j, int k) { return static_cast<float>(100 * i - 10 * j + k - 7); }

std::filesystem::path writeCube(const TempDir& dir, const SegyCubeSpec& spec,
                                const std::function<bool(int, int)>& present = {}) {
  const auto path = dir / "cube.sgy";
  samples::writeSegyCube(path, spec, [&](int i, int j, float* trace) {
    if (present && !present(i, j)) return false;
    for (int k = 0; k < spec.samples; ++k) trace[k] = cubeValue(i, j, k);
    return true;
  });
  return path;
}

/// The scalar grid of a SEG-Y stream, for value checks in grid axes (inline, crossline, sample).
volume::Volume ingest(SliceStream& stream) { return volume::ingestScalar(stream, {.background = -1.f}); }

TEST(SegyReader, TheFourEncodingsOfTheF3CropReadToTheSameValues) {
  std::vector<float> reference;
  for (const std::string name : {"f3.sgy", "f3-lsb.sgy", "f3_format1_ibm_msb.sgy", "f3_format5_ieee_msb.sgy"}) {
    SCOPED_TRACE(name);
    auto stream = openSegy(f3(name));
    const SegyGeometry& g = stream->geometry();
    EXPECT_EQ(g.traces, 414);
    EXPECT_EQ(g.missingTraces, 0);
    EXPECT_EQ(g.sorting, SegySorting::Inline);
    EXPECT_EQ(g.inlines.first, 111);
    EXPECT_EQ(g.inlines.last(), 133);
    EXPECT_EQ(g.crosslines.first, 875);
    EXPECT_EQ(g.crosslines.last(), 892);
    EXPECT_EQ(g.samples, 75);
    EXPECT_EQ(g.sampleIntervalUs, 4000.0);
    EXPECT_EQ(g.firstSampleMs, 4.0);
    EXPECT_TRUE(g.spacingFromCoordinates);
    EXPECT_NEAR(g.inlines.spacing, 25.0, 0.01);
    EXPECT_NEAR(g.crosslines.spacing, 25.0, 0.01);
    EXPECT_EQ(g.littleEndian, name == "f3-lsb.sgy");
    EXPECT_EQ(g.formatCode, name == "f3_format1_ibm_msb.sgy" ? 1 : name == "f3_format5_ieee_msb.sgy" ? 5 : 3);
    EXPECT_EQ(stream->header().dims, (std::array<std::int64_t, 3>{75, 18, 23}));
    const std::vector<float> values = readAll(*stream);
    if (reference.empty()) {
      reference = values;
      const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
      EXPECT_EQ(*lo, -10239.f);
      EXPECT_EQ(*hi, 10827.f);
    } else {
      ASSERT_EQ(values, reference);
    }
  }
}

TEST(SegyReader, GridAxesAreInlineCrosslineSampleWithTheSurveyScale) {
  TempDir dir;
  const SegyCubeSpec spec{.inlines = 9,
                          .crosslines = 11,
                          .samples = 13,
                          .firstInline = 50,
                          .inlineStep = 2,
                          .firstCrossline = 7,
                          .sampleIntervalUs = 2000,
                          .delayMs = 100,
                          .inlineSpacing = 12.5,
                          .crosslineSpacing = 30.0};
  auto stream = openSegy(writeCube(dir, spec));
  EXPECT_EQ(stream->geometry().inlines.step, 2);
  EXPECT_EQ(stream->geometry().inlines.last(), 66);
  const volume::Volume volume = ingest(*stream);
  EXPECT_EQ(volume.geometry().spacing, (std::array<double, 3>{12.5, 30.0, 2.0}));
  EXPECT_EQ(volume.geometry().origin, (std::array<double, 3>{0.0, 0.0, 100.0}));
  const auto box = volume::sampledBox(volume);
  ASSERT_TRUE(box);
  EXPECT_EQ(box->max, (std::array<int, 3>{8, 10, 12}));
  auto acc = volume::fieldGrid(volume).getConstAccessor();
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 11; ++j)
      for (int k = 0; k < 13; ++k) ASSERT_EQ(acc.getValue(openvdb::Coord(i, j, k)), cubeValue(i, j, k));
}

TEST(SegyReader, CrosslineSortedLittleEndianIntegerAndIbmCubesReadExactly) {
  for (const int format : {1, 2, 3, 5, 8}) {
    for (const bool crosslineSorted : {false, true}) {
      SCOPED_TRACE("format " + std::to_string(format) + (crosslineSorted ? " crossline-sorted" : ""));
      TempDir dir;
      const SegyCubeSpec spec{.inlines = 4,
                              .crosslines = 6,
                              .samples = 10,
                              .formatCode = format,
                              .littleEndian = crosslineSorted,
                              .crosslineSorted = crosslineSorted};
      auto stream = openSegy(writeCube(dir, spec));
      EXPECT_EQ(stream->geometry().sorting, crosslineSorted ? SegySorting::Crossline : SegySorting::Inline);
      EXPECT_EQ(stream->geometry().littleEndian, crosslineSorted);
      const volume::Volume volume = ingest(*stream);
      auto acc = volume::fieldGrid(volume).getConstAccessor();
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 6; ++j)
          for (int k = 0; k < 10; ++k) {
            const float expected = format == 8 ? std::clamp(cubeValue(i, j, k), -128.f, 127.f) : cubeValue(i, j, k);
            ASSERT_EQ(acc.getValue(openvdb::Coord(i, j, k)), expected) << i << "," << j << "," << k;
          }
    }
  }
}

TEST(SegyReader, MissingTracesAndLinesAreInactiveHoles) {
  TempDir dir;
  const SegyCubeSpec spec{.inlines = 6, .crosslines = 5, .samples = 8};
  // Inline index 3 is missing entirely (its number 4 is never seen), and the corner
  // (0, 0) and (5, 4) traces are missing: an irregular outline.
  const auto present = [](int i, int j) { return i != 3 && !(i == 0 && j == 0) && !(i == 5 && j == 4); };
  auto stream = openSegy(writeCube(dir, spec, present));
  EXPECT_EQ(stream->geometry().traces, 23);
  EXPECT_EQ(stream->geometry().missingTraces, 7);
  EXPECT_EQ(stream->geometry().inlines.count, 6);
  const volume::Volume volume = ingest(*stream);
  auto acc = volume::fieldGrid(volume).getConstAccessor();
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 8; ++k) {
        const openvdb::Coord c(i, j, k);
        ASSERT_EQ(acc.isValueOn(c), present(i, j)) << i << "," << j;
        ASSERT_EQ(acc.getValue(c), present(i, j) ? cubeValue(i, j, k) : -1.f);
      }
}

TEST(SegyReader, HeaderBytePositionsAreConfigurable) {
  TempDir dir;
  const auto path = writeCube(
      dir, {.inlines = 3, .crosslines = 4, .samples = 5, .firstInline = 20, .inlineByte = 9, .crosslineByte = 21});
  auto stream = openSegy(path, {.inlineByte = 9, .crosslineByte = 21});
  EXPECT_EQ(stream->geometry().inlines.first, 20);
  EXPECT_EQ(stream->geometry().crosslines.count, 4);
  // The default positions hold zeros here: every trace at inline 0, crossline 0.
  expectError<InputError>([&] { openSegy(path); },
                          {path.string(), "both have inline 0 and crossline 0", "--inline-byte 189"});
  expectError<InputError>([&] { openSegy(path, {.inlineByte = 190}); },
                          {path.string(), "--inline-byte 190 is not the first byte"});
}

// --- Bad input: one message naming the file and the problem ----------------------

class SegyBadInput : public ::testing::Test {
 protected:
  TempDir dir;
  std::filesystem::path good() { return writeCube(dir, {.inlines = 3, .crosslines = 4, .samples = 6}); }
  std::filesystem::path withBytes(const std::string& bytes) {
    const auto path = dir / "bad.sgy";
    writeFile(path, bytes);
    return path;
  }
};

TEST_F(SegyBadInput, TruncatedFile) {
  const std::string bytes = readFile(good());
  const auto path = withBytes(bytes.substr(0, bytes.size() - 5));
  expectError<InputError>([&] { openSegy(path); }, {path.string(), "truncated", "last trace has 259 bytes"});
}

TEST_F(SegyBadInput, TextualHeaderOnly) {
  const auto path = withBytes(readFile(good()).substr(0, 3200));
  expectError<InputError>([&] { openSegy(path); }, {path.string(), "ends after the textual header"});
  const auto headers = withBytes(readFile(good()).substr(0, 3600));
  expectError<InputError>([&] { openSegy(headers); }, {headers.string(), "no traces"});
}

TEST_F(SegyBadInput, TraceCountDoesNotMatchTheSampleCount) {
  std::string bytes = readFile(good());
  bytes[3221] = 7;  // binary header: 7 samples per trace, the traces hold 6
  const auto path = withBytes(bytes);
  expectError<InputError>([&] { openSegy(path); }, {path.string(), "not a whole number of 268-byte traces"});
}

TEST_F(SegyBadInput, UnsupportedSampleFormat) {
  std::string bytes = readFile(good());
  bytes[3225] = 4;  // fixed point with gain: obsolete
  const auto path = withBytes(bytes);
  expectError<InputError>([&] { openSegy(path); }, {path.string(), "unsupported sample format code 4"});
}

TEST_F(SegyBadInput, NonMonotonicInlineNumbers) {
  std::string bytes = readFile(good());
  // Trace 8 (third inline) gets inline 1 again: 1, 2, 1.
  const std::size_t trace8 = 3600 + 8 * (240 + 6 * 4);
  bytes[trace8 + 188 + 3] = 1;
  const auto path = withBytes(bytes);
  expectError<InputError>([&] { openSegy(path); }, {path.string(),
                                                    "inline numbers (trace header byte 189) are not "
                                                    "monotonic",
                                                    "trace 8 has inline 1 after 2"});
}

TEST_F(SegyBadInput, NonFiniteSample) {
  std::string bytes = readFile(good());
  const std::size_t sample = 3600 + 240 + 2 * 4;                 // trace 0, sample 2
  bytes.replace(sample, 4, std::string("\x7f\xc0\x00\x00", 4));  // quiet NaN
  const auto path = withBytes(bytes);
  auto stream = openSegy(path);
  std::vector<float> slice(static_cast<std::size_t>(stream->header().sliceSamples()));
  expectError<InputError>([&] { stream->readSlice(slice.data()); },
                          {path.string(), "trace 0 (inline 1, crossline 1) sample 2 is NaN"});
}

TEST_F(SegyBadInput, LineNumbersFromTheWrongBytesMakeAnAlmostEmptyGrid) {
  // Byte 1 (trace sequence number) as the inline: each trace its own line.
  const auto path = writeCube(dir, {.inlines = 3, .crosslines = 8, .samples = 6});
  expectError<InputError>([&] { openSegy(path, {.inlineByte = 1}); },
                          {path.string(), "make a 24 x 8 grid for only 24 traces", "--inline-byte 1"});
}

TEST_F(SegyBadInput, LineNumbersBeyondAnIntAreRejectedNotWrapped) {
  // Inlines -2^31, -2^31 + 1 and 2^31 - 1: a step of 1 over 2^32 numbers; and
  // -2^31, 2^31 - 1 alone: one step of 2^32 - 1. Neither fits the grid's ints.
  const SegyCubeSpec spec{.inlines = 3, .crosslines = 1, .samples = 4, .firstInline = std::numeric_limits<int>::min()};
  std::string bytes = readFile(writeCube(dir, spec));
  const std::size_t trace2 = 3600 + 2 * (240 + 4 * 4);
  bytes.replace(trace2 + 188, 4, std::string("\x7f\xff\xff\xff", 4));
  const auto three = withBytes(bytes);
  expectError<InputError>([&] { openSegy(three); },
                          {three.string(), "inline numbers -2147483648..2147483647", "beyond 2^31 - 1"});
  const std::size_t trace1 = 3600 + 1 * (240 + 4 * 4);
  bytes.replace(trace1 + 188, 4, std::string("\x7f\xff\xff\xff", 4));
  const auto path = dir / "two.sgy";
  writeFile(path, bytes.substr(0, trace2));
  expectError<InputError>([&] { openSegy(path); }, {path.string(), "beyond 2^31 - 1"});
}

// --- Header rules, on segyio's own test files (data/seismic/segyio) ---------------

std::filesystem::path segyio(const std::string& name) { return dataDir() / "seismic" / "segyio" / name; }

TEST(SegyHeaders, DelayScalarIntervalsAndExtendedTextualHeadersAsUpstreamReadsThem) {
  // Upstream segyio: delay 10000 with scalar -10 is 1000 ms.
  EXPECT_EQ(openSegy(segyio("delay-scalar.sgy"))->geometry().firstSampleMs, 1000.0);
  // A non-positive interval in one header is ignored in favour of the other.
  EXPECT_EQ(openSegy(segyio("interval-pos-bin-neg-trace.sgy"))->geometry().sampleIntervalUs, 2000.0);
  EXPECT_EQ(openSegy(segyio("interval-neg-bin-pos-trace.sgy"))->geometry().sampleIntervalUs, 4000.0);
  // Extended textual headers: counted, or (-1) up to the ((SEG: EndText)) stanza.
  const SegyGeometry unknown = openSegy(segyio("stanzas-unknown-count.sgy"))->geometry();
  EXPECT_EQ(unknown.extendedTextHeaders, 3);
  EXPECT_TRUE(unknown.extendedTextHeaderCountVariable);
  EXPECT_EQ(unknown.traces, 6);
  const SegyGeometry known = openSegy(segyio("stanzas-known-count.sgy"))->geometry();
  EXPECT_EQ(known.extendedTextHeaders, 3);
  EXPECT_FALSE(known.extendedTextHeaderCountVariable);
  EXPECT_EQ(known.traces, 6);
  EXPECT_EQ(openSegy(segyio("multi-text.sgy"))->geometry().extendedTextHeaders, 4);
}

/// IBM single-precision float from its four big-endian bytes.
float ibmFloat(const unsigned char* b) {
  const std::uint32_t w = (std::uint32_t{b[0]} << 24) | (std::uint32_t{b[1]} << 16) | (std::uint32_t{b[2]} << 8) | b[3];
  const double mantissa = static_cast<double>(w & 0xffffffu) / 16777216.0;
  const double value = mantissa * std::pow(16.0, static_cast<int>((w >> 24) & 0x7f) - 64);
  return static_cast<float>((w >> 31) ? -value : value);
}

TEST(SegyHeaders, Revision2TraceHeaderExtensionsAreSteppedOver) {
  // rotated-small-rev2 holds small.sgy's samples behind one extension per trace.
  auto rev2 = openSegy(segyio("rotated-small-rev2.sgy"));
  EXPECT_EQ(rev2->geometry().revision, 2);
  EXPECT_EQ(rev2->geometry().traceHeaderExtensions, 1);
  auto small = openSegy(f3("small.sgy"));
  const std::vector<float> a = readAll(*rev2), b = readAll(*small);
  ASSERT_EQ(a.size(), 5u * 5u * 50u);
  EXPECT_EQ(a, b);
  // Two extensions and one extended textual header: each trace's samples where the
  // layout puts them, decoded here from the file's bytes.
  const auto path = segyio("trace-header-extensions.sgy");
  auto stream = openSegy(path);
  const SegyGeometry& g = stream->geometry();
  EXPECT_EQ(g.revision, 2);
  EXPECT_EQ(g.revisionMinor, 1);
  EXPECT_EQ(g.extendedTextHeaders, 1);
  EXPECT_EQ(g.traceHeaderExtensions, 2);
  ASSERT_EQ(g.formatCode, 1);
  const std::string bytes = readFile(path);
  const std::vector<float> values = readAll(*stream);
  const int samples = g.samples;
  ASSERT_EQ(static_cast<std::int64_t>(values.size()), g.traces * samples);
  for (std::int64_t t = 0; t < g.traces; ++t)
    for (int k = 0; k < samples; ++k) {
      const std::size_t at = 3600 + 3200 + static_cast<std::size_t>(t) * (3 * 240 + 4 * samples) + 3 * 240 + 4 * k;
      const float expected = ibmFloat(reinterpret_cast<const unsigned char*>(bytes.data()) + at);
      // readAll is in stream order: line by line, trace by trace, sample fastest.
      EXPECT_EQ(values[static_cast<std::size_t>(t * samples + k)], expected) << "trace " << t << " sample " << k;
    }
}

TEST(SegyHeaders, SampleCountsAreUnsigned) {
  TempDir dir;
  const auto path = writeCube(dir, {.inlines = 2, .crosslines = 2, .samples = 40000, .formatCode = 8});
  auto stream = openSegy(path);
  EXPECT_EQ(stream->geometry().samples, 40000);
  const std::vector<float> values = readAll(*stream);
  ASSERT_EQ(values.size(), 4u * 40000u);
  EXPECT_EQ(values[1], std::clamp(cubeValue(0, 0, 1), -128.f, 127.f));
}

TEST(SegyHeaders, PreStackFilesAndImpossibleCountsSayWhy) {
  const auto preStack = segyio("small-ps.sgy");
  expectError<InputError>([&] { openSegy(preStack); },
                          {preStack.string(), "several traces per bin", "pre-stack", "keep one offset"});
  const auto maxed = segyio("decrement.sgy");
  expectError<InputError>([&] { openSegy(maxed); }, {maxed.string(), "65527 IBM float samples", "sample count"});
}

// --- SampleStatistics ------------------------------------------------------------

TEST(SampleStatistics, PercentilesRangeHolesAndTheActiveFraction) {
  std::vector<float> values;
  for (int v = -1000; v <= 1000; ++v) values.push_back(static_cast<float>(v));
  values.push_back(std::numeric_limits<float>::quiet_NaN());
  SampleStatistics statistics(500.0);
  statistics.add(values.data(), values.size());
  const SampleSummary& s = statistics.summary();
  EXPECT_EQ(s.samples, 2001);
  EXPECT_EQ(s.holes, 1);
  EXPECT_EQ(s.minValue, -1000.f);
  EXPECT_EQ(s.maxValue, 1000.f);
  EXPECT_EQ(s.activeSamples, 1002);  // |v| >= 500
  EXPECT_EQ(statistics.percentile(50), 0.f);
  EXPECT_EQ(statistics.percentile(0), -1000.f);
  EXPECT_EQ(statistics.percentile(100), 1000.f);
  EXPECT_EQ(statistics.percentile(75), 500.f);
  EXPECT_EQ(statistics.absPercentile(50), 500.f);
  EXPECT_EQ(statistics.absPercentile(90), 900.f);
}

}  // namespace
}  // namespace isovdb::io
