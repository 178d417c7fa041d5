// aspects.Model: a robot model parsed by the solver's own parser. It keeps the text, which
// `solve` parses again on its worker thread at the run's working precision (intervals
// keep the precision they were created with).
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdio>

#include "model/model.h"
#include "py_common.h"
#include "py_model.h"

namespace aspects::py {

PyModel PyModel::parse(const std::string& text, const std::string& file) {
  PyModel m;
  Model parsed = parse_model(text, file);  // throws ModelError (FILE:LINE:COL)
  m.source = text;
  m.file = file;
  m.name = parsed.name;
  for (int v : parsed.pose) m.pose.push_back(parsed.vars[v].name);
  for (int v : parsed.command) m.command.push_back(parsed.vars[v].name);
  m.variables = parsed.var_names();
  m.bisect = parsed.bisect;
  for (const Variable& v : parsed.vars) {
    m.domains.emplace_back(v.domain.lo_down(), v.domain.hi_up());
    m.periodic.push_back(v.periodic);
  }
  m.equations = parsed.equation_text;
  m.factors = parsed.user_factor_text;
  for (const Constraint& c : parsed.constraints) m.constraints.push_back(c.text);
  return m;
}

PyModel PyModel::load(const std::string& path) {
  Model parsed = load_model(path);  // a missing file is a ModelError saying why
  return parse(parsed.source, path);
}

namespace {

// A bound as a short text: %.6g, enough to recognise a declared domain.
std::string short_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

// The model as a reader sees it: its variables with their domains, then its statements.
std::string model_repr(const PyModel& p) {
  // A file name in parentheses; the embedded model's is one already.
  std::string s = "<aspects.Model " + p.name + " " +
                  (p.file.rfind("(", 0) == 0 ? p.file : "(" + p.file + ")");
  for (size_t i = 0; i < p.variables.size(); ++i) {
    const bool pose =
        std::find(p.pose.begin(), p.pose.end(), p.variables[i]) != p.pose.end();
    s += std::string("\n  ") + (pose ? "pose    " : "command ") + p.variables[i] + " in [" +
         short_number(p.domains[i].first) + ", " + short_number(p.domains[i].second) + "]" +
         (p.periodic[i] ? " periodic" : "");
  }
  for (const std::string& e : p.equations) s += "\n  equation   " + e;
  for (const std::string& f : p.factors) s += "\n  factor     " + f;
  for (const std::string& c : p.constraints) s += "\n  constraint " + c;
  if (!p.bisect.empty()) s += "\n  bisect " + p.bisect;
  return s + ">";
}

}  // namespace

void bind_model(pyb::module_& m) {
  pyb::class_<PyModel>(m, "Model", "A robot model (the language of robots/README.md)")
      .def_static("from_file", &PyModel::load, pyb::arg("path"),
                  "Parse a .robot file; a model error raises ModelError (FILE:LINE:COL)")
      .def_static("from_string", &PyModel::parse, pyb::arg("text"),
                  pyb::arg("file") = std::string("<string>"),
                  "Parse model text; `file` names it in error messages")
      .def_static("default", [] { return PyModel::parse(kDefaultModelText, "(embedded RRRRR)"); },
                  "The paper's RRRRR five-bar, the default robot of `aspects solve`")
      .def_readonly("name", &PyModel::name)
      .def_readonly("file", &PyModel::file)
      .def_readonly("source", &PyModel::source)
      .def_readonly("variables", &PyModel::variables, "every variable, model order")
      .def_readonly("pose", &PyModel::pose, "pose variables, pose order")
      .def_readonly("command", &PyModel::command, "command variables")
      .def_property_readonly(
          "domains",
          [](const PyModel& p) {
            pyb::dict d;  // model order
            for (size_t i = 0; i < p.variables.size(); ++i)
              d[pyb::str(p.variables[i])] = pyb::make_tuple(p.domains[i].first, p.domains[i].second);
            return d;
          },
          "{name: (lo, hi)} in model order: each declared domain, rounded outward to doubles")
      .def_property_readonly(
          "periodic",
          [](const PyModel& p) {
            std::vector<std::string> names;
            for (size_t i = 0; i < p.variables.size(); ++i)
              if (p.periodic[i]) names.push_back(p.variables[i]);
            return names;
          },
          "the periodic variables, model order")
      .def_readonly("equations", &PyModel::equations,
                    "each equation as written (spacing normalised, as `aspects info` prints it)")
      .def_readonly("factors", &PyModel::factors, "the user-supplied `factor` expressions")
      .def_readonly("constraints", &PyModel::constraints, "the `constraint` formulas")
      .def_readonly("bisect", &PyModel::bisect, "the model's `bisect` statement ('' if none)")
      .def("__repr__", &model_repr);
}

}  // namespace aspects::py
