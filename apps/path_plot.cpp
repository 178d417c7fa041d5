#include "path_plot.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/atomic_file.h"

extern char** environ;

namespace aspects {

namespace {

// Reads the data file, draws, saves under a temporary name and renames (never a
// half-written PNG).
const char* kScript = R"PY(
import json, os, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection
d = json.load(open(sys.argv[1]))
fig, ax = plt.subplots(figsize=(7, 7))
polys = [[(a, c), (b, c), (b, e), (a, e)] for a, b, c, e in d["boxes"]]
ax.add_collection(PolyCollection(polys, facecolors="#9ecae1", edgecolors="#4292c6",
                                 linewidths=0.2, label="CSNC %s boxes" % d["csnc"]))
for i, (x0, y0, x1, y1) in enumerate(d["segments"]):
    ax.plot([x0, x1], [y0, y1], "-o", color="#d62728", markersize=2.5, linewidth=1.2,
            label="path" if i == 0 else None)
if d["segments"]:
    ax.plot(d["segments"][0][:1], d["segments"][0][1:2], "s", color="#2ca02c", markersize=7,
            label="start")
    ax.plot(d["segments"][-1][2:3], d["segments"][-1][3:], "*", color="#000000",
            markersize=10, label="goal")
ax.autoscale_view()
ax.set_aspect("equal", adjustable="datalim")
ax.set_xlabel(d["names"][0])
ax.set_ylabel(d["names"][1])
ax.set_title(d["title"])
ax.legend(loc="best", fontsize=8)
tmp = sys.argv[2] + ".tmp.png"
fig.savefig(tmp, dpi=130)
os.replace(tmp, sys.argv[2])
)PY";

}  // namespace

void write_path_plot(const LoadedResult& r, const PathResult& p, const std::string& png) {
  const Model& m = r.model;
  if (m.pose.size() < 2) throw std::runtime_error("--plot needs at least two pose variables");
  const int vx = m.pose[0], vy = m.pose[1];
  nlohmann::json d;
  d["csnc"] = p.csnc;
  d["names"] = {m.vars[vx].name, m.vars[vy].name};
  d["title"] = m.name + ": CSNC " + std::to_string(p.csnc) + ", " +
               std::to_string(p.waypoints.size()) + " waypoints (" +
               path_outcome_name(p.outcome) + ")";
  d["boxes"] = nlohmann::json::array();
  for (const IndexSolutionBox& s : r.index.solutions)
    if (s.csnc == p.csnc) d["boxes"].push_back({s.lo[vx], s.hi[vx], s.lo[vy], s.hi[vy]});
  // Each segment drawn in its own box (a segment across the seam is drawn at the side of
  // the box it runs in), so every drawn segment is one the path takes.
  d["segments"] = nlohmann::json::array();
  for (size_t i = 0; i + 1 < p.waypoints.size(); ++i) {
    const Waypoint& a = p.waypoints[i];
    const Waypoint& b = p.waypoints[i + 1];
    auto in_box = [&](const Waypoint& w, int j) {
      return w.pose[j] + 2 * M_PI * double(w.turns[j] - a.turns[j] + a.box_turns[j]);
    };
    d["segments"].push_back({in_box(a, 0), in_box(a, 1), in_box(b, 0), in_box(b, 1)});
  }
  const std::string data = png + ".plot-data." + std::to_string(getpid()) + ".json";
  write_file_atomically(data, d.dump());
  const char* py = "/usr/bin/python3";
  std::vector<std::string> args = {py, "-c", kScript, data, png};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid;
  int rc = posix_spawn(&pid, py, nullptr, nullptr, argv.data(), environ);
  int status = 0;
  if (rc == 0) waitpid(pid, &status, 0);
  std::remove(data.c_str());
  if (rc != 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("--plot: " + std::string(py) +
                             " with matplotlib could not write " + png);
}

}  // namespace aspects
