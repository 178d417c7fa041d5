// The options of the figure commands (`aspects plot`, `view`, `export`): which variables
// as axes, which CSNCs, the picture's dpi and size, surfaces or voxels. Read as the user
// typed them and checked against the result, so that a bad one is refused before Python
// runs, naming the option (UsageError, exit 2).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "results/loaded_result.h"

namespace aspects {

enum class FigureKind {
  Plot,  // matplotlib: 2 axes (panels) or 3 (3-D panels); PNG, PDF, SVG
  View,  // plotly: one HTML page that turns in a browser; 3 axes
  Vtk,   // meshio: meshes or voxels for ParaView; 3 axes
};

struct FigureOptions {
  std::string axes;   // --axes "a,b[,c]": variable names; empty: the pose's
  std::string csncs;  // --csnc "0,3,5"; empty: the default choice
  // The numbers as typed (empty: not given), so that every text is checked here alike.
  std::string largest;  // --largest N
  std::string dpi;      // --dpi (plot)
  std::string size;     // --size WxH in inches (plot)
  bool voxels = false;  // view, export: voxels instead of surfaces
  std::string grid;     // view, export: raster cells per axis
};

// Limits of the numeric options (the messages quote them).
constexpr int kMinDpi = 10, kMaxDpi = 2400;
constexpr double kMaxInches = 100;
constexpr int kMinGrid = 4, kMaxGrid = 256;
constexpr int kDefaultViewGrid = 64;

// The "figure" entry of plotting.py's DATA.json: kind, axes (names), csncs or largest,
// dpi, size, voxels, cells. Throws UsageError naming the option when one does not fit
// the result (an unknown variable, a CSNC it does not have, ...). `has_path`: a path is
// drawn, so the axes must be pose variables.
nlohmann::json figure_json(const FigureOptions& o, const LoadedResult& r, FigureKind kind,
                           bool has_path);

}  // namespace aspects
