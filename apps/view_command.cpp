#include "view_command.h"

#include <iostream>

#include "results/loaded_result.h"
#include "results/plot_data.h"
#include "results/usage_error.h"

namespace aspects {

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

int run_view(const ViewOptions& opts) {
  if (!opts.out.empty() && !ends_with(opts.out, ".html"))
    throw UsageError("--out: the view is an HTML page; give a name ending in .html, got " +
                     opts.out);
  LoadedResult r = load_result(opts.result_dir);
  const nlohmann::json figure = figure_json(opts.figure, r, FigureKind::View, false);
  const std::string out = opts.out.empty() ? opts.result_dir + "/aspects.html" : opts.out;
  write_result_figure(r, nullptr, figure, out);
  std::cout << "wrote " << out << '\n';
  return 0;
}

int run_export(const ViewOptions& opts) {
  // meshio picks the format from the extension: VTK's XML (.vtu) or legacy (.vtk) files.
  if (!ends_with(opts.out, ".vtu") && !ends_with(opts.out, ".vtk"))
    throw UsageError("--vtk: give a file name ending in .vtu (VTK XML) or .vtk (legacy VTK), "
                     "got '" + opts.out + "'");
  LoadedResult r = load_result(opts.result_dir);
  const nlohmann::json figure = figure_json(opts.figure, r, FigureKind::Vtk, false);
  write_result_figure(r, nullptr, figure, opts.out);
  std::cout << "wrote " << opts.out << '\n';
  return 0;
}

}  // namespace aspects
