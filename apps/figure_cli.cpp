#include "figure_cli.h"

namespace aspects {

namespace {

void add_choice_options(CLI::App* cmd, FigureOptions& fo, const std::string& default_choice) {
  auto* csnc = cmd->add_option("--csnc", fo.csncs,
                               "draw these CSNCs, e.g. 0,3,5 (default: " + default_choice + ")")
                   ->type_name("LIST");
  auto* largest = cmd->add_option("--largest", fo.largest,
                                  "draw the N largest CSNCs (the separated ones among them first)")
                      ->type_name("N");
  csnc->excludes(largest);
}

void add_plot(CLI::App& app, FigureCommands& f) {
  PlotOptions& po = f.plot_options;
  auto* plot = f.plot = app.add_subcommand(
      "plot", "Draw a result: the certified count, then its CSNCs on two variables (panels) "
              "or three (3-D)");
  plot->add_option("RESULT_DIR", po.result_dir, "directory written by `aspects solve --out`")
      ->required();
  plot->add_option("-o,--out", po.out,
                   "file to write: PNG, PDF or SVG, from its extension (default: "
                   "RESULT_DIR/aspects.png)");
  plot->add_option("--path", po.path, "draw the path of this file (`aspects path --json` output)");
  plot->add_option("--axes", po.figure.axes,
                   "two or three variables, pose or command, e.g. q1,q2 (default: the pose's)")
      ->type_name("VARS");
  add_choice_options(plot, po.figure,
                     "the separated CSNCs, then the largest the filter keeps, 25 in all");
  plot->add_option("--dpi", po.figure.dpi, "dots per inch of a PNG (10 to 2400; default 110)")
      ->type_name("N");
  plot->add_option("--size", po.figure.size, "figure size WIDTHxHEIGHT in inches, e.g. 8x6")
      ->type_name("WxH");
}

void add_view(CLI::App& app, FigureCommands& f) {
  ViewOptions& vo = f.view_options;
  auto* view = f.view = app.add_subcommand(
      "view", "Write one HTML page that turns in a browser: the CSNCs of three variables as "
              "surfaces or voxels (plotly)");
  view->add_option("RESULT_DIR", vo.result_dir, "directory written by `aspects solve --out`")
      ->required();
  view->add_option("-o,--out", vo.out, "HTML file to write (default: RESULT_DIR/aspects.html)");
  view->add_option("--axes", vo.figure.axes,
                   "three variables, pose or command, e.g. x1,x2,q1 (default: the pose's, "
                   "when it has three)")
      ->type_name("VARS");
  add_choice_options(view, vo.figure,
                     "the separated CSNCs, then the largest the filter keeps, 6 in all");
  view->add_flag("--voxels", vo.figure.voxels, "draw voxels instead of surfaces");
  view->add_option("--grid", vo.figure.grid, "raster cells per axis (4 to 256; default 64)")
      ->type_name("N");
}

void add_export(CLI::App& app, FigureCommands& f) {
  ViewOptions& eo = f.export_options;
  auto* exporter = f.exporter = app.add_subcommand(
      "export", "Write the CSNCs of three variables as meshes or voxels for ParaView (meshio)");
  exporter->add_option("RESULT_DIR", eo.result_dir, "directory written by `aspects solve --out`")
      ->required();
  exporter->add_option("--vtk", eo.out, "file to write: .vtu (VTK XML) or .vtk (legacy VTK)")
      ->required();
  exporter->add_option("--axes", eo.figure.axes,
                       "three variables, pose or command (default: the pose's, when it has "
                       "three)")
      ->type_name("VARS");
  add_choice_options(exporter, eo.figure,
                     "the separated CSNCs, then the largest the filter keeps, 6 in all");
  exporter->add_flag("--voxels", eo.figure.voxels,
                     "hexahedra of the raster's cells instead of triangle surfaces");
  exporter->add_option("--grid", eo.figure.grid, "raster cells per axis (4 to 256; default 64)")
      ->type_name("N");
}

}  // namespace

void add_figure_commands(CLI::App& app, FigureCommands& f) {
  add_plot(app, f);
  add_view(app, f);
  add_export(app, f);
}

bool figure_command_chosen(const FigureCommands& f) {
  return *f.plot || *f.view || *f.exporter;
}

int run_figure_command(const FigureCommands& f) {
  if (*f.plot) return run_plot(f.plot_options);
  if (*f.view) return run_view(f.view_options);
  return run_export(f.export_options);
}

}  // namespace aspects
