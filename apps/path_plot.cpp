#include "path_plot.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

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
if d["path"]:
    xs = [p[0] for p in d["path"]]
    ys = [p[1] for p in d["path"]]
    ax.plot(xs, ys, "-o", color="#d62728", markersize=2.5, linewidth=1.2, label="path")
    ax.plot(xs[:1], ys[:1], "s", color="#2ca02c", markersize=7, label="start")
    ax.plot(xs[-1:], ys[-1:], "*", color="#000000", markersize=10, label="goal")
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
  d["path"] = nlohmann::json::array();
  for (const Waypoint& w : p.waypoints) d["path"].push_back({w.pose[0], w.pose[1]});
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
