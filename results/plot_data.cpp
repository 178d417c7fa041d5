#include "results/plot_data.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"
#include "io/le_writer.h"

extern char** environ;

namespace aspects {

namespace fs = std::filesystem;

std::string find_plotting_script() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  const fs::path dir = exe.parent_path();
  for (const fs::path& p : {dir / "../python/aspects/plotting.py",
                            dir / "../lib/python3/dist-packages/aspects/plotting.py"})
    if (fs::exists(p, ec)) return fs::weakly_canonical(p, ec).string();
  return "";
}

namespace {

struct StringWriter : LeWriter {
  std::string out;
  void bytes(const void* p, size_t n) override { out.append(static_cast<const char*>(p), n); }
};

// The variables a figure needs, in model order: the pose's (a path is drawn in it) and
// the axes' (figure["axes"], names already checked). Only these are written: on 3-RPR at
// eps 0.3 (9.3 M boxes) each variable costs 150 MB.
std::vector<int> figure_variables(const Model& m, const nlohmann::json& figure) {
  std::vector<bool> used(m.vars.size(), false);
  for (int v : m.pose) used[v] = true;
  const nlohmann::json axes = figure.value("axes", nlohmann::json(nullptr));
  if (axes.is_array())
    for (const auto& name : axes)
      for (size_t v = 0; v < m.vars.size(); ++v)
        if (m.vars[v].name == name.get<std::string>()) used[v] = true;
  std::vector<int> vars;
  for (size_t v = 0; v < used.size(); ++v)
    if (used[v]) vars.push_back(int(v));
  return vars;
}

// DATA.bin, little-endian: lower ends (boxes × `vars`, f64), upper ends, CSNC (i32, -1
// for undecided), status (i8: 0 solution, 1 + the undecided kind), by box id. An
// undecided box's command part is NaN: the index keeps its pose part only.
std::string box_bytes(const LoadedResult& r, const std::vector<int>& vars, size_t& boxes) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Row { bool sol; size_t i; };
  std::vector<Row> rows;
  rows.reserve(r.index.solutions.size() + r.index.undecided.size());
  for_each_box_by_id(r.index, [&](bool sol, size_t i) { rows.push_back({sol, i}); });
  boxes = rows.size();
  std::vector<int> pose_slot(r.model.vars.size(), -1);  // variable -> its place in pose order
  for (size_t j = 0; j < r.model.pose.size(); ++j) pose_slot[r.model.pose[j]] = int(j);
  StringWriter w;
  auto ends = [&](bool upper) {
    for (const Row& row : rows)
      for (int v : vars) {
        if (row.sol) {
          const IndexSolutionBox& s = r.index.solutions[row.i];
          w.f64(upper ? s.hi[v] : s.lo[v]);
        } else {
          const IndexUndecidedBox& u = r.index.undecided[row.i];
          const int j = pose_slot[v];
          w.f64(j < 0 ? nan : upper ? u.hi[j] : u.lo[j]);
        }
      }
  };
  ends(false);
  ends(true);
  for (const Row& row : rows) w.u32(uint32_t(row.sol ? r.index.solutions[row.i].csnc : -1));
  for (const Row& row : rows) w.u8(row.sol ? 0 : uint8_t(1 + r.index.undecided[row.i].kind));
  return std::move(w.out);
}

void run_python(const std::vector<std::string>& args_in, const std::string& libraries) {
  std::vector<std::string> args = args_in;
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid;
  int rc = posix_spawn(&pid, args[0].c_str(), nullptr, nullptr, argv.data(), environ);
  int status = 0;
  if (rc == 0) waitpid(pid, &status, 0);
  if (rc != 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(args[0] + " with " + libraries + " could not write " + args.back());
}

}  // namespace

nlohmann::json certified_count_json(const LoadedResult& r) {
  nlohmann::json out = nlohmann::json::object();
  if (r.directory.empty()) return out;
  std::ifstream in(r.directory + "/summary.json");
  if (!in) return out;
  try {
    // load_result checked that this summary is of the run that wrote the index.
    const nlohmann::json s = nlohmann::json::parse(in);
    const nlohmann::json& c = s.at("csncs");
    out["lower_bound"] = c.at("separated_lower_bound").get<long>();
    out["representatives"] = c.at("separated_representatives");
  } catch (const nlohmann::json::exception&) {
    return nlohmann::json::object();  // no count stated rather than a wrong one
  }
  return out;
}

void write_result_figure(const LoadedResult& r, const nlohmann::json& path,
                         const nlohmann::json& figure, const std::string& out) {
  const std::string script = find_plotting_script();
  if (script.empty())
    throw std::runtime_error("plotting.py not found next to this program (build/python/aspects/ "
                             "or lib/python3/dist-packages/aspects/)");
  const Model& m = r.model;
  size_t boxes = 0;
  const std::string stem = out + ".plot-data." + std::to_string(getpid());
  const std::vector<int> vars = figure_variables(m, figure);
  write_file_atomically(stem + ".bin", box_bytes(r, vars, boxes));
  nlohmann::json d;
  d["robot"] = m.name;
  d["eps"] = r.index.eps;
  d["names"] = nlohmann::json::array();
  d["periodic"] = nlohmann::json::array();
  d["pose"] = nlohmann::json::array();  // places in "names"
  for (size_t c = 0; c < vars.size(); ++c) {
    d["names"].push_back(m.vars[vars[c]].name);
    d["periodic"].push_back(m.vars[vars[c]].periodic);
    if (std::find(m.pose.begin(), m.pose.end(), vars[c]) != m.pose.end()) d["pose"].push_back(c);
  }
  d["boxes"] = boxes;
  d["filtered"] = r.index.filtered;
  d["csnc_count"] = r.index.csnc_count;
  const nlohmann::json count = certified_count_json(r);
  d["lower_bound"] = count.value("lower_bound", nlohmann::json(nullptr));
  d["representatives"] = count.value("representatives", nlohmann::json::array());
  d["binary"] = fs::path(stem + ".bin").filename().string();
  d["path"] = path;
  d["figure"] = figure;
  write_file_atomically(stem + ".json", d.dump());
  const std::string kind = figure.value("kind", "plot");
  const std::string libraries = kind == "view"   ? "plotly and scikit-image"
                                : kind == "vtk" ? "meshio and scikit-image"
                                                 : "matplotlib";
  try {
    run_python({"/usr/bin/python3", script, stem + ".json", out}, libraries);
  } catch (...) {
    std::remove((stem + ".json").c_str());
    std::remove((stem + ".bin").c_str());
    throw;
  }
  std::remove((stem + ".json").c_str());
  std::remove((stem + ".bin").c_str());
}

void write_result_plot(const LoadedResult& r, const nlohmann::json& path, const std::string& png) {
  write_result_figure(r, path, {{"kind", "plot"}}, png);
}

}  // namespace aspects
