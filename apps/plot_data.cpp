#include "plot_data.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"
#include "le_writer.h"

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

// DATA.bin, little-endian: lower ends (boxes × pose variables, f64), upper ends, CSNC
// (i32, -1 for undecided), status (i8: 0 solution, 1 + the undecided kind), by box id.
std::string box_bytes(const LoadedResult& r, size_t& boxes) {
  const size_t k = r.model.pose.size();
  struct Row { bool sol; size_t i; };
  std::vector<Row> rows;
  rows.reserve(r.index.solutions.size() + r.index.undecided.size());
  for_each_box_by_id(r.index, [&](bool sol, size_t i) { rows.push_back({sol, i}); });
  boxes = rows.size();
  StringWriter w;
  auto ends = [&](bool upper) {
    for (const Row& row : rows)
      for (size_t j = 0; j < k; ++j) {
        if (row.sol) {
          const IndexSolutionBox& s = r.index.solutions[row.i];
          w.f64(upper ? s.hi[r.model.pose[j]] : s.lo[r.model.pose[j]]);
        } else {
          const IndexUndecidedBox& u = r.index.undecided[row.i];
          w.f64(upper ? u.hi[j] : u.lo[j]);
        }
      }
  };
  ends(false);
  ends(true);
  for (const Row& row : rows) w.u32(uint32_t(row.sol ? r.index.solutions[row.i].csnc : -1));
  for (const Row& row : rows) w.u8(row.sol ? 0 : uint8_t(1 + r.index.undecided[row.i].kind));
  return std::move(w.out);
}

void run_python(const std::vector<std::string>& args_in) {
  std::vector<std::string> args = args_in;
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid;
  int rc = posix_spawn(&pid, args[0].c_str(), nullptr, nullptr, argv.data(), environ);
  int status = 0;
  if (rc == 0) waitpid(pid, &status, 0);
  if (rc != 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(args[0] + " with matplotlib could not write " + args.back());
}

}  // namespace

void write_result_plot(const LoadedResult& r, const nlohmann::json& path, const std::string& png) {
  const std::string script = find_plotting_script();
  if (script.empty())
    throw std::runtime_error("plotting.py not found next to this program (build/python/aspects/ "
                             "or lib/python3/dist-packages/aspects/)");
  const Model& m = r.model;
  size_t boxes = 0;
  const std::string stem = png + ".plot-data." + std::to_string(getpid());
  write_file_atomically(stem + ".bin", box_bytes(r, boxes));
  nlohmann::json d;
  d["robot"] = m.name;
  d["eps"] = r.index.eps;
  d["names"] = nlohmann::json::array();
  for (int v : m.pose) d["names"].push_back(m.vars[v].name);
  d["periodic"] = r.pose_periodic;
  d["boxes"] = boxes;
  d["filtered"] = r.index.filtered;
  d["csnc_count"] = r.index.csnc_count;
  d["binary"] = fs::path(stem + ".bin").filename().string();
  d["path"] = path;
  write_file_atomically(stem + ".json", d.dump());
  try {
    run_python({"/usr/bin/python3", script, stem + ".json", png});
  } catch (...) {
    std::remove((stem + ".json").c_str());
    std::remove((stem + ".bin").c_str());
    throw;
  }
  std::remove((stem + ".json").c_str());
  std::remove((stem + ".bin").c_str());
}

}  // namespace aspects
