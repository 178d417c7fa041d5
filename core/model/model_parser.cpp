// Parser of the robot model language (grammar in robots/README.md). One statement per
// line; a line may continue while a parenthesis or bracket is open. Every error is a
// ModelError naming the file, line and column.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "model/constant_values.h"
#include "model/exact_period.h"
#include "model/model.h"

namespace aspects {

namespace {

enum class Tok { Ident, Number, Punct, Newline, End };

struct Token {
  Tok kind;
  std::string text;
  int line, col;
};

class Lexer {
 public:
  Lexer(const std::string& text, const std::string& file) : s_(text), file_(file) {}

  std::vector<Token> run() {
    std::vector<Token> out;
    int depth = 0;
    while (i_ < s_.size()) {
      char c = s_[i_];
      check_printable(c);
      if (c == '#') {
        while (i_ < s_.size() && s_[i_] != '\n') {
          check_printable(s_[i_]);
          advance();
        }
      } else if (c == '\n') {
        if (depth == 0) out.push_back({Tok::Newline, "\\n", line_, col_});
        advance();
      } else if (c == ' ' || c == '\t') {
        advance();
      } else if (std::isalpha((unsigned char)c) || c == '_') {
        int l = line_, co = col_;
        size_t b = i_;
        while (i_ < s_.size() && (std::isalnum((unsigned char)s_[i_]) || s_[i_] == '_')) advance();
        out.push_back({Tok::Ident, s_.substr(b, i_ - b), l, co});
      } else if (std::isdigit((unsigned char)c) || (c == '.' && i_ + 1 < s_.size() &&
                                                     std::isdigit((unsigned char)s_[i_ + 1]))) {
        int l = line_, co = col_;
        size_t b = i_;
        while (i_ < s_.size() && (std::isdigit((unsigned char)s_[i_]) || s_[i_] == '.')) advance();
        if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
          size_t save = i_;
          int sl = line_, sc = col_;
          advance();
          if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) advance();
          if (i_ < s_.size() && std::isdigit((unsigned char)s_[i_])) {
            while (i_ < s_.size() && std::isdigit((unsigned char)s_[i_])) advance();
          } else {
            i_ = save, line_ = sl, col_ = sc;
          }
        }
        std::string t = s_.substr(b, i_ - b);
        if (std::count(t.begin(), t.end(), '.') > 1)
          throw ModelError(file_, l, co, "malformed number '" + t + "'");
        out.push_back({Tok::Number, t, l, co});
      } else if (std::string("+-*/^()[],=<>").find(c) != std::string::npos) {
        if (c == '(' || c == '[') ++depth;
        if ((c == ')' || c == ']') && depth > 0) --depth;
        std::string t(1, c);
        int l = line_, co = col_;
        advance();
        if ((c == '<' || c == '>') && i_ < s_.size() && s_[i_] == '=') {
          t += '=';
          advance();
        }
        out.push_back({Tok::Punct, t, l, co});
      } else {
        throw ModelError(file_, line_, col_,
                         std::string("unexpected character '") + (std::isprint((unsigned char)c) ? std::string(1, c) : "\\x" + hex(c)) + "'");
      }
    }
    out.push_back({Tok::Newline, "\\n", line_, col_});
    out.push_back({Tok::End, "end of file", line_, col_});
    return out;
  }

 private:
  // The certificate embeds the model text and check_cert accepts only printable ASCII,
  // tabs and newlines (a carriage return or a bidi control could make the text read
  // differently from what is checked), comments included.
  void check_printable(char c) const {
    unsigned char u = static_cast<unsigned char>(c);
    if (u == '\t' || u == '\n' || (u >= 0x20 && u <= 0x7e)) return;
    throw ModelError(file_, line_, col_,
                     "byte 0x" + hex(c) + " is not printable ASCII (only printable ASCII, "
                     "tabs and newlines are allowed, comments included)");
  }
  static std::string hex(char c) {
    const char* d = "0123456789abcdef";
    unsigned char u = (unsigned char)c;
    return std::string{d[u >> 4], d[u & 15]};
  }
  void advance() {
    if (s_[i_] == '\n') {
      ++line_;
      col_ = 1;
    } else {
      ++col_;
    }
    ++i_;
  }
  const std::string& s_;
  const std::string& file_;
  size_t i_ = 0;
  int line_ = 1, col_ = 1;
};

// Which functions of one argument the language knows, and their node.
const std::map<std::string, Op>& unary_functions() {
  static const std::map<std::string, Op> m = {
      {"sqr", Op::Sqr}, {"sqrt", Op::Sqrt}, {"sin", Op::Sin},   {"cos", Op::Cos},
      {"tan", Op::Tan}, {"exp", Op::Exp},   {"log", Op::Log},   {"abs", Op::Abs},
      {"asin", Op::Asin}, {"acos", Op::Acos}, {"atan", Op::Atan}};
  return m;
}

const std::set<std::string>& keywords() {
  static const std::set<std::string> k = {"robot", "constant", "let", "pose", "command",
                                          "equation", "constraint", "factor", "in",
                                          "periodic", "pi", "min", "max", "and", "or"};
  return k;
}

class Parser {
 public:
  Parser(const std::string& text, const std::string& file, Model& m)
      : toks_(Lexer(text, file).run()), file_(file), m_(m), constants_(m.dag) {
    index_groups();
  }

  void run() {
    while (peek().kind != Tok::End) {
      if (peek().kind == Tok::Newline) {
        ++p_;
        continue;
      }
      statement();
    }
    finish();
  }

 private:
  const Token& peek() const { return toks_[p_]; }
  const Token& next() { return toks_[p_++]; }
  [[noreturn]] void fail(const Token& t, const std::string& msg) {
    throw ModelError(file_, t.line, t.col, msg);
  }
  bool is_punct(const std::string& s) const {
    return peek().kind == Tok::Punct && peek().text == s;
  }
  bool is_word(const std::string& s) const {
    return peek().kind == Tok::Ident && peek().text == s;
  }
  std::string describe(const Token& t) const {
    if (t.kind == Tok::Newline) return "end of line";
    if (t.kind == Tok::End) return "end of file";
    return "'" + t.text + "'";
  }
  void expect_punct(const std::string& s) {
    if (!is_punct(s)) fail(peek(), "expected '" + s + "', found " + describe(peek()));
    ++p_;
  }
  void expect_end_of_statement() {
    if (peek().kind != Tok::Newline)
      fail(peek(), "expected end of line, found " + describe(peek()));
    ++p_;
  }
  Token expect_new_name() {
    const Token& t = peek();
    if (t.kind != Tok::Ident) fail(t, "expected a name, found " + describe(t));
    if (keywords().count(t.text) || unary_functions().count(t.text))
      fail(t, "'" + t.text + "' is a reserved word and cannot be used as a name");
    auto it = names_.find(t.text);
    if (it != names_.end())
      fail(t, "duplicate name '" + t.text + "' (first defined on line " +
                  std::to_string(it->second.line) + ")");
    ++p_;
    return t;
  }

  void statement() {
    const Token& kw = peek();
    if (kw.kind != Tok::Ident) fail(kw, "expected a statement keyword, found " + describe(kw));
    std::string k = kw.text;
    ++p_;
    if (k == "robot") {
      if (!m_.name.empty()) fail(kw, "duplicate 'robot' statement");
      const Token& t = peek();
      if (t.kind != Tok::Ident && t.kind != Tok::Number)
        fail(t, "expected the robot's name, found " + describe(t));
      // Names like 3-RPR or 3-RRR*: take every token up to the end of the line.
      std::string name;
      while (peek().kind != Tok::Newline) name += next().text;
      m_.name = name;
    } else if (k == "bisect") {
      if (!m_.bisect.empty()) fail(kw, "duplicate 'bisect' statement");
      const Token& at = peek();
      std::string name;  // "pose-first" is three tokens: up to the end of the line
      while (peek().kind != Tok::Newline && peek().kind != Tok::End) name += next().text;
      if (std::find(std::begin(kBisectNames), std::end(kBisectNames), name) ==
          std::end(kBisectNames))
        fail(at, "unknown bisector '" + name + "' (expected round-robin, pose-first or verdict)");
      m_.bisect = name;
    } else if (k == "constant" || k == "let") {
      Token name = expect_new_name();
      expect_punct("=");
      const Token& at = peek();
      int node = expr();
      if (k == "constant" && !m_.dag.is_constant(node))
        fail(at, "constant '" + name.text + "' depends on a variable (use 'let')");
      names_[name.text] = Name{node, name.line};
    } else if (k == "pose" || k == "command") {
      variable(kw, k == "pose" ? VarKind::Pose : VarKind::Command);
    } else if (k == "equation") {
      const Token& at = peek();
      size_t start = p_;
      int lhs = expr();
      expect_punct("=");
      int rhs = expr();
      int node = written(m_.dag.binary(Op::Sub, lhs, rhs), start);
      if (m_.dag.is_constant(node)) fail(at, "equation does not depend on any variable");
      m_.equations.push_back(node);
      m_.equation_text.push_back(source_text(start, p_));
      equation_tokens_.push_back(at);
    } else if (k == "factor") {
      const Token& at = peek();
      size_t start = p_;
      int node = written(expr(), start);
      if (m_.dag.is_constant(node)) fail(at, "factor does not depend on any variable");
      m_.user_factors.push_back(node);
      m_.user_factor_lines.push_back(at.line);
      m_.user_factor_text.push_back(source_text(start, p_));
    } else if (k == "constraint") {
      const Token& at = peek();
      size_t start = p_;
      int root = formula();
      m_.constraints.push_back({root, source_text(start, p_), at.line});
    } else {
      fail(kw, "unknown statement '" + k +
                   "' (expected robot, constant, let, pose, command, equation, factor, constraint or "
                   "bisect)");
    }
    expect_end_of_statement();
  }

  std::string source_text(size_t from, size_t to) const {
    std::string s;
    for (size_t i = from; i < to; ++i) {
      const Token& t = toks_[i];
      if (t.kind == Tok::Newline) continue;
      bool tight = s.empty() || t.text == ")" || t.text == "," || t.text == "^" ||
                   s.back() == '(' || s.back() == '^' ||
                   (t.text == "(" && std::isalnum((unsigned char)s.back()));
      if (!tight) s += ' ';
      s += t.text;
    }
    return s;
  }

  void variable(const Token& kw, VarKind kind) {
    Token name = expect_new_name();
    // A neighbour pair packs one shift per variable in 2 bits of 32. Refused at the
    // declaration that passes the limit: a model of thousands is not parsed further.
    if (m_.vars.size() >= size_t(kMaxVariables))
      fail(name, "'" + name.text + "' is variable " + std::to_string(m_.vars.size() + 1) +
                     "; at most " + std::to_string(kMaxVariables) + " variables are supported");
    if (!is_word("in")) fail(peek(), "expected 'in' after the variable's name, found " + describe(peek()));
    ++p_;
    const Token& open = peek();
    expect_punct("[");
    const Token& lo_tok = peek();
    int lo_node = -1, hi_node = -1;
    Interval lo = constant_expr(&lo_node);
    expect_punct(",");
    const Token& hi_tok = peek();
    Interval hi = constant_expr(&hi_node);
    expect_punct("]");
    Variable v;
    v.name = name.text;
    v.kind = kind;
    v.line = name.line;
    if (mpfr_cmp(&lo.get()->left, &hi.get()->right) > 0)
      fail(open, "empty domain for '" + name.text + "': lower bound " + lo.str() +
                     " exceeds upper bound " + hi.str());
    (void)lo_tok;
    (void)hi_tok;
    mpfi_interv_fr(v.domain.get(), &lo.get()->left, &hi.get()->right);
    v.inner_lo = mpfr_get_d(&lo.get()->right, MPFR_RNDU);
    v.inner_hi = mpfr_get_d(&hi.get()->left, MPFR_RNDD);
    if (is_word("periodic")) {
      const Token& per = next();
      // One period exactly, decided on the bounds as written (core/model/exact_period.h); the
      // independent checker applies the same rule.
      if (!exactly_one_period(m_.dag, meanings_, lo_node, hi_node))
        fail(per, "periodic domain of '" + name.text + "' must be exactly one period: bounds a*pi + b "
                  "(a, b rational) with upper - lower = 2*pi exactly, e.g. [-pi, pi]");
      // Exact bounds may still have wide enclosures (k - k with a huge k is [-huge, huge]):
      // the root box would be many periods wide.
      const double width = v.domain.width_up();
      if (!(width <= max_period_width())) {
        char shown[32];
        std::snprintf(shown, sizeof shown, "%.17g", width);
        fail(open, "periodic domain of '" + name.text + "' evaluates to an enclosure of width " +
                       shown + ", more than one period (2*pi) plus rounding: write its bounds "
                       "so that they evaluate closely (e.g. [-pi, pi])");
      }
      v.periodic = true;
    }
    (void)kw;
    int index = int(m_.vars.size());
    m_.vars.push_back(v);
    (kind == VarKind::Pose ? m_.pose : m_.command).push_back(index);
    names_[name.text] = Name{m_.dag.var(index), name.line};
    var_tokens_.push_back(name);
  }

  Interval constant_expr(int* node_out = nullptr) {
    const Token& at = peek();
    int node = expr();
    if (node_out) *node_out = node;
    if (!m_.dag.is_constant(node)) fail(at, "a domain bound must be a constant expression");
    Interval v = constants_.value(node);
    if (v.empty() || !v.bounded()) fail(at, "domain bound is not a finite number");
    // Boxes are stored as doubles: an enclosure beyond their range is no domain.
    if (!std::isfinite(v.lo_down()) || !std::isfinite(v.hi_up()))
      fail(at, "domain bound is not a finite number: it evaluates beyond the range of doubles "
               "(about 1.8e308)");
    return v;
  }

  // formula := conj ('or' conj)* ; conj := fprimary ('and' fprimary)*
  // fprimary := '(' formula ')' | expr ('>='|'<='|'>'|'<') expr
  int formula() {
    int a = conjunction();
    if (!is_word("or")) return a;
    FormulaNode n;
    n.kind = FormulaNode::Or;
    n.kids.push_back(a);
    while (is_word("or")) {
      ++p_;
      n.kids.push_back(conjunction());
    }
    m_.formula.push_back(n);
    return int(m_.formula.size()) - 1;
  }
  int conjunction() {
    int a = formula_primary();
    if (!is_word("and")) return a;
    FormulaNode n;
    n.kind = FormulaNode::And;
    n.kids.push_back(a);
    while (is_word("and")) {
      ++p_;
      n.kids.push_back(formula_primary());
    }
    m_.formula.push_back(n);
    return int(m_.formula.size()) - 1;
  }
  int formula_primary() {
    // A parenthesised group is a formula when it holds a comparison, 'and' or 'or' (no
    // expression does), an expression otherwise (robots/README.md). Decided from the
    // index, not by trying one and then the other: that retried every nested group.
    if (is_punct("(") && group_holds_logic(p_)) {
      const Token& open = next();
      if (++nesting_ > kMaxNesting) fail(open, "formula nested too deeply");
      int f = formula();
      expect_punct(")");
      --nesting_;
      return f;
    }
    const Token& at = peek();
    const size_t start = p_;
    int lhs = expr();
    if (!is_relation())
      fail(peek(), "expected a comparison ('>=', '<=', '>' or '<'), found " + describe(peek()));
    std::string rel = next().text;
    int rhs = expr();
    FormulaNode n;
    n.kind = FormulaNode::Atom;
    n.strict = rel == ">" || rel == "<";
    bool greater = rel[0] == '>';
    n.expr = written(greater ? m_.dag.binary(Op::Sub, lhs, rhs) : m_.dag.binary(Op::Sub, rhs, lhs),
                     start);
    if (m_.dag.is_constant(n.expr)) fail(at, "comparison does not depend on any variable");
    m_.constraint_atoms.push_back(n.expr);
    m_.formula.push_back(n);
    return int(m_.formula.size()) - 1;
  }
  bool is_relation() const {
    return is_punct(">=") || is_punct("<=") || is_punct(">") || is_punct("<");
  }

  // expr := term (('+'|'-') term)*
  int expr() {
    // Recursion (here and in differentiation) is bounded by the nesting and depth of
    // expressions: refuse absurd ones rather than overflow the stack.
    const Token& at = peek();
    const size_t start = p_;
    if (++nesting_ > kMaxNesting) fail(at, "expression nested too deeply");
    int a = term();
    while (is_punct("+") || is_punct("-")) {
      Op op = next().text == "+" ? Op::Add : Op::Sub;
      a = written(m_.dag.binary(op, a, term()), start);
      if (m_.dag.depth(a) > kMaxDepth) fail(at, "expression too long (depth over 1000)");
    }
    // Also without a sum: sin(a) where the name a is itself deep, a chain of lets.
    if (m_.dag.depth(a) > kMaxDepth) fail(at, "expression too long (depth over 1000)");
    --nesting_;
    return a;
  }
  // term := unary (('*'|'/') unary)*
  int term() {
    const Token& at = peek();
    const size_t start = p_;
    int a = unary();
    while (is_punct("*") || is_punct("/")) {
      Op op = next().text == "*" ? Op::Mul : Op::Div;
      a = written(m_.dag.binary(op, a, unary(), /*keep_operands=*/true), start);
      if (m_.dag.depth(a) > kMaxDepth) fail(at, "expression too long (depth over 1000)");
    }
    return a;
  }
  // unary := '-' unary | '+' unary | power
  int unary() {
    if (is_punct("-")) {
      const size_t start = p_;
      const Token& at = next();
      if (++nesting_ > kMaxNesting) fail(at, "expression nested too deeply");
      int a = written(m_.dag.unary(Op::Neg, unary()), start);
      --nesting_;
      return a;
    }
    if (is_punct("+")) {
      const Token& at = next();
      if (++nesting_ > kMaxNesting) fail(at, "expression nested too deeply");
      int a = unary();
      --nesting_;
      return a;
    }
    return power();
  }
  // power := primary ['^' ['-'] INTEGER]
  int power() {
    const size_t start = p_;
    int a = primary();
    if (is_punct("^")) {
      ++p_;
      bool neg = false;
      if (is_punct("-")) {
        neg = true;
        ++p_;
      }
      const Token& t = peek();
      if (t.kind != Tok::Number || t.text.find_first_not_of("0123456789") != std::string::npos)
        fail(t, "exponent after '^' must be an integer, found " + describe(t));
      if (t.text.size() > 4) fail(t, "exponent " + t.text + " is too large");
      ++p_;
      int k = std::stoi(t.text);
      a = written(m_.dag.pow(a, neg ? -k : k), start);
    }
    return a;
  }
  int primary() {
    const size_t start = p_;
    const Token& t = peek();
    if (t.kind == Tok::Number) {
      ++p_;
      Interval v;
      if (!Interval::from_string(v, t.text)) fail(t, "malformed number '" + t.text + "'");
      // Beyond the double range counts as non-finite: boxes are stored as doubles.
      if (!v.bounded() || std::isinf(v.lo_down()) || std::isinf(v.hi_up()))
        fail(t, "number '" + t.text + "' is not finite");
      return remember_meaning(m_.dag.constant(v), t.text);
    }
    if (is_punct("(")) {
      ++p_;
      int a = expr();
      expect_punct(")");
      return a;
    }
    if (t.kind != Tok::Ident) fail(t, "expected an expression, found " + describe(t));
    ++p_;
    if (t.text == "pi") {
      Interval pi;
      mpfi_const_pi(pi.get());
      return remember_meaning(m_.dag.constant(pi), "pi");
    }
    auto uf = unary_functions().find(t.text);
    if (uf != unary_functions().end()) {
      expect_punct("(");
      int a = expr();
      expect_punct(")");
      return written(m_.dag.unary(uf->second, a), start);
    }
    if (t.text == "min" || t.text == "max") {
      expect_punct("(");
      int a = expr();
      expect_punct(",");
      int b = expr();
      expect_punct(")");
      return written(m_.dag.binary(t.text == "min" ? Op::Min : Op::Max, a, b), start);
    }
    if (is_punct("(")) fail(t, "unknown function '" + t.text + "'");
    auto it = names_.find(t.text);
    if (it == names_.end()) fail(t, "unknown name '" + t.text + "'");
    return it->second.node;
  }

  void finish() {
    const Token& end = toks_.back();
    if (m_.name.empty()) fail(toks_.front(), "missing 'robot NAME' statement");
    int np = int(m_.pose.size()), nc = int(m_.command.size()), ne = int(m_.equations.size());
    if (np == 0) fail(end, "the model declares no pose variable");
    if (np != nc || nc != ne)
      fail(end, "the system is not square: " + std::to_string(np) + " pose variable(s), " +
                    std::to_string(nc) + " command variable(s), " + std::to_string(ne) +
                    " equation(s); they must be equal");
    check_periodic_use();
    for (int e : m_.equations) {
      for (int j : m_.pose) m_.fx.push_back(m_.dag.derivative(e, j));
      for (int j : m_.command) m_.fq.push_back(m_.dag.derivative(e, j));
    }
  }

  // A periodic variable must enter the model only through sin/cos of sums of it
  // and other terms, so that f is 2*pi-periodic in it: the wrap-around links of the
  // neighbourhood graph rely on that.
  void check_periodic_use() {
    const Dag& d = m_.dag;
    std::vector<int> roots = m_.equations;
    roots.insert(roots.end(), m_.user_factors.begin(), m_.user_factors.end());
    roots.insert(roots.end(), m_.constraint_atoms.begin(), m_.constraint_atoms.end());
    std::vector<int> live = d.closure(roots);
    std::vector<char> bare(size_t(d.size()), 0);
    for (size_t vi = 0; vi < m_.vars.size(); ++vi) {
      if (!m_.vars[vi].periodic) continue;
      // bare[id]: the variable reaches id through +, - and negation only. Once per node, in
      // increasing ids (children first): a walk per use is exponential on a shared DAG
      // (let a1 = a0 + a0, let a2 = a1 + a1, ...).
      for (int id : live) {
        const Node& n = d.node(id);
        bool passes = n.op == Op::Add || n.op == Op::Sub || n.op == Op::Neg;
        bare[id] = n.op == Op::Var ? n.k == int(vi)
                   : passes        ? bare[n.a] || (n.b >= 0 && bare[n.b])
                                   : 0;
      }
      for (int id : live) {
        const Node& n = d.node(id);
        bool wraps = n.op == Op::Sin || n.op == Op::Cos;
        bool passes = n.op == Op::Add || n.op == Op::Sub || n.op == Op::Neg;
        if (wraps || passes || n.op == Op::Var || n.op == Op::Const) continue;
        for (int c : {n.a, n.b})
          if (c >= 0 && bare[c]) fail_periodic_use(vi, id, live);
      }
      // An equation or factor that is itself a sum with the bare variable is not periodic.
      for (int root : roots)
        if (bare[root]) fail_periodic_use(vi, root, live);
    }
  }

  // The periodic variable vi is used outside sin() and cos() by `node`: said at the text the
  // user wrote there, the innermost written expression that holds the node (the DAG may
  // make a node of its own, x^3 as sqr(x)*x), rather than at the variable's declaration.
  [[noreturn]] void fail_periodic_use(size_t vi, int node, const std::vector<int>& live) {
    const Dag& d = m_.dag;
    std::vector<char> holds(size_t(d.size()), 0);
    for (int id : live) {  // children first
      const Node& n = d.node(id);
      holds[size_t(id)] = id == node || (n.a >= 0 && holds[size_t(n.a)]) ||
                          (n.b >= 0 && holds[size_t(n.b)]);
      auto w = written_.find(id);
      if (holds[size_t(id)] && w != written_.end())
        fail(toks_[w->second.first],
             "periodic variable '" + m_.vars[vi].name +
                 "' must appear only inside sin() or cos(); '" +
                 source_text(w->second.first, w->second.second) + "' uses it outside them");
    }
    fail(var_tokens_[vi], "periodic variable '" + m_.vars[vi].name +
                              "' must appear only inside sin() or cos()");
  }

  // Records where the user first wrote `node`: tokens [from, p_).
  int written(int node, size_t from) {
    written_.emplace(node, std::make_pair(from, p_));
    return node;
  }

  // Each '(' token's matching ')' (toks_.size() - 1 when unmatched), and how many
  // comparisons, 'and' and 'or' precede each token: together they tell in O(1) whether a
  // group holds logic.
  void index_groups() {
    group_end_.assign(toks_.size(), toks_.size() - 1);
    logic_before_.assign(toks_.size() + 1, 0);
    std::vector<size_t> open;
    for (size_t i = 0; i < toks_.size(); ++i) {
      const Token& t = toks_[i];
      // A punctuation token starting with '<' or '>' is a comparison (<, <=, >, >=).
      const char c = t.kind == Tok::Punct ? t.text[0] : 0;
      const bool logic = c == '<' || c == '>' ||
                         (t.kind == Tok::Ident && (t.text == "and" || t.text == "or"));
      logic_before_[i + 1] = logic_before_[i] + (logic ? 1 : 0);
      if (c == '(') open.push_back(i);
      if (c == ')' && !open.empty()) {
        group_end_[open.back()] = i;
        open.pop_back();
      }
    }
  }
  bool group_holds_logic(size_t open) const {
    return logic_before_[group_end_[open]] > logic_before_[open + 1];
  }

  struct Name {
    int node;
    int line;
  };
  static constexpr int kMaxNesting = 200, kMaxDepth = 1000, kMaxVariables = 16;
  // One period and 2^-20 of it, or 2^(20 - p) of it at a working precision of p < 40 bits:
  // the rounding of sensible bounds (up to 1e5 or so at 24 bits) stays far below.
  static double max_period_width() {
    const long excess_bits = std::min(20L, working_precision() - 20);
    return 2 * M_PI * (1 + std::ldexp(1.0, -int(excess_bits)));
  }
  int nesting_ = 0;
  std::vector<Token> toks_;
  size_t p_ = 0;
  const std::string& file_;
  Model& m_;
  std::map<std::string, Name> names_;
  ConstantValues constants_;  // the domain bounds' enclosures
  std::vector<size_t> group_end_;     // see index_groups()
  std::vector<size_t> logic_before_;
  ConstantMeanings meanings_;  // exact meaning of each literal and pi node, for periods

  // The DAG shares constant nodes with equal enclosures: a node that two different
  // texts reach has no single exact meaning (empty text).
  int remember_meaning(int node, const std::string& text) {
    auto [it, fresh] = meanings_.emplace(node, text);
    if (!fresh && it->second != text) it->second.clear();
    return node;
  }
  std::vector<Token> var_tokens_;
  std::vector<Token> equation_tokens_;
  std::map<int, std::pair<size_t, size_t>> written_;  // node: tokens of its first text
};

}  // namespace

std::vector<std::string> Model::var_names() const {
  std::vector<std::string> v;
  for (const auto& x : vars) v.push_back(x.name);
  return v;
}

Box Model::initial_box() const {
  Box b;
  for (const auto& v : vars) b.push_back(v.domain);
  return b;
}

Model parse_model(const std::string& text, const std::string& file) {
  Model m;
  m.file = file;
  // CRLF line endings are read as LF, and the model is kept (and embedded in the
  // certificate) that way; any other carriage return is an error of the lexer.
  std::string source;
  source.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i)
    if (!(text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n')) source += text[i];
  m.source = source;
  Parser(m.source, file, m).run();
  return m;
}

Model load_model(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw ModelError(path, 0, 0, "cannot open model file: it is a directory");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw ModelError(path, 0, 0,
                     std::string("cannot open model file") +
                         (errno != 0 ? std::string(": ") + std::strerror(errno) : ""));
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_model(ss.str(), path);
}

const char* const kDefaultModelText =
    "# RRRRR five-bar, paper Section 5.2 (embedded default of `aspects solve`)\n"
    "robot RRRRR\n"
    "bisect verdict\n"
    "pose    x1 in [-20, 20]\n"
    "pose    x2 in [-20, 20]\n"
    "command q1 in [-pi, pi] periodic\n"
    "command q2 in [-pi, pi] periodic\n"
    "equation (x1 - 8*cos(q1))^2 + (x2 - 8*sin(q1))^2 - 25 = 0\n"
    "equation (x1 - 9 - 5*cos(q2))^2 + (x2 - 5*sin(q2))^2 - 64 = 0\n";

}  // namespace aspects
