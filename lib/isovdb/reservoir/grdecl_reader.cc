// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/reservoir/grdecl_reader.h"

#include <cctype>
#include <charconv>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>
#include <sstream>

#include "isovdb/errors.h"
#include "isovdb/huge_pages.h"
#include "isovdb/reservoir/grdecl_edits.h"
#include "isovdb/reservoir/grdecl_tokens.h"

namespace isovdb::reservoir {
namespace {

// Keywords that carry no record.
const std::set<std::string> kFlagKeywords = {
    "RUNSPEC", "GRID",    "EDIT",    "NOECHO", "ECHO",    "OIL",          "WATER",  "GAS",   "DISGAS",
    "VAPOIL",  "FIELD",   "METRIC",  "LAB",    "UNIFOUT", "UNIFIN",       "FMTOUT", "FMTIN", "INIT",
    "NOSIM",   "NEWTRAN", "OLDTRAN", "NONNC",  "NOGGF",   "GRIDFILE_OFF", "MULTOUT"};
// Sections after the grid: nothing there describes the grid, stop reading.
const std::set<std::string> kStopKeywords = {"PROPS", "REGIONS", "SOLUTION", "SUMMARY", "SCHEDULE", "END"};
// Keywords with one non-numeric (or defaulted) record that need no warning.
const std::set<std::string> kKnownTextKeywords = {"MAPUNITS", "GRIDUNIT", "GDORIENT", "START",  "WELLDIMS",
                                                  "TABDIMS",  "EQLDIMS",  "REGDIMS",  "NSTACK", "COORDSYS"};
// Keywords that change properties in a box of cells, records ended by an empty record.
const std::set<std::string> kEditKeywords = {"COPY", "MULTIPLY", "ADD", "EQUALS", "MINVALUE", "MAXVALUE"};
// Keywords of several records (ended by an empty one) that describe no cell property.
const std::set<std::string> kSkippedMultiRecordKeywords = {"MULTREGT", "NNC",     "EDITNNC", "EQUALREG",
                                                           "MULTIREG", "COPYREG", "ADDREG",  "THPRES"};

bool looksLikeKeyword(const GrdeclToken& t) {
  if (t.quoted || t.text.empty() || t.text.size() > 8) return false;
  if (!std::isupper(static_cast<unsigned char>(t.text[0]))) return false;
  for (char c : t.text)
    if (!(std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_'))
      return false;
  return true;
}

/// The position of `c` in `s`, or npos: a loop over a token of a few characters, where
/// `string_view::find` is a call into `memchr` per token (with the exponent check below,
/// 11 % of reading a 1.5 M-cell deck).
std::size_t findChar(std::string_view s, char c) {
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i] == c) return i;
  return std::string_view::npos;
}

bool parseDouble(std::string_view s, double& out) {
  const char* begin = s.data();
  const char* end = s.data() + s.size();
  // Fortran exponents (1.0D+03).
  std::string fixed;
  if (std::any_of(s.begin(), s.end(), [](char c) { return c == 'd' || c == 'D'; })) {
    fixed = s;
    for (char& c : fixed)
      if (c == 'd' || c == 'D') c = 'e';
    begin = fixed.data();
    end = fixed.data() + fixed.size();
  }
  if (begin != end && *begin == '+') ++begin;
  auto [ptr, ec] = std::from_chars(begin, end, out);
  return ec == std::errc() && ptr == end;
}

/// A record's entries: a value, or std::nullopt where `n*` defaults n of them.
using RecordItems = std::vector<std::optional<std::string>>;

struct Parser {
  GrdeclDeck& deck;
  GrdeclLimits limits;
  int depth = 0;
  bool stopped = false;
  std::optional<CellBox> currentBox{};  ///< BOX ... ENDBOX

  /// The entries of the record t[i..end), `n*` expanded.
  static RecordItems recordItems(const std::vector<GrdeclToken>& t, std::size_t i, std::size_t end) {
    RecordItems items;
    for (std::size_t k = i; k < end; ++k) {
      const std::string_view s = t[k].text;
      const std::size_t star = t[k].quoted ? std::string::npos : s.find('*');
      long long repeat = 0;
      if (star != std::string::npos && star > 0 &&
          std::from_chars(s.data(), s.data() + star, repeat).ptr == s.data() + star && repeat > 0 && repeat < 1000) {
        const std::optional<std::string> item =
            star + 1 < s.size() ? std::optional<std::string>(std::string(s.substr(star + 1))) : std::nullopt;
        items.insert(items.end(), static_cast<std::size_t>(repeat), item);
      } else {
        items.emplace_back(std::string(s));
      }
    }
    return items;
  }

  const std::array<int, 3>& gridDims(const std::filesystem::path& file, const GrdeclToken& keyword) const {
    if (deck.dims[0] == 0)
      throw InputError(where(file, keyword.line) + ": " + std::string(keyword.text) +
                       " before SPECGRID or DIMENS: the grid's size is not known yet");
    return deck.dims;
  }

  int integerItem(const std::optional<std::string>& item, const std::filesystem::path& file,
                  const GrdeclToken& keyword) const {
    double v = 0;
    if (!item || !parseDouble(*item, v) || v != std::floor(v) || std::abs(v) > 1e9)
      throw InputError(where(file, keyword.line) + ": " + std::string(keyword.text) +
                       ": expected a cell index, found '" + item.value_or("default") + "'");
    return static_cast<int>(v);
  }

  /// Box bounds from items[first..first+6) (missing or defaulted ones: the current BOX or the grid).
  CellBox boxOf(const RecordItems& items, std::size_t first, const std::filesystem::path& file,
                const GrdeclToken& keyword) const {
    const std::array<int, 3>& dims = gridDims(file, keyword);
    const CellBox grid{{0, 0, 0}, {dims[0] - 1, dims[1] - 1, dims[2] - 1}};
    std::array<std::optional<int>, 6> bounds;
    for (std::size_t b = 0; b < 6 && first + b < items.size(); ++b)
      if (items[first + b]) bounds[b] = integerItem(items[first + b], file, keyword);
    try {
      return cellBoxOf(bounds, currentBox.value_or(grid), dims);
    } catch (const std::invalid_argument& e) {
      throw InputError(where(file, keyword.line) + ": " + std::string(keyword.text) + ": " + e.what());
    }
  }

  /// The records of a multi-record keyword from t[i], each handed to `record(begin, end)`; returns
  /// the index after the empty record that ends the keyword.
  template <typename F>
  std::size_t forEachRecord(const std::vector<GrdeclToken>& t, std::size_t i, const std::filesystem::path& file,
                            const GrdeclToken& keyword, F&& record) const {
    while (i < t.size() && !t[i].isSlash()) {
      const std::size_t end = recordEnd(t, i, file, keyword);
      record(i, end);
      i = end + 1;
    }
    return recordEnd(t, i, file, keyword) + 1;
  }

  std::string where(const std::filesystem::path& file, int line) const {
    return file.string() + ":" + std::to_string(line);
  }

  // Index of the `/` that ends the record starting at `i`; throws when none.
  std::size_t recordEnd(const std::vector<GrdeclToken>& t, std::size_t i, const std::filesystem::path& file,
                        const GrdeclToken& keyword) const {
    for (std::size_t k = i; k < t.size(); ++k)
      if (t[k].isSlash()) return k;
    throw InputError(where(file, keyword.line) + ": keyword " + std::string(keyword.text) +
                     " has no terminating '/' before the end of the file");
  }

  // Numeric values of the record from `i`; `/` index in `end`. Throws on a non-number.
  /// Most values one keyword may hold once the grid's size is known: what its largest
  /// array holds, 8 N (ZCORN) or 6 (NX+1)(NY+1) (COORD) values.
  double gridValueLimit() const {
    if (deck.dims[0] <= 0) return std::numeric_limits<double>::infinity();
    const double nx = deck.dims[0], ny = deck.dims[1], nz = deck.dims[2];
    return std::max(8.0 * nx * ny * nz, 6.0 * (nx + 1) * (ny + 1)) + 64;  // + 64: MAPAXES-sized records
  }
  /// Values the deck holds so far, every keyword together.
  double valuesHeld() const {
    double held = static_cast<double>(deck.coord.size() + deck.zcorn.size() + deck.actnum.size() + deck.mapaxes.size());
    for (const auto& [name, values] : deck.properties) held += static_cast<double>(values.size());
    return held;
  }
  std::string beyondGrid() const {
    return "more than any array of the " + std::to_string(deck.dims[0]) + " x " + std::to_string(deck.dims[1]) + " x " +
           std::to_string(deck.dims[2]) + " grid holds";
  }
  std::string beyondMaxValues() const {
    return "the deck's keywords together would hold more than --max-values " + std::to_string(limits.maxValues) +
           " values (raise it for a larger grid)";
  }

  std::vector<double> numbers(const std::vector<GrdeclToken>& t, std::size_t i, std::size_t& end,
                              const std::filesystem::path& file, const GrdeclToken& keyword,
                              std::size_t limit = static_cast<std::size_t>(-1)) const {
    std::vector<double> values;
    // The whole deck is bounded, not each n*value: three 10^8 repeats made 4.5 GB.
    const double gridLimit = gridValueLimit();
    const double deckRoom = static_cast<double>(limits.maxValues) - valuesHeld();
    // One value per token at least (n*value repeats add more): no regrowth for plain arrays.
    std::size_t tokens = 0;
    while (i + tokens < t.size() && i + tokens < limit && !t[i + tokens].isSlash()) ++tokens;
    reserveHuge(values, std::min(tokens, static_cast<std::size_t>(std::max(0.0, deckRoom))));
    for (end = i; end < t.size() && end < limit && !t[end].isSlash(); ++end) {
      const std::string_view s = t[end].text;
      const std::size_t star = findChar(s, '*');
      double value = 0;
      long long repeat = 1;
      bool ok = true;
      if (star != std::string::npos) {
        const auto [p, ec] = std::from_chars(s.data(), s.data() + star, repeat);
        ok = ec == std::errc() && p == s.data() + star && repeat > 0 && star + 1 < s.size() &&
             parseDouble(s.substr(star + 1), value);
      } else {
        ok = parseDouble(s, value);
      }
      if (!ok || t[end].quoted) {
        if (looksLikeKeyword(t[end]))
          throw InputError(where(file, keyword.line) + ": keyword " + std::string(keyword.text) +
                           " has no terminating '/' (keyword " + std::string(s) + " found at line " +
                           std::to_string(t[end].line) + ")");
        throw InputError(where(file, t[end].line) + ": keyword " + std::string(keyword.text) + ": '" + std::string(s) +
                         "' is not a number (expected a value or n*value)");
      }
      const double count = static_cast<double>(values.size()) + static_cast<double>(repeat);
      if (count > gridLimit || count > deckRoom)
        throw InputError(where(file, t[end].line) + ": keyword " + std::string(keyword.text) + " at '" +
                         std::string(s) +
                         "': " + (count > gridLimit ? "would hold " + beyondGrid() : beyondMaxValues()));
      values.insert(values.end(), static_cast<std::size_t>(repeat), value);
    }
    if (end == t.size() && end < limit)
      throw InputError(where(file, keyword.line) + ": keyword " + std::string(keyword.text) +
                       " has no terminating '/' before the end of the file");
    return values;
  }

  bool recordIsNumeric(const std::vector<GrdeclToken>& t, std::size_t i) const {
    if (i >= t.size() || t[i].isSlash()) return true;  // empty record
    double v;
    const std::string_view s = t[i].text;
    const std::size_t star = findChar(s, '*');
    return !t[i].quoted &&
           (star == std::string::npos ? parseDouble(s, v) : star + 1 < s.size() && parseDouble(s.substr(star + 1), v));
  }

  void readFile(const std::filesystem::path& file) {
    if (depth > 16) throw InputError(file.string() + ": INCLUDE nested more than 16 deep");
    // A device or a pipe (INCLUDE '/dev/zero') would be read forever.
    if (std::filesystem::exists(file) && !std::filesystem::is_regular_file(file))
      throw InputError(file.string() + ": not a regular file (a GRDECL deck or INCLUDE must be a file)");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw IoError(file.string() + ": cannot open GRDECL file");
    // The whole text, read at once: the tokens view it while this file is parsed.
    std::string text;
    resizeHuge(text, static_cast<std::size_t>(std::filesystem::file_size(file)));
    if (!in.read(text.data(), static_cast<std::streamsize>(text.size())))
      throw IoError(file.string() + ": cannot read GRDECL file");
    const std::vector<GrdeclToken> t = tokenizeGrdecl(text);

    std::size_t i = 0;
    while (i < t.size() && !stopped) {
      const GrdeclToken& keyword = t[i];
      if (keyword.isSlash()) {  // a stray terminator (e.g. after a defaulted record)
        ++i;
        continue;
      }
      if (!looksLikeKeyword(keyword))
        throw InputError(where(file, keyword.line) + ": expected a keyword, found '" + std::string(keyword.text) + "'");
      const std::string name(keyword.text);
      ++i;
      if (kStopKeywords.count(name)) {
        stopped = true;
        break;
      }
      if (kFlagKeywords.count(name)) continue;
      if (name == "TITLE") {  // the next line is free text
        const int line = keyword.line;
        while (i < t.size() && t[i].line == line + 1) ++i;
        continue;
      }
      if (name == "INCLUDE") {
        const std::size_t end = recordEnd(t, i, file, keyword);
        if (end != i + 1) throw InputError(where(file, keyword.line) + ": INCLUDE expects one file name then '/'");
        const std::filesystem::path included = file.parent_path() / t[i].text;
        if (!std::filesystem::exists(included))
          throw InputError(where(file, keyword.line) + ": INCLUDE file not found: " + included.string());

        ++depth;
        readFile(included);
        --depth;
        i = end + 1;
        continue;
      }
      if (kEditKeywords.count(name)) {
        i = forEachRecord(t, i, file, keyword, [&](std::size_t begin, std::size_t end) {
          applyEdit(recordItems(t, begin, end), file, keyword);
        });
        continue;
      }
      if (name == "FAULTS") {
        i = forEachRecord(t, i, file, keyword, [&](std::size_t begin, std::size_t end) {
          const RecordItems items = recordItems(t, begin, end);
          if (items.size() < 8 || !items[0] || !items[7])
            throw InputError(where(file, t[begin].line) +
                             ": FAULTS: expected 'name' I1 I2 J1 J2 K1 K2 'face' before '/'");
          GrdeclFault fault{*items[0], {}, *items[7]};
          for (std::size_t b = 0; b < 6; ++b) fault.box[b] = integerItem(items[1 + b], file, keyword);
          deck.faults.push_back(std::move(fault));
        });
        continue;
      }
      if (name == "MULTFLT") {
        i = forEachRecord(t, i, file, keyword, [&](std::size_t begin, std::size_t end) {
          const RecordItems items = recordItems(t, begin, end);
          double multiplier = 0;
          if (items.size() < 2 || !items[0] || !items[1] || !parseDouble(*items[1], multiplier))
            throw InputError(where(file, t[begin].line) + ": MULTFLT: expected 'fault name' multiplier before '/'");
          deck.faultMultipliers[*items[0]] = multiplier;
        });
        continue;
      }
      if (name == "BOX") {
        const std::size_t end = recordEnd(t, i, file, keyword);
        currentBox.reset();  // a BOX's defaults are the whole grid
        currentBox = boxOf(recordItems(t, i, end), 0, file, keyword);
        i = end + 1;
        continue;
      }
      if (name == "ENDBOX") {
        currentBox.reset();
        continue;
      }
      if (kSkippedMultiRecordKeywords.count(name)) {
        deck.warnings.push_back(where(file, keyword.line) + ": keyword " + name +
                                " does not change the cells' geometry or properties (skipped)");
        i = forEachRecord(t, i, file, keyword, [](std::size_t, std::size_t) {});
        continue;
      }
      if (kKnownTextKeywords.count(name) || !recordIsNumeric(t, i)) {
        if (!kKnownTextKeywords.count(name))
          deck.warnings.push_back(where(file, keyword.line) + ": unknown keyword " + name + " skipped");
        i = recordEnd(t, i, file, keyword) + 1;
        // More records before the next keyword: a multi-record keyword, ended by an empty record.
        if (i < t.size() && !t[i].isSlash() && !looksLikeKeyword(t[i]))
          i = forEachRecord(t, i, file, keyword, [](std::size_t, std::size_t) {});
        continue;
      }
      if (name == "SPECGRID") {  // nx ny nz numres F|T: only the first three matter
        const std::size_t end = recordEnd(t, i, file, keyword);
        std::size_t stop = i;
        std::vector<double> values = numbers(t, i, stop, file, keyword, std::min(end, i + 3));
        i = end + 1;
        store(name, std::move(values), file, keyword.line);
        continue;
      }
      std::size_t end = i;
      std::vector<double> values = numbers(t, i, end, file, keyword);
      i = end + 1;
      store(name, std::move(values), file, keyword.line);
    }
  }

  void applyEdit(const RecordItems& items, const std::filesystem::path& file, const GrdeclToken& keyword) {
    PropertyEdit edit;
    edit.keyword = keyword.text;
    const bool copy = edit.keyword == "COPY";
    if (items.size() < 2 || !items[0] || !items[1])
      throw InputError(where(file, keyword.line) + ": " + edit.keyword + ": expected " +
                       (copy ? "'FROM' 'TO'" : "'NAME' value") + " then an optional box before '/'");
    edit.name = *items[0];
    if (copy)
      edit.target = *items[1];
    else if (!parseDouble(*items[1], edit.value))
      throw InputError(where(file, keyword.line) + ": " + edit.keyword + " " + edit.name + ": '" + *items[1] +
                       "' is not a number");
    edit.box = boxOf(items, 2, file, keyword);
    const std::string skipped = applyPropertyEdit(edit, deck.dims, deck.properties);
    if (skipped.empty())
      ++deck.editsApplied;
    else
      deck.warnings.push_back(where(file, keyword.line) + ": " + skipped + " (skipped)");
  }

  void store(const std::string& name, std::vector<double> values, const std::filesystem::path& file, int line) {
    const bool cellProperty =
        name != "SPECGRID" && name != "DIMENS" && name != "COORD" && name != "ZCORN" && name != "MAPAXES";
    if (currentBox && cellProperty) {
      // Inside BOX ... ENDBOX an array holds the box's cells only.
      if (static_cast<long long>(values.size()) != currentBox->cellCount())
        throw InputError(where(file, line) + ": " + name + " has " + std::to_string(values.size()) +
                         " values for a BOX of " + std::to_string(currentBox->cellCount()) + " cells");
      // The BOX was checked against the grid of its time; a later SPECGRID/DIMENS may have shrunk it.
      for (int a = 0; a < 3; ++a)
        if (currentBox->lo[a] < 0 || currentBox->hi[a] >= deck.dims[a])
          throw InputError(where(file, line) + ": " + name + ": the open BOX reaches beyond the grid's " +
                           std::to_string(deck.dims[0]) + " x " + std::to_string(deck.dims[1]) + " x " +
                           std::to_string(deck.dims[2]) + " cells (the grid's dimensions changed after BOX)");
      std::vector<double>& whole = deck.properties[name];
      whole.resize(static_cast<std::size_t>(deck.dims[0]) * deck.dims[1] * deck.dims[2], 0.0);
      std::size_t next = 0;
      forEachCell(*currentBox, deck.dims, [&](std::size_t c) { whole[c] = values[next++]; });
      return;
    }
    if (name == "SPECGRID" || name == "DIMENS") {
      if (values.size() < 3)
        throw InputError(where(file, line) + ": " + name + " needs nx ny nz, found " + std::to_string(values.size()) +
                         " values");
      for (int a = 0; a < 3; ++a) {
        if (!(values[a] >= 1 && values[a] <= 1e6) || values[a] != std::floor(values[a]))
          throw InputError(where(file, line) + ": " + name + " dimension " + std::to_string(a + 1) +
                           " must be a positive integer");
        deck.dims[a] = static_cast<int>(values[a]);
      }
      // Every array of the grid is then allowed its size: ZCORN's 8 N values must fit.
      const double zcornValues = 8.0 * deck.dims[0] * deck.dims[1] * deck.dims[2];
      if (zcornValues > static_cast<double>(limits.maxValues))
        throw InputError(where(file, line) + ": " + name + " " + std::to_string(deck.dims[0]) + " x " +
                         std::to_string(deck.dims[1]) + " x " + std::to_string(deck.dims[2]) + ": its ZCORN (" +
                         std::to_string(static_cast<long long>(zcornValues)) + " values) would exceed --max-values " +
                         std::to_string(limits.maxValues) + " (raise it for a larger grid)");
    } else if (name == "COORD") {
      deck.coord = std::move(values);
    } else if (name == "ZCORN") {
      deck.zcorn = std::move(values);
    } else if (name == "ACTNUM") {
      deck.actnum = std::move(values);
    } else if (name == "MAPAXES") {
      deck.mapaxes = std::move(values);
    } else {
      deck.properties[name] = std::move(values);
    }
  }
};

}  // namespace

GrdeclDeck readGrdecl(const std::filesystem::path& path, const GrdeclLimits& limits) {
  return readGrdecl(std::vector<std::filesystem::path>{path}, limits);
}

GrdeclDeck readGrdecl(const std::vector<std::filesystem::path>& paths, const GrdeclLimits& limits) {
  if (paths.empty()) throw InputError("no GRDECL file given");
  if (limits.maxValues < 1)
    throw InputError("--max-values must be at least 1, got " + std::to_string(limits.maxValues));
  GrdeclDeck deck;
  deck.path = paths.front();
  for (const auto& path : paths) {
    Parser parser{deck, limits};
    parser.readFile(path);
  }
  return deck;
}

}  // namespace isovdb::reservoir
