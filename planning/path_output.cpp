#include "path_output.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "io/atomic_file.h"

namespace aspects {

PathFileFormat path_file_format(const std::string& file) {
  const size_t dot = file.find_last_of('.');
  const size_t slash = file.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return PathFileFormat::Unknown;
  std::string ext = file.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == "csv" ? PathFileFormat::Csv : ext == "json" ? PathFileFormat::Json
                                                            : PathFileFormat::Unknown;
}

namespace {

std::string number(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string csv(const Model& m, const PathResult& p) {
  std::string s = "kind";
  for (int v : m.pose) s += "," + m.vars[v].name;
  for (int v : m.command) s += "," + m.vars[v].name + "_lo," + m.vars[v].name + "_hi";
  s += ",box\n";
  for (const Waypoint& w : p.waypoints) {
    s += waypoint_kind_name(w.kind);
    for (size_t j = 0; j < w.pose.size(); ++j)
      s += "," + number(w.pose[j] + 2 * M_PI * double(j < w.turns.size() ? w.turns[j] : 0));
    for (size_t j = 0; j < w.command.lo.size(); ++j)
      s += "," + number(w.command.lo[j]) + "," + number(w.command.hi[j]);
    s += "," + std::to_string(w.box) + "\n";
  }
  return s;
}

}  // namespace

void write_path_file(const std::string& file, const Model& m, const std::vector<double>& from,
                     const std::vector<double>& to, const PathResult& p) {
  const PathFileFormat f = path_file_format(file);
  if (f == PathFileFormat::Unknown)
    throw std::runtime_error("cannot write " + file + ": the name must end in .csv or .json");
  AtomicFile out(file);
  out.write(f == PathFileFormat::Csv ? csv(m, p) : path_json(from, to, p).dump() + "\n");
  out.commit();
}

}  // namespace aspects
