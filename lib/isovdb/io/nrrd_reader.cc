// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/nrrd_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "isovdb/errors.h"
#include "isovdb/io/bunzip2_stream.h"
#include "isovdb/io/byte_stream.h"
#include "isovdb/io/dense_slice_stream.h"
#include "isovdb/io/header_text.h"

namespace isovdb::io {

namespace {

using namespace detail;

/// The fields of one NRRD header and how to name them in messages.
class NrrdFields : public HeaderFields {
 public:
  using HeaderFields::HeaderFields;

  void add(const std::string& name, std::string value) {
    if (!values_.emplace(name, std::move(value)).second) fail(name, "appears twice");
  }
  const std::string* find(const std::string& name) const {
    const auto it = values_.find(name);
    return it == values_.end() ? nullptr : &it->second;
  }
  const std::string& require(const std::string& name, const std::string& why = {}) const {
    const std::string* value = find(name);
    if (!value) throw InputError(where() + "field '" + name + "' is missing" + why);
    return *value;
  }
  std::int64_t integer(const std::string& name, const std::string& text) const {
    const auto value = parseInt(text);
    if (!value) fail(name, "'" + text + "' is not an integer");
    return *value;
  }
  double number(const std::string& name, const std::string& text) const {
    const auto value = parseDouble(text);
    if (!value) fail(name, "'" + text + "' is not a number");
    return *value;
  }
  /// Parses "(a,b,c)" into three numbers.
  std::array<double, 3> vector3(const std::string& name, std::string_view text) const {
    const std::string t = trim(text);
    if (t.size() < 2 || t.front() != '(' || t.back() != ')')
      fail(name, "expected a vector like (1,0,0), got '" + t + "'");
    std::vector<double> values;
    std::string_view inner(t);
    inner = inner.substr(1, inner.size() - 2);
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = inner.find(',', start);
      values.push_back(number(name, trim(inner.substr(start, comma - start))));
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    if (values.size() != 3)
      fail(name, "vector " + t + " has " + std::to_string(values.size()) + " components, expected 3");
    return {values[0], values[1], values[2]};
  }

 private:
  std::map<std::string, std::string> values_;
};

/// Splits "space directions" into its per-axis tokens: "(..)" vectors or "none".
std::vector<std::string> splitVectors(const NrrdFields& fields, const std::string& name, const std::string& text) {
  std::vector<std::string> tokens;
  std::size_t i = 0;
  while (i < text.size()) {
    if (std::isspace(static_cast<unsigned char>(text[i]))) {
      ++i;
    } else if (text[i] == '(') {
      const std::size_t close = text.find(')', i);
      if (close == std::string::npos) fields.fail(name, "unbalanced parentheses in '" + text + "'");
      tokens.push_back(text.substr(i, close + 1 - i));
      i = close + 1;
    } else {
      std::size_t end = i;
      while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) ++end;
      tokens.push_back(text.substr(i, end - i));
      i = end;
    }
  }
  return tokens;
}

SampleType parseNrrdType(const NrrdFields& fields, const std::string& text) {
  std::string name = lower(trim(text));
  if (name == "signed short int") name = "int16";
  if (name == "signed int") name = "int32";
  const auto type = parseSampleType(name);
  if (!type)
    fields.fail("type", "unknown or unsupported sample type '" + text +
                            "' (expected int8, uint8, int16, uint16, int32, uint32, float or double)");
  return *type;
}

}  // namespace

std::unique_ptr<SliceStream> openNrrd(const std::filesystem::path& path) {
  const std::string source = path.string();
  NrrdFields fields("'" + source + "': ");
  auto file = std::make_unique<FileRegionStream>(path);

  const auto magic = file->readLine(64);
  if (!magic || magic->size() != 8 || magic->compare(0, 7, "NRRD000") != 0 || (*magic)[7] < '1' || (*magic)[7] > '5')
    throw InputError(fields.where() + "not a NRRD file (the first line must be NRRD0001 to NRRD0005)");

  bool blankLine = false;
  std::int64_t lineNumber = 1;
  while (auto line = file->readLine()) {
    ++lineNumber;
    fields.checkHeaderLength(file->position(), "(missing blank line before the data?)");
    if (trim(*line).empty()) {
      blankLine = true;
      break;
    }
    if ((*line)[0] == '#') continue;
    const std::size_t colon = line->find(':');
    if (colon == std::string::npos)
      throw InputError(fields.where() + "line " + std::to_string(lineNumber) +
                       " is neither 'field: value' nor a comment: '" + *line + "'");
    if (colon + 1 < line->size() && (*line)[colon + 1] == '=') continue;  // key:=value pair
    std::string name = lower(trim(std::string_view(*line).substr(0, colon)));
    if (name == "datafile") name = "data file";
    if (name == "lineskip") name = "line skip";
    if (name == "byteskip") name = "byte skip";
    fields.add(name, trim(std::string_view(*line).substr(colon + 1)));
  }

  // dimension, type, sizes.
  const std::int64_t dimension = fields.integer("dimension", fields.require("dimension"));
  if (dimension != 3) fields.fail("dimension", "only 3-D volumes are supported, got " + std::to_string(dimension));
  VolumeHeader header;
  header.sampleType = parseNrrdType(fields, fields.require("type"));
  const std::vector<std::string> sizes = splitWords(fields.require("sizes"));
  if (static_cast<std::int64_t>(sizes.size()) != dimension)
    fields.fail("sizes", "dimension is 3 but it gives " + std::to_string(sizes.size()) + " values");
  for (int axis = 0; axis < 3; ++axis) header.dims[axis] = fields.integer("sizes", sizes[axis]);
  const std::int64_t dataBytes = checkedVolumeBytes(header, source, "field 'sizes'");

  // encoding, endian.
  const std::string encoding = lower(fields.require("encoding"));
  const bool gzip = encoding == "gzip" || encoding == "gz";
  const bool bzip2 = encoding == "bzip2" || encoding == "bz2";
  const bool compressed = gzip || bzip2;
  if (!compressed && encoding != "raw")
    fields.fail("encoding", "unsupported encoding '" + encoding + "' (supported: raw, gzip, bzip2)");
  if (sampleSize(header.sampleType) > 1) {
    const std::string endian = lower(
        fields.require("endian", " (required for " + std::string(sampleTypeName(header.sampleType)) + " samples)"));
    if (endian != "little" && endian != "big")
      fields.fail("endian", "expected 'little' or 'big', got '" + endian + "'");
    header.bigEndian = endian == "big";
  }

  // Geometry: spacings or space directions, space origin.
  const std::string* spacings = fields.find("spacings");
  const std::string* directions = fields.find("space directions");
  if (spacings && directions)
    fields.fail("spacings", "contradicts 'space directions' (a header may give only one of them)");
  if (spacings) {
    const std::vector<std::string> words = splitWords(*spacings);
    if (words.size() != 3)
      fields.fail("spacings", "dimension is 3 but it gives " + std::to_string(words.size()) + " values");
    for (int axis = 0; axis < 3; ++axis) {
      header.spacing[axis] = fields.number("spacings", words[axis]);
      if (!std::isfinite(header.spacing[axis]) || header.spacing[axis] <= 0)
        fields.fail("spacings", "each value must be finite and positive, got '" + words[axis] + "'");
    }
  }
  if (directions) {
    const std::vector<std::string> vectors = splitVectors(fields, "space directions", *directions);
    if (vectors.size() != 3)
      fields.fail("space directions", "dimension is 3 but it gives " + std::to_string(vectors.size()) + " vectors");
    for (int axis = 0; axis < 3; ++axis) {
      if (lower(vectors[axis]) == "none")
        fields.fail("space directions", "axis " + std::to_string(axis) + " has no direction ('none')");
      const std::array<double, 3> v = fields.vector3("space directions", vectors[axis]);
      for (int other = 0; other < 3; ++other) {
        if (other != axis && v[other] != 0.0)
          fields.fail("space directions", "only axis-aligned volumes are supported, but axis " + std::to_string(axis) +
                                              " has direction " + vectors[axis]);
      }
      if (!std::isfinite(v[axis]) || v[axis] <= 0)
        fields.fail("space directions", "axis " + std::to_string(axis) + " has direction " + vectors[axis] +
                                            " (flipped or zero steps are not supported)");
      header.spacing[axis] = v[axis];
    }
  }
  if (const std::string* origin = fields.find("space origin")) header.origin = fields.vector3("space origin", *origin);
  if (const std::string* spaceDimension = fields.find("space dimension")) {
    if (fields.integer("space dimension", *spaceDimension) != 3)
      fields.fail("space dimension", "only 3 is supported, got " + *spaceDimension);
  }

  // Skips.
  std::int64_t lineSkip = 0;
  std::int64_t byteSkip = 0;
  if (const std::string* text = fields.find("line skip")) {
    lineSkip = fields.integer("line skip", *text);
    if (lineSkip < 0) fields.fail("line skip", "must be >= 0, got " + *text);
  }
  if (const std::string* text = fields.find("byte skip")) {
    byteSkip = fields.integer("byte skip", *text);
    if (byteSkip < -1 || (byteSkip == -1 && compressed))
      fields.fail("byte skip", "must be >= 0 (or -1 with raw encoding), got " + *text);
  }

  // Where the data is: the data file, or after the blank line.
  std::unique_ptr<FileRegionStream> data;
  std::string dataName = source;
  if (const std::string* dataFile = fields.find("data file")) {
    if (const std::string problem = dataFileProblem(*dataFile); !problem.empty()) fields.fail("data file", problem);
    const std::filesystem::path dataPath = dataFilePath(path, *dataFile);
    dataName = dataPath.string();
    std::error_code ec;
    if (!std::filesystem::exists(dataPath, ec))
      throw IoError(fields.where() + "field 'data file': '" + dataName + "': no such file");
    data = std::make_unique<FileRegionStream>(
        dataPath, FileRegionOptions{.label = "'" + dataName + "' (data file of '" + source + "')"});
  } else {
    if (!blankLine)
      throw InputError(fields.where() +
                       "no data: the header has neither a 'data file' field nor a blank line "
                       "followed by attached data");
    data = std::move(file);
  }
  data->skipLines(lineSkip);

  const std::string need = joinDims(header.dims) + " " + std::string(sampleTypeName(header.sampleType)) +
                           " samples need " + std::to_string(dataBytes) + " bytes";
  std::unique_ptr<ByteStream> bytes;
  if (compressed) {
    // The byte skip counts decompressed bytes (Teem, pynrrd).
    if (gzip)
      bytes = std::make_unique<InflateStream>(std::move(data));
    else
      bytes = std::make_unique<Bunzip2Stream>(std::move(data));
    bytes->skip(byteSkip);
  } else {
    const std::int64_t available = data->remaining();
    if (byteSkip == -1) byteSkip = std::max<std::int64_t>(available - dataBytes, 0);
    if (available - byteSkip != dataBytes)
      fields.fail("sizes", need + " but '" + dataName + "' holds " +
                               std::to_string(std::max<std::int64_t>(available - byteSkip, 0)) + " data bytes" +
                               (byteSkip > 0 ? " after the byte skip of " + std::to_string(byteSkip) : ""));
    data->skip(byteSkip);
    bytes = std::move(data);
  }
  return std::make_unique<DenseSliceStream>(source, header, std::move(bytes));
}

}  // namespace isovdb::io
