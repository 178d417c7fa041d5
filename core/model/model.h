// A robot model: pose variables x, command variables q, n equations f(x, q) = 0, and
// the symbolic Jacobians Fx = df/dx, Fq = df/dq, all as nodes of one expression DAG.
// Parsed from the model language documented in robots/README.md.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "model/expr.h"
#include "numerics/interval.h"

namespace aspects {

// A model error, printed as "FILE:LINE:COL: error: MESSAGE" (or "FILE: error: MESSAGE").
class ModelError : public std::runtime_error {
 public:
  // Line 0: an error of the whole file (it cannot be opened), said without a position.
  ModelError(const std::string& file, int line, int col, const std::string& msg)
      : std::runtime_error(file +
                           (line > 0 ? ":" + std::to_string(line) + ":" + std::to_string(col)
                                     : std::string()) +
                           ": error: " + msg),
        file_(file), line_(line), col_(col), message_(msg) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int col() const { return col_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_, col_;
  std::string message_;
};

enum class VarKind { Pose, Command };

struct Variable {
  std::string name;
  VarKind kind;
  Interval domain;  // outward enclosure of the declared domain
  // Inner enclosure of the declared bounds, rounded inward to doubles: a box whose
  // variable reaches [inner_lo, inner_hi] certainly meets the declared domain. (May be
  // reversed for a degenerate domain whose bound is not a double.)
  double inner_lo = 0, inner_hi = 0;
  bool periodic = false;
  int line = 0;
};

// A factor of det Fx · det Fq used to separate aspects by sign (paper 4.4.2).
struct Factor {
  int node;             // DAG node
  std::string text;     // printable expression
  std::string origin;   // "det Fx", "det Fq", "diagonal of Fq", "user (line N)"
  std::string kind;     // certificate form: "detFx", "diagFq 2", "user 1"
};

// A node of a constraint formula (paper 5.4): an atom g(x, q) >= 0 (or > 0), or the
// conjunction / disjunction of other formula nodes.
struct FormulaNode {
  enum Kind { Atom, And, Or } kind = Atom;
  int expr = -1;        // Atom: DAG node of g = lhs - rhs (oriented so that g >= 0 holds)
  bool strict = false;  // Atom: g > 0 instead of g >= 0
  std::vector<int> kids;  // And/Or: formula node ids
};

struct Constraint {
  int root;             // formula node id
  std::string text;
  int line;
};

// The names a `bisect` statement may give. The language only lists them; what each one
// does is the search's (search/bisector.h maps every one of them to a bisector).
inline const char* const kBisectNames[] = {"round-robin", "pose-first", "verdict"};

struct Model {
  std::string name;
  std::string file;     // path as given, for messages
  std::string source;   // the model text, verbatim
  // `bisect NAME`: the search's bisector for this robot unless --bisect is given (empty:
  // not stated), one of kBisectNames. A search choice only: the certificate is checked
  // the same way.
  std::string bisect;
  Dag dag;
  std::vector<Variable> vars;  // model order (order of declaration)
  std::vector<int> pose;       // indices into vars
  std::vector<int> command;
  std::vector<int> equations;  // node of lhs - rhs
  std::vector<std::string> equation_text;
  std::vector<int> user_factors;  // nodes, from `factor EXPR`
  std::vector<int> user_factor_lines;
  std::vector<std::string> user_factor_text;
  std::vector<FormulaNode> formula;      // nodes of every constraint formula
  std::vector<Constraint> constraints;   // `constraint` statements
  std::vector<int> constraint_atoms;     // DAG nodes g of every atom
  std::vector<int> fx, fq;  // n×n row-major nodes: d eq_i / d pose_j, d eq_i / d command_j

  int n() const { return int(equations.size()); }
  std::vector<std::string> var_names() const;
  Box initial_box() const;
};

// Parses model text. `file` is used in error messages only.
Model parse_model(const std::string& text, const std::string& file);
// Reads and parses a file; a missing file is a ModelError at 0:0.
Model load_model(const std::string& path);

// The paper's RRRRR five-bar (Section 5.2), the default robot of `aspects solve`.
extern const char* const kDefaultModelText;

}  // namespace aspects
