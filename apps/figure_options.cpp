#include "figure_options.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <vector>

#include "results/number_text.h"
#include "results/usage_error.h"

namespace aspects {

namespace {

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, ',')) parts.push_back(part);
  if (!text.empty() && text.back() == ',') parts.push_back("");
  return parts;
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

std::vector<std::string> pose_names(const Model& m) {
  std::vector<std::string> names;
  for (int v : m.pose) names.push_back(m.vars[v].name);
  return names;
}

nlohmann::json axes_json(const std::string& text, const LoadedResult& r, FigureKind kind,
                         bool has_path) {
  const Model& m = r.model;
  const std::string command = kind == FigureKind::Plot ? "plot" : kind == FigureKind::View
                                                                      ? "view" : "export";
  std::vector<std::string> all;
  for (const auto& v : m.vars) all.push_back(v.name);
  if (text.empty()) {
    const size_t n = m.pose.size();
    if (kind != FigureKind::Plot && n != 3)
      throw UsageError("--axes: `aspects " + command + "` draws 3 variables and " + m.name +
                       " has " + std::to_string(n) + " pose variable" + (n == 1 ? "" : "s") +
                       " (" + joined(pose_names(m)) + "): give three of " + joined(all) +
                       " with --axes");
    return nullptr;
  }
  const std::vector<std::string> names = split_commas(text);
  const bool plot = kind == FigureKind::Plot;
  if (plot ? names.size() != 2 && names.size() != 3 : names.size() != 3)
    throw UsageError(std::string("--axes: give ") + (plot ? "2 or 3" : "3") +
                     " variable names separated by commas, got '" + text + "'");
  std::set<std::string> seen;
  nlohmann::json out = nlohmann::json::array();
  for (const std::string& n : names) {
    const auto it = std::find(all.begin(), all.end(), n);
    if (it == all.end())
      throw UsageError("--axes: '" + n + "' is not a variable of " + m.name + " (its variables: " +
                       joined(all) + ")");
    if (!seen.insert(n).second) throw UsageError("--axes: '" + n + "' is given twice");
    if (has_path) {
      const auto pose = pose_names(m);
      if (std::find(pose.begin(), pose.end(), n) == pose.end())
        throw UsageError("--axes: '" + n + "' is not a pose variable, and --path is drawn in "
                         "pose coordinates (" + joined(pose) + ")");
    }
    out.push_back(n);
  }
  return out;
}

nlohmann::json csncs_json(const std::string& text, const LoadedResult& r) {
  const long count = long(r.index.csnc_count);
  nlohmann::json out = nlohmann::json::array();
  std::set<long> seen;
  for (const std::string& part : split_commas(text)) {
    size_t used = 0;
    long k = -1;
    try {
      k = std::stol(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != part.size())
      throw UsageError("--csnc: give CSNC numbers separated by commas, got '" + text + "'");
    if (k < 0 || k >= count)
      throw UsageError("--csnc: CSNCs are numbered from 0 to " + std::to_string(count - 1) +
                       " (the result has " + std::to_string(count) + "), got " + part);
    if (!seen.insert(k).second) throw UsageError("--csnc: CSNC " + part + " is given twice");
    out.push_back(k);
  }
  return out;
}

// An integer option's text in [lo, hi]; empty text: null (not given).
nlohmann::json integer_json(const std::string& option, const std::string& text, long lo, long hi,
                            const std::string& what) {
  if (text.empty()) return nullptr;
  size_t used = 0;
  long v = 0;
  try {
    v = std::stol(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || v < lo || v > hi)
    throw UsageError(option + ": " + what + ", an integer from " + std::to_string(lo) + " to " +
                     std::to_string(hi) + ", got '" + text + "'");
  return v;
}

// "WxH" in inches, each in (0, kMaxInches].
nlohmann::json size_json(const std::string& text) {
  const size_t x = text.find_first_of("xX");
  const std::string usage = "--size: give WIDTHxHEIGHT in inches (e.g. 8x6), each above 0 "
                            "and at most " + std::to_string(int(kMaxInches)) + ", got '" +
                            text + "'";
  if (x == std::string::npos) throw UsageError(usage);
  double w = 0, h = 0;
  if (parse_number(text.substr(0, x), w) != NumberText::Finite ||
      parse_number(text.substr(x + 1), h) != NumberText::Finite || !(w > 0) || !(h > 0) ||
      w > kMaxInches || h > kMaxInches)
    throw UsageError(usage);
  return {w, h};
}

}  // namespace

nlohmann::json figure_json(const FigureOptions& o, const LoadedResult& r, FigureKind kind,
                           bool has_path) {
  nlohmann::json f;
  f["kind"] = kind == FigureKind::Plot ? "plot" : kind == FigureKind::View ? "view" : "vtk";
  f["axes"] = axes_json(o.axes, r, kind, has_path);
  f["csncs"] = o.csncs.empty() ? nlohmann::json(nullptr) : csncs_json(o.csncs, r);
  f["largest"] = integer_json("--largest", o.largest, 1, 1000000, "a number of CSNCs");
  if (!o.csncs.empty() && !o.largest.empty())
    throw UsageError("--csnc and --largest: give one of them");
  f["dpi"] = integer_json("--dpi", o.dpi, kMinDpi, kMaxDpi, "dots per inch");
  f["size"] = o.size.empty() ? nlohmann::json(nullptr) : size_json(o.size);
  f["voxels"] = o.voxels;
  const nlohmann::json cells = integer_json("--grid", o.grid, kMinGrid, kMaxGrid, "cells per axis");
  f["cells"] = cells.is_null() ? nlohmann::json(kDefaultViewGrid) : cells;
  return f;
}

}  // namespace aspects
