// aspects.count: the certified number of aspects, or bounds on it (proofs/counting/), as
// `aspects count --json` reports it (run/count_report.h), and its directory (out=); and
// aspects.piece_path, a certified path through the pieces of such a directory
// (planning/piece_path.h), as `aspects path DIR --json` reports it.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdio>
#include <map>
#include <stdexcept>
#include <thread>
#include <utility>

#include "counting/exact_count.h"
#include "counting/factor_gradients.h"
#include "model/model.h"
#include "piece_path.h"
#include "piece_path_output.h"
#include "py_common.h"
#include "py_model.h"
#include "py_polling.h"
#include "results/count_pieces.h"
#include "results/pose.h"
#include "results/result_index.h"
#include "results/usage_error.h"
#include "run/count_dir.h"
#include "run/count_report.h"
#include "search/stop_condition.h"

namespace aspects::py {

namespace {

const InterruptNotes kCountInterrupts = {
    "aspects.count: interrupted: the refinement stops and the certified bounds reached are "
    "returned (Ctrl-C again to stop at once)\n",
    "aspects.count: interrupted again: stopping now\n"};

// The count on a worker thread (py_polling.h): Ctrl-C stops the refinement, and the bounds
// reached (which hold) are returned, as on the command line.
pyb::tuple count(const PyModel& pm, const CountConfig& given, double time_limit,
                 const std::string& out) {
  Model m = parse_model(pm.source, pm.file);
  if (!out.empty()) prepare_count_dir(out, "out");
  StopCondition stop;
  if (time_limit > 0) stop.set_time_limit(time_limit);
  CountConfig cfg = given;
  cfg.stop = &stop;
  CountResult r;
  bool interrupted = false;
  Progress none;  // no progress callback
  try {
    run_polling([&] { r = count_aspects(m, cfg); }, stop, none, pyb::none(), kCountInterrupts,
                interrupted);
  } catch (const std::invalid_argument& e) {  // a refused model: named as the CLI names it
    throw std::invalid_argument(m.file + ": " + e.what());
  }
  if (!out.empty()) write_count_dir(out, m, r, cfg.eps);
  return pyb::make_tuple(to_python(count_json(m, r, cfg.eps)),
                         pyb::str(count_line(r.bounds)), interrupted);
}

pyb::tuple piece_path(const std::string& dir, const std::vector<double>& a,
                      const std::vector<double>& b, const std::string& cls) {
  CountDirectory d = load_count_directory(dir);
  const int64_t c = parse_class_signs(cls, int(d.pieces.factors.size()));
  const std::vector<double> from = checked_pose(a, "start", d.model);
  const std::vector<double> to = checked_pose(b, "goal", d.model);
  // The gradients' nodes are added to the model before its evaluator exists.
  FactorGradients fg(d.model, d.factor_nodes);
  ModelEvaluator ev(d.model);
  const PiecePathResult r = plan_piece_path(d, ev, fg, from, to, c);
  return pyb::make_tuple(to_python(piece_path_json(d, from, to, r)),
                         pyb::str(piece_path_text(d, from, to, r)));
}

// A count directory's pieces as arrays: one row per piece proved connected (its cell's id,
// box and its class), and the joins as pairs of rows. The components of the joins are
// connected sets of one aspect each; the aspects themselves when the count is exact.
pyb::dict count_pieces_arrays(const std::string& dir) {
  const CountDirectory D = load_count_directory(dir);
  const CountPieces& P = D.pieces;
  const size_t nv = P.nv;
  size_t n = 0;
  for (const CountPieceCell& c : P.cells) n += c.pieces.size();
  pyb::array_t<int32_t> cell(n);
  pyb::array_t<uint32_t> cls(n);
  pyb::array_t<double> lo({n, nv}), hi({n, nv});
  auto cv = cell.mutable_unchecked<1>();
  auto kv = cls.mutable_unchecked<1>();
  auto lov = lo.mutable_unchecked<2>();
  auto hiv = hi.mutable_unchecked<2>();
  std::map<std::pair<int32_t, uint32_t>, int64_t> row_of;
  size_t row = 0;
  for (const CountPieceCell& c : P.cells)
    for (const CountPiece& q : c.pieces) {
      cv(row) = c.id;
      kv(row) = q.cls;
      for (size_t v = 0; v < nv; ++v) lov(row, v) = c.box[2 * v], hiv(row, v) = c.box[2 * v + 1];
      row_of[{c.id, q.cls}] = int64_t(row++);
    }
  std::vector<int64_t> a, b;
  for (const CountJoin& j : P.joins) {
    const auto x = row_of.find({j.a, j.cls}), y = row_of.find({j.b, j.cls});
    if (x == row_of.end() || y == row_of.end())
      throw IndexError(dir + ": a join names a piece the file does not hold");
    a.push_back(x->second);
    b.push_back(y->second);
  }
  pyb::dict d;
  d["cell"] = cell;
  d["cls"] = cls;
  d["lo"] = lo;
  d["hi"] = hi;
  d["join_a"] = pyb::array_t<int64_t>(a.size(), a.data());
  d["join_b"] = pyb::array_t<int64_t>(b.size(), b.data());
  d["factors"] = P.factors;
  d["factor_origins"] = D.factor_origins;
  d["lower"] = P.lower;
  d["upper"] = P.upper < 0 ? pyb::object(pyb::none()) : pyb::object(pyb::int_(P.upper));
  d["eps"] = P.eps;
  std::vector<std::string> names, pose;
  for (const auto& v : D.model.vars) names.push_back(v.name);
  for (int v : D.model.pose) pose.push_back(D.model.vars[v].name);
  d["variables"] = names;
  d["pose_variables"] = pose;
  d["robot"] = D.model.name;
  d["model_file"] = P.model_file;
  return d;
}

}  // namespace

void bind_count(pyb::module_& m) {
  m.def(
      "_count",
      [](const PyModel& model, double eps, double min_width, int rounds, double time_limit,
         int threads, const std::string& out) {
        CountConfig cfg;
        cfg.eps = eps;
        cfg.min_width = min_width;
        cfg.max_rounds = rounds;
        cfg.threads = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
        cfg.keep_records = !out.empty();
        return count(model, cfg, time_limit, out);
      },
      pyb::arg("model"), pyb::arg("eps"), pyb::arg("min_width"), pyb::arg("rounds"),
      pyb::arg("time_limit"), pyb::arg("threads"), pyb::arg("out"),
      "Count; returns (count --json's object, the count line, interrupted). Use aspects.count.");
  m.def("_piece_path", &piece_path, pyb::arg("directory"), pyb::arg("start"), pyb::arg("goal"),
        pyb::arg("cls"),
        "A path through a count's pieces; returns (path --json's object, the lines printed). "
        "Use aspects.piece_path.");
  m.def("_count_pieces", &count_pieces_arrays, pyb::arg("directory"),
        "A count directory's pieces and joins as arrays. Use aspects.load_count.");
}

}  // namespace aspects::py
