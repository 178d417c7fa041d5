#include "loaded_result.h"

namespace aspects {

LoadedResult load_result_from(ResultIndex index, const std::string& what) {
  set_working_precision(index.precision_bits);
  LoadedResult r{std::move(index), Model{}, {}};
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
  return load_result_from(read_result_index(result_dir), result_dir);
}

}  // namespace aspects
