// aspects.Result (the compiled part; python/aspects/result.py adds the rest): the boxes as
// numpy arrays, the summary, and `query` and `path` as `aspects query|path --json` answer
// them, through the same code (results/pose_query.h, planning/path_plan.h).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <optional>

#include "model/model_eval.h"
#include "path_plan.h"
#include "py_common.h"
#include "results/pose.h"
#include "results/pose_query.h"
#include "results/result_index.h"
#include "results/sha256.h"
#include "results/usage_error.h"
#include "search/output_boxes.h"

namespace aspects::py {

namespace {

// Box status codes of Result.status (aspects.SOLUTION, ...): an undecided box's kind as
// the index records it, shifted by one.
constexpr int8_t kSolution = 0;

// Every box by increasing id: id, lower and upper ends (model order; an undecided box's
// command ends are NaN, the index keeps only its pose part), status, CSNC, and the signs
// of the determinant factors on a solution box (0 where its enclosure straddles 0, and on
// an undecided box).
pyb::dict box_arrays(const PyResult& p) {
  const LoadedResult& r = *p.loaded;
  const size_t ns = r.index.solutions.size(), nu = r.index.undecided.size();
  const size_t n = ns + nu, nv = r.index.nv;
  pyb::array_t<uint32_t> id(n);
  pyb::array_t<double> lo({n, nv}), hi({n, nv});
  pyb::array_t<int8_t> status(n);
  pyb::array_t<int32_t> csnc(n);
  const size_t np = r.index.factors.size();  // each solution box has one sign per factor
  pyb::array_t<int8_t> signs({n, np});
  auto sgv = signs.mutable_unchecked<2>();
  auto idv = id.mutable_unchecked<1>();
  auto lov = lo.mutable_unchecked<2>();
  auto hiv = hi.mutable_unchecked<2>();
  auto stv = status.mutable_unchecked<1>();
  auto csv = csnc.mutable_unchecked<1>();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  size_t row = 0;
  for_each_box_by_id(r.index, [&](bool solution, size_t i) {
    if (solution) {
      const IndexSolutionBox& s = r.index.solutions[i];
      idv(row) = s.id;
      for (size_t v = 0; v < nv; ++v) lov(row, v) = s.lo[v], hiv(row, v) = s.hi[v];
      stv(row) = kSolution;
      csv(row) = s.csnc;
      for (size_t k = 0; k < np; ++k) sgv(row, k) = int8_t(s.signs[k]);
    } else {
      const IndexUndecidedBox& u = r.index.undecided[i];
      idv(row) = u.id;
      for (size_t v = 0; v < nv; ++v) lov(row, v) = nan, hiv(row, v) = nan;
      for (size_t k = 0; k < r.model.pose.size(); ++k) {
        lov(row, r.model.pose[k]) = u.lo[k];
        hiv(row, r.model.pose[k]) = u.hi[k];
      }
      stv(row) = int8_t(1 + u.kind);
      csv(row) = -1;
      for (size_t k = 0; k < np; ++k) sgv(row, k) = 0;
    }
    ++row;
  });
  pyb::dict d;
  d["id"] = id;
  d["lower"] = lo;
  d["upper"] = hi;
  d["status"] = status;
  d["csnc"] = csnc;
  d["signs"] = signs;
  return d;
}

// Per CSNC: the signs of the determinant factors, which are constant on it. A box's
// enclosure of a factor may straddle 0 where another box of the CSNC decides the sign, so
// each factor's sign is the first decided one among its boxes (0: decided on none).
std::vector<std::vector<int>> csnc_signs(const LoadedResult& r) {
  std::vector<std::vector<int>> signs(r.index.csnc_count);
  for (const IndexSolutionBox& s : r.index.solutions) {
    std::vector<int>& c = signs[s.csnc];
    if (c.empty()) c.assign(s.signs.size(), 0);
    for (size_t i = 0; i < s.signs.size(); ++i)
      if (c[i] == 0) c[i] = s.signs[i];
  }
  return signs;
}

}  // namespace

void bind_result(pyb::module_& m) {
  m.attr("SOLUTION") = int(kSolution);
  m.attr("UNDECIDED_NO_EXISTENCE") = 1 + int(UndecidedKind::NoExistence);
  m.attr("UNDECIDED_SINGULAR") = 1 + int(UndecidedKind::Singular);
  m.attr("UNDECIDED_CONSTRAINT") = 1 + int(UndecidedKind::Constraint);
  m.attr("UNEXPLORED") = 1 + int(UndecidedKind::Unexplored);
  pyb::class_<PyResult>(m, "_Result")
      .def_property_readonly("summary", [](const PyResult& p) { return to_python(p.summary); })
      .def_property_readonly("directory", [](const PyResult& p) { return p.dir; })
      .def_property_readonly("model_source",
                             [](const PyResult& p) { return p.loaded->index.model_source; })
      .def_property_readonly("model_file",
                             [](const PyResult& p) { return p.loaded->index.model_file; })
      .def_property_readonly("robot", [](const PyResult& p) { return p.loaded->model.name; })
      .def_property_readonly("eps", [](const PyResult& p) { return p.loaded->index.eps; })
      .def_property_readonly("variables",
                             [](const PyResult& p) { return p.loaded->model.var_names(); })
      .def_property_readonly("pose_variables",
                             [](const PyResult& p) {
                               std::vector<std::string> n;
                               for (int v : p.loaded->model.pose)
                                 n.push_back(p.loaded->model.vars[v].name);
                               return n;
                             })
      .def_property_readonly("pose_periodic",
                             [](const PyResult& p) { return p.loaded->pose_periodic; })
      .def_property_readonly("csnc_count",
                             [](const PyResult& p) { return p.loaded->index.csnc_count; })
      .def_property_readonly("filtered_count",
                             [](const PyResult& p) { return p.loaded->index.filtered; })
      .def_property_readonly("factors",
                             [](const PyResult& p) {
                               std::vector<std::pair<std::string, std::string>> f;
                               for (auto& x : p.loaded->index.factors)
                                 f.emplace_back(x.origin, x.text);
                               return f;
                             })
      .def_property_readonly("model_sha256",
                             [](const PyResult& p) {
                               return sha256_hex_of(p.loaded->index.model_source);
                             })
      .def_property_readonly("certificate_file",
                             [](const PyResult& p) { return p.loaded->index.certificate_file; })
      .def_property_readonly("certificate_sha256",
                             [](const PyResult& p) { return p.loaded->index.certificate_sha256; })
      .def_property_readonly("link_count",
                             [](const PyResult& p) { return p.loaded->index.links.size(); })
      .def("_csnc_signs", [](const PyResult& p) { return csnc_signs(*p.loaded); })
      .def("_arrays", &box_arrays)
      .def("_query",
           [](const PyResult& p, const std::vector<double>& pose) {
             const LoadedResult& r = *p.loaded;
             std::vector<double> x = checked_pose(pose, "pose", r.model);
             ModelEvaluator ev(r.model);
             return to_python(query_json(x, query_pose(r, ev, x), r));
           },
           pyb::arg("pose"))
      .def("_query_many",
           [](const PyResult& p, const std::vector<std::vector<double>>& poses) {
             // One evaluator for every row; a bad row names its index.
             const LoadedResult& r = *p.loaded;
             ModelEvaluator ev(r.model);
             pyb::list answers;
             for (size_t i = 0; i < poses.size(); ++i) {
               const std::string what = "poses[" + std::to_string(i) + "]";
               std::vector<double> x = checked_pose(poses[i], what, r.model);
               answers.append(to_python(query_json(x, query_pose(r, ev, x), r)));
             }
             return answers;
           },
           pyb::arg("poses"))
      .def("_path",
           [](const PyResult& p, const std::vector<double>& a, const std::vector<double>& b,
              std::optional<long> csnc) {
             const LoadedResult& r = *p.loaded;
             std::vector<double> from = checked_pose(a, "start", r.model);
             std::vector<double> to = checked_pose(b, "goal", r.model);
             // None: any CSNC (plan_path's -1); a negative one is no CSNC.
             if (csnc && (*csnc < 0 || *csnc >= long(r.index.csnc_count)))
               throw UsageError("csnc must be between 0 and " +
                                std::to_string(long(r.index.csnc_count) - 1) + ", got " +
                                std::to_string(*csnc));
             ModelEvaluator ev(r.model);
             return to_python(
                 path_json(from, to, plan_path(r, ev, from, to, csnc ? int(*csnc) : -1)));
           },
           pyb::arg("start"), pyb::arg("goal"), pyb::arg("csnc") = pyb::none());
  m.def(
      "_load",
      [](const std::string& dir) {
        auto loaded = std::make_shared<LoadedResult>(load_result(dir));
        nlohmann::json summary;
        std::ifstream in(dir + "/summary.json");
        if (in) {
          try {
            summary = nlohmann::json::parse(in);
          } catch (const nlohmann::json::exception& e) {
            throw IndexError(dir + "/summary.json: not JSON (" + e.what() + ")");
          }
        }
        return PyResult{loaded, summary, dir};
      },
      pyb::arg("directory"), "Read DIR/aspects.idx (and summary.json when present)");
}

}  // namespace aspects::py
