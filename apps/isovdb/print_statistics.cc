// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include <cstdio>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "commands.h"

namespace isovdb::cli {

namespace {

using Json = pipeline::Statistics::Json;

void printValue(const std::string& key, const Json& value) {
  if (value.is_object()) {
    for (const auto& [name, child] : value.items()) printValue(key.empty() ? name : key + "." + name, child);
    return;
  }
  if (value.is_array() && !value.empty() && value.front().is_object()) {
    for (std::size_t i = 0; i < value.size(); ++i) printValue(key + "[" + std::to_string(i) + "]", value[i]);
    return;
  }
  std::printf("%s: %s\n", key.c_str(), value.is_string() ? value.get<std::string>().c_str() : value.dump().c_str());
}

/// A count with thousands separators (1,234,567).
std::string count(const Json& value) {
  std::string digits = std::to_string(value.get<std::int64_t>());
  const std::size_t first = digits[0] == '-' ? 1 : 0;
  for (std::size_t i = digits.size(); i > first + 3; i -= 3) digits.insert(i - 3, ",");
  return digits;
}

std::string text(const Json& value) { return value.is_string() ? value.get<std::string>() : value.dump(); }

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, s < 10 ? "%.2f s" : "%.1f s", s);
  return buf;
}

/// The parts of `section` present among `keys`, each by `format`, joined by ", ".
class Line {
 public:
  explicit Line(std::string label) : label_(std::move(label)) {}
  Line& add(const std::string& part) {
    if (!part.empty()) parts_.push_back(part);
    return *this;
  }
  void print() const {
    if (parts_.empty()) return;
    std::string joined;
    for (const std::string& p : parts_) joined += (joined.empty() ? "" : ", ") + p;
    std::printf("%s: %s\n", label_.c_str(), joined.c_str());
  }

 private:
  std::string label_;
  std::vector<std::string> parts_;
};

/// `value` of `key` in `section` through `format`, or "" where the key is absent.
template <class Format>
std::string part(const Json& section, const char* key, Format&& format) {
  return section.is_object() && section.contains(key) && !section[key].is_null() ? format(section[key]) : "";
}

void printInput(const Json& input) {
  Line line("input");
  line.add(part(input, "path", text));
  line.add(part(input, "format", text)).add(part(input, "kind", text));
  line.add(part(input, "dims", [](const Json& d) {
    std::string s;
    for (const auto& v : d) s += (s.empty() ? "" : "x") + text(v);
    return s;
  }));
  line.add(part(input, "active_voxels", [](const Json& v) { return count(v) + " active voxels"; }));
  line.print();
}

void printMeshCheck(const char* label, const Json& check) {
  Line line(label);
  line.add(part(check, "closed", [](const Json& v) { return std::string(v.get<bool>() ? "closed" : "NOT closed"); }));
  line.add(
      part(check, "manifold", [](const Json& v) { return std::string(v.get<bool>() ? "manifold" : "NOT manifold"); }));
  line.add(part(check, "self_intersecting_pairs", [](const Json& v) {
    return v.get<std::int64_t>() < 0 ? std::string() : count(v) + " self-intersecting pairs";
  }));
  line.add(part(check, "euler_characteristic", [](const Json& v) { return "Euler characteristic " + text(v); }));
  line.add(part(check, "components", [](const Json& v) { return count(v) + " components"; }));
  line.print();
}

/// At most ~15 lines: what was read, what was built, what the check found, time, memory, output.
void printSummary(const Json& json) {
  if (json.contains("input")) printInput(json["input"]);
  const Json none = Json::object();
  const auto section = [&](const char* name) -> const Json& { return json.contains(name) ? json[name] : none; };
  Line("distance field")
      .add(part(section("distance_field"), "active_voxels", [](const Json& v) { return count(v) + " band voxels"; }))
      .add(part(section("distance_field"), "method", text))
      .print();
  Line("volume")
      .add(part(section("volume"), "active_voxels", [](const Json& v) { return count(v) + " active voxels"; }))
      .print();
  Line("morph")
      .add(part(section("morph"), "planes", [](const Json& v) { return count(v) + " planes"; }))
      .add(part(section("morph"), "original_slices", [](const Json& v) { return count(v) + " original slices"; }))
      .add(part(section("morph"), "interpolation", text))
      .print();
  const Json& reservoir = section("reservoir");
  Line("reservoir")
      .add(part(reservoir, "active_cells", [](const Json& v) { return count(v) + " active cells"; }))
      .add(part(reservoir, "property", text))
      .add(part(reservoir, "cut_cells", [](const Json& v) { return count(v) + " cut cells"; }))
      .add(part(reservoir, "mc_triangles", [](const Json& v) { return count(v) + " triangles"; }))
      .add(part(reservoir, "pn_triangles", [](const Json& v) { return count(v) + " after PN tessellation"; }))
      .add(part(reservoir, "warnings",
                [](const Json& v) { return v.empty() ? std::string() : count(Json(v.size())) + " warnings"; }))
      .print();
  Line("self-intersecting pairs")
      .add(part(reservoir, "self_intersecting_pairs",
                [](const Json& v) {
                  return count(v["total"]) + " (" + count(v["at_inverted_cells"]) + " at inverted cells, " +
                         count(v["at_pinched_cells"]) + " at pinched cells, " + count(v["elsewhere"]) + " elsewhere)";
                }))
      .print();
  Line("octree")
      .add(part(section("octree"), "leaves", [](const Json& v) { return count(v) + " leaves"; }))
      .add(
          part(section("octree"), "surface_leaves", [](const Json& v) { return count(v) + " crossed by the surface"; }))
      .print();
  const Json& metaCells = section("meta_cells");
  Line("meta-cells")
      .add(part(metaCells, "contoured", [](const Json& v) { return count(v) + " contoured"; }))
      .add(part(metaCells, "meta_cell_size", [](const Json& v) { return "size " + text(v); }))
      .add(part(metaCells, "threads", [](const Json& v) { return text(v) + " threads"; }))
      .print();
  const Json& contour = section("contour");
  Line("mesh")
      .add(part(contour, "triangles", [](const Json& v) { return count(v) + " triangles"; }))
      .add(part(contour, "vertices", [](const Json& v) { return count(v) + " vertices"; }))
      .add(part(contour, "method", [](const Json& v) { return "method " + text(v); }))
      .add(part(contour, "max_error",
                [&contour](const Json& v) {
                  const int finest = contour.value("finest_cell_voxels", 1);
                  return finest == 1 ? "within " + text(v) + " voxel (--max-error)"
                                     : "--max-error " + text(v) + " asked, but cells stop at " +
                                           std::to_string(finest) + " voxels: not guaranteed";
                }))
      .print();
  if (json.contains("mesh")) printMeshCheck("mesh", json["mesh"]);
  if (json.contains("check")) printMeshCheck("check", json["check"]);
  const Json& topology = section("topology");
  Line("topology")
      .add(part(topology, "solid_euler_characteristic",
                [](const Json& v) { return "the object's Euler characteristic " + text(v); }))
      .add(part(topology, "matches",
                [](const Json& v) {
                  return std::string(v.get<bool>() ? "the mesh matches it" : "the mesh does NOT match it");
                }))
      .print();
  if (json.contains("passed")) std::printf("passed: %s\n", json["passed"].get<bool>() ? "yes" : "NO");
  if (json.contains("timings_s")) {
    Line line("time");
    double total = 0;
    for (const auto& [stage, s] : json["timings_s"].items()) {
      if (!s.is_number()) continue;
      std::string name = stage;
      for (char& c : name) c = c == '_' ? ' ' : c;
      line.add(name + " " + seconds(s.get<double>()));
      total += s.get<double>();
    }
    line.add("total " + seconds(total));
    line.print();
  }
  Line("peak memory")
      .add(part(section("memory"), "peak_rss_bytes",
                [](const Json& v) { return count(Json(v.get<std::int64_t>() >> 20)) + " MB"; }))
      .print();
  Line("output").add(part(section("output"), "path", text)).print();
  Line("preview").add(part(section("preview"), "path", text)).print();
  std::printf("(every figure: --verbose, or --stats FILE.json)\n");
}

}  // namespace

void printStatistics(const pipeline::Statistics& stats, bool everyFigure) {
  if (everyFigure)
    printValue("", stats.json());
  else
    printSummary(stats.json());
}

void reportStatistics(pipeline::Statistics& stats, const std::string& statsPath, const Context& context,
                      bool everyFigure) {
  stats.recordMemory();
  if (!statsPath.empty()) stats.write(statsPath);
  printStatistics(stats, everyFigure || context.verbose);
}

}  // namespace isovdb::cli
