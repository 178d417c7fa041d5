#include "plot_command.h"

#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "results/loaded_result.h"
#include "results/plot_data.h"
#include "results/usage_error.h"

namespace aspects {

namespace {

// The --path file, checked enough that the plotting script cannot misread it: waypoints
// with one number per pose variable, a CSNC of the result.
nlohmann::json read_path(const std::string& file, const LoadedResult& r) {
  std::ifstream in(file);
  if (!in) throw UsageError("--path: cannot read " + file);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception&) {
    throw UsageError("--path: " + file + " is not JSON (give what `aspects path --json` prints)");
  }
  const std::string usage = "--path: " + file + " is not the output of `aspects path --json`";
  if (!j.is_object() || !j.contains("waypoints") || !j["waypoints"].is_array())
    throw UsageError(usage + " (no waypoints)");
  if (j["waypoints"].empty()) throw UsageError("--path: " + file + " holds no path (no waypoints)");
  if (!j.contains("csnc") || !j["csnc"].is_number_integer() || j["csnc"].get<long>() < 0 ||
      j["csnc"].get<long>() >= long(r.index.csnc_count))
    throw UsageError(usage + " of this result (its CSNC is not one of the " +
                     std::to_string(r.index.csnc_count) + ")");
  for (const auto& w : j["waypoints"]) {
    if (!w.is_object() || !w.contains("pose") || !w["pose"].is_array() ||
        w["pose"].size() != r.model.pose.size())
      throw UsageError(usage + " of this result (a waypoint without " +
                       std::to_string(r.model.pose.size()) + " pose coordinates)");
    for (const auto& x : w["pose"])
      if (!x.is_number()) throw UsageError(usage + " (a pose coordinate is not a number)");
    if (w.contains("turns") && (!w["turns"].is_array() || w["turns"].size() != w["pose"].size()))
      throw UsageError(usage + " (bad turns)");
  }
  return j;
}

}  // namespace

int run_plot(const PlotOptions& opts) {
  LoadedResult r = load_result(opts.result_dir);
  nlohmann::json path = opts.path.empty() ? nlohmann::json(nullptr) : read_path(opts.path, r);
  const nlohmann::json figure = figure_json(opts.figure, r, FigureKind::Plot, !path.is_null());
  const std::string out = opts.out.empty() ? opts.result_dir + "/aspects.png" : opts.out;
  write_result_figure(r, path, figure, out);
  std::cout << "wrote " << out << '\n';
  return 0;
}

}  // namespace aspects
