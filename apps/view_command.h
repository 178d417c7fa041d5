// `aspects view RESULT_DIR [--out FILE.html]` and `aspects export RESULT_DIR --vtk FILE`:
// the CSNCs of a result in three variables (a 3-DOF robot's pose, or any three chosen with
// --axes), as surfaces (marching cubes over the boxes rasterised on a grid) or voxels: a
// self-contained HTML page that turns in a browser (plotly), or a file ParaView opens
// (meshio). Drawn by python/aspects/view3d.py and meshes.py through plot_data.h.
#pragma once

#include <string>

#include "figure_options.h"

namespace aspects {

struct ViewOptions {
  std::string result_dir;
  std::string out;  // view: empty is RESULT_DIR/aspects.html; export: the --vtk file
  FigureOptions figure;
};

// Exit code: 0 written; throws UsageError (2) for a bad option, IndexError (2) for a bad
// result directory, std::runtime_error (1) when the file cannot be written.
int run_view(const ViewOptions& opts);
int run_export(const ViewOptions& opts);

}  // namespace aspects
