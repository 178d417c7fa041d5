#include "run/count_dir.h"

#include <filesystem>

#include "io/atomic_file.h"
#include "numerics/interval.h"
#include "results/count_pieces.h"
#include "results/result_index.h"
#include "results/usage_error.h"
#include "run/count_report.h"

namespace aspects {

void prepare_count_dir(const std::string& dir, const std::string& option) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (dir.find('\0') != std::string::npos)
    throw UsageError(option + ": the path contains a NUL character");
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw UsageError(option + ": '" + dir + "' exists and is not a directory");
  if (fs::exists(fs::path(dir) / kResultIndexName, ec))
    throw UsageError(option + ": '" + dir + "' holds a solve's result (" + kResultIndexName +
                     "): give a directory of its own to the count");
  fs::create_directories(dir, ec);
  if (ec) throw UsageError(option + ": cannot make the directory '" + dir + "': " + ec.message());
}

void write_count_dir(const std::string& dir, const Model& m, const CountResult& r, double eps) {
  namespace fs = std::filesystem;
  write_count_pieces((fs::path(dir) / kCountPiecesName).string(),
                     count_pieces_of(m, r, eps, working_precision()));
  write_file_atomically((fs::path(dir) / "summary.json").string(),
                        count_json(m, r, eps).dump(1) + "\n");
}

}  // namespace aspects
