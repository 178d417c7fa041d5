// model.cpp — trusted core: lexer and recursive-descent parser of the model language, written for
// the checker independently of the solver's. One statement per line (`#` comments); a statement
// continues over newlines while a ( or [ is open. Grammar:
//   expr := term (('+'|'-') term)*     term := unary (('*'|'/') unary)*
//   unary := ('-'|'+') unary | power   power := primary ['^' ['-'] INTEGER]
//   primary := NUMBER | pi | NAME | FUNC '(' expr ')' | (min|max) '(' expr ',' expr ')'
//            | '(' expr ')'
//   formula := conj ('or' conj)*       conj := fprim ('and' fprim)*
//   fprim := '(' formula ')' | expr ('>='|'>'|'<='|'<') expr
// Besides syntax it enforces what the proofs rely on: a square system, and periodic
// variables entering only through sin/cos of sums (so f is 2π-periodic in them and the
// 2π shifts of links and of the neighbourhood graph are sound).
#include "checker.h"

#include <gmpxx.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <tuple>

namespace cc {
namespace {

enum class Tok { Ident, Number, Punct, Newline, End };
struct Token {
  Tok kind;
  std::string text;
  int line, col;
};

[[noreturn]] void fail(int line, int col, const std::string& msg) {
  throw ModelError(std::to_string(line) + ":" + std::to_string(col) + ": " + msg);
}

std::vector<Token> lex(const std::string& s) {
  std::vector<Token> out;
  int depth = 0, line = 1, col = 1;
  size_t i = 0;
  auto adv = [&]() {  // one byte other than '\n' (only the newline branch consumes those)
    ++i;
    ++col;
  };
  auto digit = [&](size_t k) { return k < s.size() && std::isdigit((unsigned char)s[k]); };
  while (i < s.size()) {
    char c = s[i];
    int l = line, co = col;
    size_t b = i;
    if (c == '#') {
      while (i < s.size() && s[i] != '\n') adv();
    } else if (c == '\n') {
      if (depth == 0) out.push_back({Tok::Newline, "end of line", l, co});
      ++i;
      ++line;
      col = 1;
    } else if (c == ' ' || c == '\t' || c == '\r') {
      adv();
    } else if (std::isalpha((unsigned char)c) || c == '_') {
      while (i < s.size() && (std::isalnum((unsigned char)s[i]) || s[i] == '_')) adv();
      out.push_back({Tok::Ident, s.substr(b, i - b), l, co});
    } else if (digit(i) || (c == '.' && digit(i + 1))) {
      int dots = 0;
      while (digit(i) || (i < s.size() && s[i] == '.')) {
        if (s[i] == '.') ++dots;
        adv();
      }
      if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        size_t k = i + 1;
        if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
        if (digit(k)) {
          while (i < k) adv();
          while (digit(i)) adv();
        }
      }
      if (dots > 1) fail(l, co, "malformed number '" + s.substr(b, i - b) + "'");
      out.push_back({Tok::Number, s.substr(b, i - b), l, co});
    } else if (std::string("+-*/^()[],=<>").find(c) != std::string::npos) {
      if (c == '(' || c == '[') ++depth;
      if ((c == ')' || c == ']') && depth > 0) --depth;
      adv();
      bool le = (c == '<' || c == '>') && i < s.size() && s[i] == '=';  // <= and >=
      if (le) adv();
      out.push_back({Tok::Punct, le ? std::string{c, '='} : std::string(1, c), l, co});
    } else {
      fail(l, co, "unexpected character (byte " + std::to_string((unsigned char)c) + ")");
    }
  }
  out.push_back({Tok::Newline, "end of line", line, col});
  out.push_back({Tok::End, "end of file", line, col});
  return out;
}

const std::map<std::string, Op> kFunctions = {
    {"sqr", Op::Sqr}, {"sqrt", Op::Sqrt}, {"sin", Op::Sin},   {"cos", Op::Cos},
    {"tan", Op::Tan}, {"exp", Op::Exp},   {"log", Op::Log},   {"abs", Op::Abs},
    {"asin", Op::Asin}, {"acos", Op::Acos}, {"atan", Op::Atan}};
const std::set<std::string> kReserved = {
    "robot", "constant", "let", "pose", "command", "equation", "constraint", "factor",
    "in", "periodic", "pi", "min", "max", "and", "or"};

class Parser {
 public:
  explicit Parser(const std::string& text) : t_(lex(text)) {}

  Model run() {
    while (peek().kind != Tok::End) {
      if (peek().kind == Tok::Newline) ++p_;
      else statement();
    }
    const Token& e = t_.back();
    if (m_.name.empty()) fail(1, 1, "missing 'robot NAME' statement");
    if (m_.pose.empty()) fail(e.line, e.col, "no pose variable");
    if (m_.pose.size() != m_.command.size() || m_.command.size() != m_.eqs.size())
      fail(e.line, e.col,
           "the system is not square (poses, commands and equations differ in number)");
    check_periodic();
    return std::move(m_);
  }

 private:
  const Token& peek() const { return t_[p_]; }
  bool punct(const char* s) const { return peek().kind == Tok::Punct && peek().text == s; }
  bool word(const char* s) const { return peek().kind == Tok::Ident && peek().text == s; }
  static bool relation(const Token& t) {
    return t.kind == Tok::Punct && (t.text[0] == '<' || t.text[0] == '>');
  }
  [[noreturn]] void bad(const Token& t, const std::string& msg) { fail(t.line, t.col, msg); }
  void expect(const char* s) {
    if (!punct(s)) bad(peek(), std::string("expected '") + s + "', found '" + peek().text + "'");
    ++p_;
  }

  // Structurally equal nodes are shared, as in the solver's DAG: e*e is then a square.
  int add(Op op, int a = -1, int b = -1, int k = 0) {
    auto memo = memo_.emplace(std::make_tuple(op, a, b, k), int(m_.nodes.size()));
    if (!memo.second) return memo.first->second;
    Node n{op, a, b, k, 0};
    if (a >= 0) n.dep |= m_.nodes[a].dep;
    if (b >= 0) n.dep |= m_.nodes[b].dep;
    if (op == Op::Var) n.dep = uint64_t(1) << k;
    m_.nodes.push_back(n);
    return int(m_.nodes.size()) - 1;
  }

  std::string new_name() {
    const Token& t = peek();
    if (t.kind != Tok::Ident) bad(t, "expected a name, found '" + t.text + "'");
    if (kReserved.count(t.text) || kFunctions.count(t.text)) bad(t, "'" + t.text + "' is reserved");
    if (names_.count(t.text)) bad(t, "duplicate name '" + t.text + "'");
    ++p_;
    return t.text;
  }

  void statement() {
    Token kw = peek();
    if (kw.kind != Tok::Ident) bad(kw, "expected a statement, found '" + kw.text + "'");
    ++p_;
    const std::string& k = kw.text;
    if (k == "robot") {
      if (!m_.name.empty()) bad(kw, "duplicate 'robot' statement");
      if (peek().kind != Tok::Ident && peek().kind != Tok::Number)
        bad(peek(), "expected the robot's name");
      while (peek().kind != Tok::Newline) m_.name += t_[p_++].text;  // e.g. 3-RRR*
    } else if (k == "bisect") {  // the search's choice: checked for its name only
      std::string name;
      while (peek().kind != Tok::Newline) name += t_[p_++].text;  // pose-first: 3 tokens
      if (name != "round-robin" && name != "pose-first" && name != "verdict")
        bad(kw, "unknown bisector '" + name + "'");
    } else if (k == "constant" || k == "let") {
      std::string name = new_name();
      expect("=");
      Token at = peek();
      int e = expr();
      if (k == "constant" && m_.nodes[e].dep)
        bad(at, "constant '" + name + "' depends on a variable");
      names_[name] = e;
    } else if (k == "pose" || k == "command") {
      Var v;
      v.name = new_name();
      v.pose = k == "pose";
      if (!word("in")) bad(peek(), "expected 'in'");
      ++p_;
      expect("[");
      v.lo = const_expr();
      expect(",");
      v.hi = const_expr();
      expect("]");
      if (word("periodic")) {
        v.periodic = true;
        ++p_;
      }
      int index = int(m_.vars.size());
      if (index >= 64) bad(kw, "too many variables");
      m_.vars.push_back(v);
      (v.pose ? m_.pose : m_.command).push_back(index);
      names_[v.name] = add(Op::Var, -1, -1, index);
      var_tok_.push_back(kw);
    } else if (k == "equation") {
      Token at = peek();
      int lhs = expr();
      expect("=");
      int e = add(Op::Sub, lhs, expr());
      if (!m_.nodes[e].dep) bad(at, "equation does not depend on any variable");
      m_.eqs.push_back(e);
    } else if (k == "constraint") {
      m_.constraints.push_back(formula(false));
    } else if (k == "factor") {
      Token at = peek();
      int e = expr();
      if (!m_.nodes[e].dep) bad(at, "factor does not depend on any variable");
      m_.factors.push_back(e);
    } else {
      bad(kw, "unknown statement '" + k + "'");
    }
    if (peek().kind != Tok::Newline)
      bad(peek(), "expected end of line, found '" + peek().text + "'");
    ++p_;
  }

  int const_expr() {
    Token at = peek();
    int e = expr();
    if (m_.nodes[e].dep) bad(at, "a domain bound must be a constant expression");
    return e;
  }
  struct Depth {  // bounded recursion: a hostile model must not overflow the stack
    Parser& p;
    int k;
    explicit Depth(Parser& q, int step = 1) : p(q), k(step) {
      p.depth_ += k;
      if (p.depth_ > 200) p.bad(p.peek(), "expression nested too deeply");
    }
    ~Depth() { p.depth_ -= k; }
  };
  // A disjunction (conj = false) or conjunction of constraint formulas.
  int formula(bool conj) {
    Depth guard(*this, !conj);
    std::vector<int> kids{conj ? fprim() : formula(true)};
    while (word(conj ? "and" : "or")) {
      ++p_;
      kids.push_back(conj ? fprim() : formula(true));
    }
    if (kids.size() == 1) return kids[0];
    m_.formulas.push_back({conj ? Formula::And : Formula::Or, false, -1, kids});
    return int(m_.formulas.size()) - 1;
  }
  // A '(' group is a formula iff it holds a comparison, 'and' or 'or' (an expression never
  // does, so this is the reading the solver's try-formula-then-expression would find).
  bool formula_group() const {
    if (!punct("(")) return false;
    size_t depth = 0;
    for (size_t i = p_; t_[i].kind != Tok::End; ++i) {
      const Token& t = t_[i];
      const bool open = t.kind == Tok::Punct && t.text == "(";
      const bool close = t.kind == Tok::Punct && t.text == ")";
      if (open) ++depth;
      if (close) --depth;
      if ((open || close) && depth == 0) return false;
      if (relation(t) || (t.kind == Tok::Ident && (t.text == "and" || t.text == "or"))) return true;
    }
    return false;
  }
  int fprim() {
    if (formula_group()) {
      ++p_;
      int f = formula(false);
      expect(")");
      return f;
    }
    Token at = peek();
    int lhs = expr();
    if (!relation(peek()))
      bad(peek(), "expected a comparison ('>=', '>', '<=' or '<'), found '" + peek().text + "'");
    const std::string rel = t_[p_++].text;
    const int rhs = expr();
    const int g = rel[0] == '>' ? add(Op::Sub, lhs, rhs) : add(Op::Sub, rhs, lhs);
    if (!m_.nodes[g].dep) bad(at, "comparison does not depend on any variable");
    m_.atoms.push_back(g);
    m_.formulas.push_back({Formula::Atom, rel.size() == 1, g, {}});
    return int(m_.formulas.size()) - 1;
  }
  int expr() {
    Depth guard(*this);
    int a = term();
    while (punct("+") || punct("-")) {
      Op op = t_[p_++].text == "+" ? Op::Add : Op::Sub;
      a = add(op, a, term());
    }
    return a;
  }
  int term() {
    int a = unary();
    while (punct("*") || punct("/")) {
      Op op = t_[p_++].text == "*" ? Op::Mul : Op::Div;
      a = add(op, a, unary());
    }
    return a;
  }
  int unary() {
    int signs = 0;
    for (; punct("-") || punct("+"); ++p_) signs += punct("-");
    int a = power();
    return signs % 2 ? add(Op::Neg, a) : a;
  }
  int power() {
    int a = primary();
    if (!punct("^")) return a;
    ++p_;
    bool neg = punct("-");
    if (neg) ++p_;
    const Token& t = peek();
    if (t.kind != Tok::Number || t.text.find_first_not_of("0123456789") != std::string::npos)
      bad(t, "exponent after '^' must be an integer");
    if (t.text.size() > 4) bad(t, "exponent too large");
    ++p_;
    int k = std::stoi(t.text) * (neg ? -1 : 1);
    if (k == 0) return literal("1");  // x^0 = 1
    if (k == 1) return a;
    return k == 2 ? add(Op::Sqr, a) : add(Op::Pow, a, -1, k);
  }
  int literal(const std::string& text) {
    auto l = literal_.emplace(text, int(m_.literals.size()));
    if (l.second) m_.literals.push_back(text);
    return add(Op::Const, -1, -1, l.first->second);
  }
  int primary() {
    Token t = peek();
    ++p_;
    if (t.kind == Tok::Number) return literal(t.text);
    if (t.kind == Tok::Punct && t.text == "(") {
      int a = expr();
      expect(")");
      return a;
    }
    if (t.kind != Tok::Ident) bad(t, "expected an expression, found '" + t.text + "'");
    if (t.text == "pi") return add(Op::Pi);
    auto f = kFunctions.find(t.text);
    if (f != kFunctions.end()) {
      expect("(");
      int a = expr();
      expect(")");
      return add(f->second, a);
    }
    if (t.text == "min" || t.text == "max") {
      expect("(");
      int a = expr();
      expect(",");
      int b = expr();
      expect(")");
      return add(t.text == "min" ? Op::Min : Op::Max, a, b);
    }
    auto it = names_.find(t.text);
    if (it == names_.end() || punct("(")) bad(t, "unknown name '" + t.text + "'");
    return it->second;
  }

  // f is 2π-periodic in a periodic variable if every use of it is inside sin/cos, through
  // sums only. bare[id]: the variables that reach node id through +, - and negation only.
  void check_periodic() {
    uint64_t periodic = 0;
    for (size_t v = 0; v < m_.vars.size(); ++v)
      if (m_.vars[v].periodic) periodic |= uint64_t(1) << v;
    std::vector<uint64_t> bare(m_.nodes.size(), 0);
    for (size_t id = 0; id < bare.size(); ++id) {
      const Node& n = m_.nodes[id];
      if (n.op == Op::Var) bare[id] = n.dep;
      if (n.op == Op::Add || n.op == Op::Sub || n.op == Op::Neg)
        bare[id] = bare[n.a] | (n.b >= 0 ? bare[n.b] : 0);
    }
    std::vector<int> roots = m_.eqs;
    roots.insert(roots.end(), m_.factors.begin(), m_.factors.end());
    roots.insert(roots.end(), m_.atoms.begin(), m_.atoms.end());
    for (int r : roots)
      if (bare[r] & periodic) fail_periodic(bare[r] & periodic);
    const std::vector<int> live = closure(m_, roots);
    for (auto id = live.rbegin(); id != live.rend(); ++id) {  // parents before children
      const Node& n = m_.nodes[*id];
      const bool sum = n.op == Op::Add || n.op == Op::Sub || n.op == Op::Neg;
      const bool wraps = sum || n.op == Op::Sin || n.op == Op::Cos;
      uint64_t under = (n.a >= 0 ? bare[n.a] : 0) | (n.b >= 0 ? bare[n.b] : 0);
      if (!wraps && (under & periodic)) fail_periodic(under & periodic);
    }
  }
  [[noreturn]] void fail_periodic(uint64_t vars) {
    int v = 0;
    while (!(vars >> v & 1)) ++v;
    const std::string name = m_.vars[v].name;
    bad(var_tok_[v], "periodic variable '" + name + "' must appear only inside sin() or cos()");
  }

  std::vector<Token> t_;
  size_t p_ = 0;
  Model m_;
  std::map<std::string, int> names_, literal_;
  std::map<std::tuple<Op, int, int, int>, int> memo_;
  std::vector<Token> var_tok_;
  int depth_ = 0;
};

}  // namespace

Model parse_model(const std::string& text) { return Parser(text).run(); }

std::vector<int> closure(const Model& m, const std::vector<int>& roots) {
  std::vector<char> need(m.nodes.size(), 0);
  for (int r : roots) need[r] = 1;
  std::vector<int> out;
  for (int id = int(need.size()) - 1; id >= 0; --id) {
    if (!need[id]) continue;
    const Node& n = m.nodes[id];
    if (n.a >= 0) need[n.a] = 1;
    if (n.b >= 0) need[n.b] = 1;
    out.push_back(id);
  }
  std::reverse(out.begin(), out.end());
  return out;
}

namespace {

// a·π + b with exact rationals; `ok` false when the node is not of that form (or too big).
struct Affine {
  mpq_class a, b;
  bool ok = false;
};

// The exact value of a decimal literal (digits, optional '.', optional e[+-]digits).
bool literal_value(const std::string& s, mpq_class& out) {
  const size_t e = std::min(s.find_first_of("eE"), s.size());
  const size_t point = std::min(s.find('.'), e);
  std::string digits = s.substr(0, point);
  long exp10 = 0;
  if (point < e) {
    digits += s.substr(point + 1, e - point - 1);
    exp10 = -long(e - point - 1);
  }
  if (e < s.size()) {
    const std::string x = s.substr(e + 1);
    if (x.size() > 7) return false;  // |exponent| < 10^6: the rational stays small
    exp10 += std::stol(x);
  }
  if (exp10 > 10000 || exp10 < -10000 || digits.size() > 10000) return false;
  mpz_class ten;
  mpz_ui_pow_ui(ten.get_mpz_t(), 10, (unsigned long)std::labs(exp10));
  out = mpz_class(digits, 10);
  if (exp10 >= 0) out *= ten;
  if (exp10 < 0) out /= ten;
  return true;
}

size_t bits(const mpq_class& q) {  // the size of a rational, for the memory budget
  return mpz_sizeinbase(q.get_num_mpz_t(), 2) + mpz_sizeinbase(q.get_den_mpz_t(), 2);
}

}  // namespace

bool exactly_one_period(const Model& m, const Var& v) {
  // Forward over the nodes the bounds use (children have smaller ids), no recursion: a
  // chain of `constant` names may be long. At most 2^24 bits of rationals in all (a hostile
  // model must not exhaust memory); beyond that the domain is refused.
  std::vector<Affine> val(size_t(std::max(v.lo, v.hi)) + 1);
  size_t budget = size_t(1) << 24;
  for (int id : closure(m, {v.lo, v.hi})) {
    const Node& n = m.nodes[id];
    Affine& r = val[id];
    if (n.dep) continue;
    const Affine* x = n.a >= 0 ? &val[n.a] : nullptr;
    const Affine* y = n.b >= 0 ? &val[n.b] : nullptr;
    if ((x && !x->ok) || (y && !y->ok)) continue;
    r.ok = true;
    switch (n.op) {
      case Op::Const: r.ok = literal_value(m.literals[n.k], r.b); break;
      case Op::Pi: r.a = 1; break;
      case Op::Add:
        r.a = x->a + y->a;
        r.b = x->b + y->b;
        break;
      case Op::Sub:
        r.a = x->a - y->a;
        r.b = x->b - y->b;
        break;
      case Op::Neg:
        r.a = -x->a;
        r.b = -x->b;
        break;
      case Op::Mul:  // one factor must be rational (no π²)
        r.ok = x->a == 0 || y->a == 0;
        r.a = x->a * y->b + y->a * x->b;
        r.b = x->b * y->b;
        break;
      case Op::Div:  // by a nonzero rational only
        r.ok = y->a == 0 && y->b != 0;
        if (r.ok) {
          r.a = x->a / y->b;
          r.b = x->b / y->b;
        }
        break;
      default: r.ok = false;
    }
    const size_t used = r.ok ? bits(r.a) + bits(r.b) : 0;
    if (used > budget) return false;
    budget -= used;
  }
  const Affine& lo = val[v.lo];
  const Affine& hi = val[v.hi];
  return lo.ok && hi.ok && hi.a - lo.a == 2 && hi.b == lo.b;
}

}  // namespace cc
