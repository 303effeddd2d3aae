// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/metaimage_reader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "isovdb/errors.h"
#include "isovdb/io/byte_stream.h"
#include "isovdb/io/dense_slice_stream.h"
#include "isovdb/io/header_text.h"

namespace isovdb::io {

namespace {

using namespace detail;

struct Field {
  std::string name;  ///< as spelled in the file
  std::string value;
};

/// The fields of one MetaImage header (keys compared case-insensitively).
class MetaFields : public HeaderFields {
 public:
  using HeaderFields::HeaderFields;

  void add(const std::string& name, std::string value) {
    if (!fields_.emplace(lower(name), Field{name, std::move(value)}).second) fail(name, "appears twice");
  }
  /// The first of `names` present, or nullptr; two present with different values is an error.
  const Field* find(std::initializer_list<const char*> names) const {
    const Field* found = nullptr;
    for (const char* name : names) {
      const auto it = fields_.find(lower(name));
      if (it == fields_.end()) continue;
      if (!found) {
        found = &it->second;
      } else if (splitWords(found->value) != splitWords(it->second.value)) {
        fail(it->second.name, "'" + it->second.value + "' contradicts " + found->name + " = " + found->value);
      }
    }
    return found;
  }
  const Field& require(const char* name) const {
    const Field* field = find({name});
    if (!field) throw InputError(where() + "field '" + name + "' is missing");
    return *field;
  }
  bool boolean(const Field& field) const {
    const std::string value = lower(trim(field.value));
    if (value == "true" || value == "1") return true;
    if (value == "false" || value == "0") return false;
    fail(field.name, "expected True or False, got '" + field.value + "'");
  }
  std::int64_t integer(const Field& field) const {
    const auto value = parseInt(trim(field.value));
    if (!value) fail(field.name, "'" + field.value + "' is not an integer");
    return *value;
  }
  template <std::size_t N>
  std::array<double, N> numbers(const Field& field) const {
    const std::vector<std::string> words = splitWords(field.value);
    if (words.size() != N)
      fail(field.name, "expected " + std::to_string(N) + " values, got " + std::to_string(words.size()));
    std::array<double, N> values{};
    for (std::size_t i = 0; i < N; ++i) {
      const auto value = parseDouble(words[i]);
      if (!value || !std::isfinite(*value)) fail(field.name, "'" + words[i] + "' is not a finite number");
      values[i] = *value;
    }
    return values;
  }

 private:
  std::map<std::string, Field> fields_;
};

SampleType parseElementType(const MetaFields& fields, const Field& field) {
  struct Entry {
    const char* name;
    SampleType type;
  };
  static constexpr Entry kTypes[] = {
      {"MET_CHAR", SampleType::Int8},     {"MET_UCHAR", SampleType::UInt8},    {"MET_SHORT", SampleType::Int16},
      {"MET_USHORT", SampleType::UInt16}, {"MET_INT", SampleType::Int32},      {"MET_UINT", SampleType::UInt32},
      {"MET_FLOAT", SampleType::Float32}, {"MET_DOUBLE", SampleType::Float64},
  };
  const std::string name = trim(field.value);
  for (const Entry& entry : kTypes)
    if (lower(name) == lower(entry.name)) return entry.type;
  fields.fail(field.name, "unknown or unsupported element type '" + name +
                              "' (expected MET_CHAR, MET_UCHAR, MET_SHORT, MET_USHORT, MET_INT, MET_UINT, "
                              "MET_FLOAT or MET_DOUBLE)");
}

}  // namespace

std::unique_ptr<SliceStream> openMetaImage(const std::filesystem::path& path) {
  const std::string source = path.string();
  MetaFields fields("'" + source + "': ");
  auto file = std::make_unique<FileRegionStream>(path);

  // Header: "Key = Value" lines up to and including ElementDataFile.
  const Field* dataFileField = nullptr;
  std::int64_t lineNumber = 0;
  while (auto line = file->readLine()) {
    ++lineNumber;
    fields.checkHeaderLength(file->position(), "without an ElementDataFile field");
    const std::string text = trim(*line);
    if (std::any_of(text.begin(), text.end(), [](unsigned char c) { return (c < 0x20 && c != '\t') || c == 0x7f; }))
      throw InputError(fields.where() + "not a MetaImage header (line " + std::to_string(lineNumber) +
                       " holds binary data before any ElementDataFile field)");
    if (text.empty() || text[0] == '#') continue;
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos || equals == 0) {
      if (lineNumber == 1) throw InputError(fields.where() + "not a MetaImage header (no 'Key = Value' first line)");
      throw InputError(fields.where() + "line " + std::to_string(lineNumber) + " is not 'Key = Value': '" + text + "'");
    }
    const std::string key = trim(std::string_view(text).substr(0, equals));
    fields.add(key, trim(std::string_view(text).substr(equals + 1)));
    if (lower(key) == "elementdatafile") {
      dataFileField = &fields.require("ElementDataFile");
      break;
    }
  }

  if (const Field* objectType = fields.find({"ObjectType"}); objectType && lower(objectType->value) != "image")
    fields.fail(objectType->name, "expected Image, got '" + objectType->value + "'");
  const Field& nDims = fields.require("NDims");
  if (fields.integer(nDims) != 3) fields.fail(nDims.name, "only 3-D volumes are supported, got " + nDims.value);

  VolumeHeader header;
  const Field& dimSize = fields.require("DimSize");
  const std::vector<std::string> dims = splitWords(dimSize.value);
  if (dims.size() != 3) fields.fail(dimSize.name, "NDims is 3 but it gives " + std::to_string(dims.size()) + " values");
  for (int axis = 0; axis < 3; ++axis) header.dims[axis] = fields.integer(Field{dimSize.name, dims[axis]});
  header.sampleType = parseElementType(fields, fields.require("ElementType"));
  const std::int64_t dataBytes = checkedVolumeBytes(header, source, "field '" + dimSize.name + "'");

  if (const Field* channels = fields.find({"ElementNumberOfChannels"}); channels && fields.integer(*channels) != 1)
    fields.fail(channels->name, "only 1 channel is supported, got " + channels->value);
  if (const Field* binary = fields.find({"BinaryData"}); binary && !fields.boolean(*binary))
    fields.fail(binary->name, "ASCII data (BinaryData = False) is not supported");
  if (const Field* msb = fields.find({"BinaryDataByteOrderMSB", "ElementByteOrderMSB", "ByteOrderMSB"}))
    header.bigEndian = fields.boolean(*msb);
  if (const Field* spacing =
          fields.find({"ElementSpacing"}) ? fields.find({"ElementSpacing"}) : fields.find({"ElementSize"})) {
    header.spacing = fields.numbers<3>(*spacing);
    for (double value : header.spacing)
      if (value <= 0) fields.fail(spacing->name, "each value must be positive, got '" + spacing->value + "'");
  }
  if (const Field* origin = fields.find({"Offset", "Origin", "Position"})) header.origin = fields.numbers<3>(*origin);
  if (const Field* matrix = fields.find({"TransformMatrix", "Rotation", "Orientation"})) {
    const std::array<double, 9> m = fields.numbers<9>(*matrix);
    for (int i = 0; i < 9; ++i) {
      if (std::abs(m[i] - (i % 4 == 0 ? 1.0 : 0.0)) > 1e-6)
        fields.fail(matrix->name, "only the identity is supported (axis-aligned volumes), got '" + matrix->value + "'");
    }
  }

  bool compressed = false;
  if (const Field* field = fields.find({"CompressedData"})) compressed = fields.boolean(*field);
  std::int64_t compressedSize = -1;
  if (const Field* field = fields.find({"CompressedDataSize"}); field && compressed) {
    compressedSize = fields.integer(*field);
    if (compressedSize <= 0) fields.fail(field->name, "must be positive, got " + field->value);
  }
  std::int64_t headerSize = 0;
  const Field* headerSizeField = fields.find({"HeaderSize"});
  if (headerSizeField) {
    headerSize = fields.integer(*headerSizeField);
    if (headerSize < -1) fields.fail(headerSizeField->name, "must be >= 0 or -1, got " + headerSizeField->value);
    if (headerSize == -1 && compressed && compressedSize < 0)
      fields.fail(headerSizeField->name, "-1 with CompressedData = True needs CompressedDataSize");
  }

  // The data: after the header (LOCAL) or in a detached file.
  if (!dataFileField) throw InputError(fields.where() + "field 'ElementDataFile' is missing");
  const std::string dataFile = trim(dataFileField->value);
  const bool local = lower(dataFile) == "local";
  std::filesystem::path dataPath = path;
  std::string label = "'" + source + "'";
  if (!local) {
    if (const std::string problem = dataFileProblem(dataFile); !problem.empty())
      fields.fail(dataFileField->name, problem);
    dataPath = dataFilePath(path, dataFile);
    std::error_code ec;
    if (!std::filesystem::exists(dataPath, ec))
      throw IoError(fields.where() + "field '" + dataFileField->name + "': '" + dataPath.string() + "': no such file");
    label = "'" + dataPath.string() + "' (data file of '" + source + "')";
  }
  const std::string dataName = dataPath.string();

  std::unique_ptr<FileRegionStream> data;
  if (local && headerSize == 0) {
    data = std::move(file);
  } else {
    file.reset();
    data = std::make_unique<FileRegionStream>(dataPath, FileRegionOptions{.label = label});
    if (headerSize == -1) {
      const std::int64_t tail = compressed ? compressedSize : dataBytes;
      if (tail > data->fileSize())
        fields.fail(headerSizeField->name, "-1 needs the last " + std::to_string(tail) + " bytes of '" + dataName +
                                               "', which holds only " + std::to_string(data->fileSize()));
      data->skip(data->fileSize() - tail);
    } else if (headerSize > 0) {
      if (headerSize > data->fileSize())
        fields.fail(headerSizeField->name, std::to_string(headerSize) + " is past the end of '" + dataName + "' (" +
                                               std::to_string(data->fileSize()) + " bytes)");
      data->skip(headerSize);
    }
  }

  std::unique_ptr<ByteStream> bytes;
  if (compressed) {
    bytes = std::make_unique<InflateStream>(std::move(data));
  } else {
    if (data->remaining() != dataBytes)
      fields.fail(dimSize.name, joinDims(header.dims) + " " + std::string(sampleTypeName(header.sampleType)) +
                                    " samples need " + std::to_string(dataBytes) + " bytes but '" + dataName +
                                    "' holds " + std::to_string(data->remaining()) + " data bytes from offset " +
                                    std::to_string(data->fileSize() - data->remaining()));
    bytes = std::move(data);
  }
  return std::make_unique<DenseSliceStream>(source, header, std::move(bytes));
}

}  // namespace isovdb::io
