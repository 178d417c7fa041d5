// The module's exceptions: a model error carries FILE:LINE:COL (as the command line prints
// it) and its parts as attributes; a bad result directory and a bad argument are
// ValueErrors with the command line's message.
#include "model/model.h"
#include "py_common.h"
#include "results/result_index.h"
#include "results/usage_error.h"

namespace aspects::py {

void bind_errors(pyb::module_& m) {
  static pyb::exception<ModelError> model_error(m, "ModelError", PyExc_ValueError);
  static pyb::exception<IndexError> result_error(m, "ResultError", PyExc_ValueError);
  pyb::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ModelError& e) {
      pyb::object err = pyb::reinterpret_borrow<pyb::object>(model_error.ptr())(e.what());
      err.attr("file") = e.file();
      err.attr("line") = e.line();
      err.attr("col") = e.col();
      err.attr("message") = e.message();
      PyErr_SetObject(model_error.ptr(), err.ptr());
    } catch (const IndexError& e) {
      result_error(e.what());
    } catch (const UsageError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
}

}  // namespace aspects::py
