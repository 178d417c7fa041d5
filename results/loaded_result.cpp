#include "results/loaded_result.h"

#include "results/result_files.h"

namespace aspects {

LoadedResult load_result_from(ResultIndex index, const std::string& what) {
  set_working_precision(index.precision_bits);
  LoadedResult r{std::move(index), Model{}, {}, {}};
  try {
    r.model = parse_model(r.index.model_source, r.index.model_file);
  } catch (const ModelError& e) {
    throw IndexError(what + ": the recorded model does not parse: " + e.what());
  }
  if (uint32_t(r.model.n()) != r.index.n || r.model.vars.size() != r.index.nv)
    throw IndexError(what + ": the recorded model has " + std::to_string(r.model.vars.size()) +
                     " variables, the index " + std::to_string(r.index.nv));
  for (int v : r.model.pose) r.pose_periodic.push_back(r.model.vars[v].periodic);
  return r;
}

LoadedResult load_result(const std::string& result_dir) {
  ResultIndex idx = read_result_index(result_dir);
  const std::vector<std::string> bad = mismatched_files(result_dir, idx);
  if (!bad.empty()) throw IndexError(bad.front());
  LoadedResult r = load_result_from(std::move(idx), result_dir);
  r.directory = result_dir;
  return r;
}

std::string certificate_note(const LoadedResult& r) {
  if (!r.index.certificate_file.empty()) return "";
  return "this result has no certificate (solved with --no-cert): its solution boxes, links, "
         "CSNCs and signs are the solver's, not checked by check_cert";
}

}  // namespace aspects
