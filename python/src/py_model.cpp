// aspects.Model: a robot model parsed by the solver's own parser. It keeps the text, which
// `solve` parses again on its worker thread at the run's working precision (intervals
// keep the precision they were created with).
#include <pybind11/stl.h>

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
  return m;
}

PyModel PyModel::load(const std::string& path) {
  Model parsed = load_model(path);  // a missing file is a ModelError at 0:0
  return parse(parsed.source, path);
}

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
      .def("__repr__", [](const PyModel& p) {
        return "<aspects.Model " + p.name + ": " + std::to_string(p.pose.size()) + " pose, " +
               std::to_string(p.command.size()) + " command variables>";
      });
}

}  // namespace aspects::py
