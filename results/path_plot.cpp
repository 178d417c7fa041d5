#include "results/path_plot.h"

#include "results/plot_data.h"

namespace aspects {

void write_path_plot(const LoadedResult& r, const nlohmann::json& path, const std::string& png) {
  write_result_plot(r, path, png);
}

}  // namespace aspects
