// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/reservoir/grdecl_reader.h"

#include <cctype>
#include <charconv>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "isovdb/errors.h"
#include "isovdb/reservoir/grdecl_tokens.h"

namespace isovdb::reservoir {
namespace {

// Keywords that carry no record.
const std::set<std::string> kFlagKeywords = {
    "RUNSPEC", "GRID",    "EDIT",    "NOECHO", "ECHO",    "OIL",    "WATER",        "GAS",    "DISGAS",
    "VAPOIL",  "FIELD",   "METRIC",  "LAB",    "UNIFOUT", "UNIFIN", "FMTOUT",       "FMTIN",  "INIT",
    "NOSIM",   "NEWTRAN", "OLDTRAN", "ENDBOX", "NONNC",   "NOGGF",  "GRIDFILE_OFF", "MULTOUT"};
// Sections after the grid: nothing there describes the grid, stop reading.
const std::set<std::string> kStopKeywords = {"PROPS", "REGIONS", "SOLUTION", "SUMMARY", "SCHEDULE", "END"};
// Keywords with one non-numeric (or defaulted) record that need no warning.
const std::set<std::string> kKnownTextKeywords = {"MAPUNITS", "GRIDUNIT", "GDORIENT", "START",  "WELLDIMS",
                                                  "TABDIMS",  "EQLDIMS",  "REGDIMS",  "NSTACK", "COORDSYS"};
// Keywords made of records ended by an empty record.
const std::set<std::string> kMultiRecordKeywords = {"COPY", "MULTIPLY", "ADD", "EQUALS", "MINVALUE", "MAXVALUE"};

bool looksLikeKeyword(const GrdeclToken& t) {
  if (t.quoted || t.text.empty() || t.text.size() > 8) return false;
  if (!std::isupper(static_cast<unsigned char>(t.text[0]))) return false;
  for (char c : t.text)
    if (!(std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_'))
      return false;
  return true;
}

bool parseDouble(const std::string& s, double& out) {
  const char* begin = s.data();
  const char* end = s.data() + s.size();
  // Fortran exponents (1.0D+03).
  std::string fixed;
  if (s.find_first_of("dD") != std::string::npos) {
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

struct Parser {
  GrdeclDeck& deck;
  int depth = 0;
  bool stopped = false;

  std::string where(const std::filesystem::path& file, int line) const {
    return file.string() + ":" + std::to_string(line);
  }

  // Index of the `/` that ends the record starting at `i`; throws when none.
  std::size_t recordEnd(const std::vector<GrdeclToken>& t, std::size_t i, const std::filesystem::path& file,
                        const GrdeclToken& keyword) const {
    for (std::size_t k = i; k < t.size(); ++k)
      if (t[k].isSlash()) return k;
    throw InputError(where(file, keyword.line) + ": keyword " + keyword.text +
                     " has no terminating '/' before the end of the file");
  }

  // Numeric values of the record from `i`; `/` index in `end`. Throws on a non-number.
  std::vector<double> numbers(const std::vector<GrdeclToken>& t, std::size_t i, std::size_t& end,
                              const std::filesystem::path& file, const GrdeclToken& keyword,
                              std::size_t limit = static_cast<std::size_t>(-1)) const {
    std::vector<double> values;
    for (end = i; end < t.size() && end < limit && !t[end].isSlash(); ++end) {
      const std::string& s = t[end].text;
      const std::size_t star = s.find('*');
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
          throw InputError(where(file, keyword.line) + ": keyword " + keyword.text +
                           " has no terminating '/' (keyword " + s + " found at line " + std::to_string(t[end].line) +
                           ")");
        throw InputError(where(file, t[end].line) + ": keyword " + keyword.text + ": '" + s +
                         "' is not a number (expected a value or n*value)");
      }
      if (repeat > 100000000) throw InputError(where(file, t[end].line) + ": repeat count too large: " + s);
      values.insert(values.end(), static_cast<std::size_t>(repeat), value);
    }
    if (end == t.size() && end < limit)
      throw InputError(where(file, keyword.line) + ": keyword " + keyword.text +
                       " has no terminating '/' before the end of the file");
    return values;
  }

  bool recordIsNumeric(const std::vector<GrdeclToken>& t, std::size_t i) const {
    if (i >= t.size() || t[i].isSlash()) return true;  // empty record
    double v;
    const std::string& s = t[i].text;
    const std::size_t star = s.find('*');
    return !t[i].quoted &&
           (star == std::string::npos ? parseDouble(s, v) : star + 1 < s.size() && parseDouble(s.substr(star + 1), v));
  }

  void readFile(const std::filesystem::path& file) {
    if (depth > 16) throw InputError(file.string() + ": INCLUDE nested more than 16 deep");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw IoError(file.string() + ": cannot open GRDECL file");
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::vector<GrdeclToken> t = tokenizeGrdecl(buffer.str());

    std::size_t i = 0;
    while (i < t.size() && !stopped) {
      const GrdeclToken& keyword = t[i];
      if (keyword.isSlash()) {  // a stray terminator (e.g. after a defaulted record)
        ++i;
        continue;
      }
      if (!looksLikeKeyword(keyword))
        throw InputError(where(file, keyword.line) + ": expected a keyword, found '" + keyword.text + "'");
      const std::string& name = keyword.text;
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
      if (kMultiRecordKeywords.count(name)) {
        deck.warnings.push_back(where(file, keyword.line) + ": keyword " + name + " is not applied (skipped)");
        while (i < t.size() && !t[i].isSlash()) i = recordEnd(t, i, file, keyword) + 1;
        i = recordEnd(t, i, file, keyword) + 1;
        continue;
      }
      if (kKnownTextKeywords.count(name) || !recordIsNumeric(t, i)) {
        if (!kKnownTextKeywords.count(name))
          deck.warnings.push_back(where(file, keyword.line) + ": unknown keyword " + name + " skipped");
        i = recordEnd(t, i, file, keyword) + 1;
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

  void store(const std::string& name, std::vector<double> values, const std::filesystem::path& file, int line) {
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

GrdeclDeck readGrdecl(const std::filesystem::path& path) {
  GrdeclDeck deck;
  deck.path = path;
  Parser parser{deck};
  parser.readFile(path);
  return deck;
}

GrdeclDeck readGrdecl(const std::vector<std::filesystem::path>& paths) {
  if (paths.empty()) throw InputError("no GRDECL file given");
  GrdeclDeck deck;
  deck.path = paths.front();
  for (const auto& path : paths) {
    Parser parser{deck};
    parser.readFile(path);
  }
  return deck;
}

}  // namespace isovdb::reservoir
