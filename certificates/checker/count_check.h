// count_check.h — trusted core: the check of a count certificate's records after its tree
// (FORMAT.md, "Count certificates"), in three files: count_check.cpp (the records, the
// final cover and both bounds), count_proofs.cpp (the proofs on one box: Hansen–Sengupta
// with chosen unknowns, points of W_s, pavings, refutations of a class), count_connected.cpp
// (connected pieces: graphs and the star-shaped test; joins; the upper bound). The proofs
// run in line on the checker's own evaluator, after the tree's proofs are judged.
#pragma once

#include <map>

#include "check.h"

namespace cc {

// The outcome of a Hansen–Sengupta step with chosen unknowns (count_proofs.cpp).
enum class Hs { Image, Empty, Failed };

// A set of sign classes: bit s for the class s (bit i of s set when factor i is positive).
using Mask = uint64_t;
constexpr int kMaxCountFactors = 6;  // 2^6 classes, one bit each in a Mask
// The pavings' budgets (parts of U per star test, per empty piece): a cap on work, not a
// part of any proof. Above the engine's own (8000 and 4000), whose arithmetic differs.
constexpr long kStarParts = 1L << 16;
constexpr long kPavingParts = 1L << 16;
constexpr size_t kMaxTerms = 16;  // terms of a reduced disjunction, each one star test

class CountCheck {
 public:
  explicit CountCheck(Checker& c) : c_(c), pr_(*c.ev), n_(c.n), nv_(c.nv) {}
  void run();

 private:
  enum class State : uint8_t { Unmade, Pending, Live, Split, Void };
  struct Cell {
    State state = State::Unmade;
    Box origin, box;             // as created; now (after its chart)
    bool solution = false;       // made from an S record's output box
    std::vector<int> w;          // its chart (fit), for a paving or a star test
    Box w_tilde;
    std::vector<Ival> range;     // the chart's image: every w(u), u ∈ U, lies in it
    Mask claimed = 0;            // classes with a piece record
    Mask empty = 0, point = 0;   // verified: empty pieces, pieces holding a point of W_s
    Mask connected = 0;          // verified: connected pieces (nonempty: with a point too)
    Mask other_class = 0;        // empty because another class holds the graph (checked last)
    Mask graph_of_s = 0;         // connected as the graph of an S box, if nonempty (last)
  };

  Checker& c_;
  Prover pr_;
  int n_, nv_;
  long first_ = 0;
  long last_id_ = -1;
  std::vector<Cell> cells_;
  std::map<std::pair<long, long>, Mask> refuted_, joined_;  // verified, per pair of cells
  std::string upper_open_;  // why no upper bound, when none is proved
  // The star test's second derivatives: a copy of the model with the nodes of its Jacobian
  // (derivative.cpp), and an evaluator of them, made on first use.
  std::unique_ptr<Model> dm_;
  std::unique_ptr<Evaluator> dev_;
  std::vector<std::vector<int>> jn_;
  std::vector<int> jprog_;
  bool jn_ok_ = true;

  long rec() const { return c_.rec(); }
  [[noreturn]] void reject(const std::string& why) { c_.reject(why); }
  void limit() { c_.ev->work_limit = c_.work_limit(); }

  // ----- records
  long cell_id(bool order = true);
  Box reals_box(size_t k) { return c_.rd.intervals(k); }
  std::vector<int> chart_vars();
  Mask class_field();
  void half();
  void fit(bool void_only);
  void none();
  void split();
  void piece();
  void refuted();
  void joined();
  void every_cell_made();
  void finish();

  // ----- proofs
  Hs hansen_sengupta(std::vector<Ival>& box, const std::vector<int>& w, std::vector<Ival>& y);
  bool refute(const Box& b);
  bool no_class(std::vector<Ival> b, Mask cls, int depth, long& budget);
  bool factors(const std::vector<Ival>& box, std::vector<Ival>& out);
  // The constraints on box b (FORMAT.md, "Counting", C7): False; True; Atoms (`terms` holds
  // one term: atom formula ids whose conjunction is what is left); Disjunction (an `or` of
  // two Unknown disjuncts or more is left: `terms`, at most kMaxTerms, whose disjunction is
  // what is left; empty when there would be more).
  enum class Reduced { False, True, Atoms, Disjunction };
  using Dnf = std::vector<std::vector<int>>;
  Reduced reduce(const std::vector<Ival>& b, Dnf& terms);
  bool reduce_formula(int f, Dnf& dnf);
  // Every constraint True on b.
  bool feasible(const std::vector<Ival>& b);
  Mask excluded(const Box& b);
  Mask excluded(const std::vector<Ival>& b);
  bool point(const Box& box, const std::vector<int>& w, const std::vector<double>& u,
             const Box& hint, Mask cls, std::vector<Ival>* at = nullptr);
  bool narrow_w(const Cell& cell, std::vector<Ival>& b);
  // Halves part z of a paving in its u (of uv) widest relative to the cell's box, pushing
  // both halves; false when every u is narrower than min_rel of it or cannot be halved.
  bool halve_widest_u(const Cell& cell, const std::vector<int>& uv, double min_rel, Box z,
                      std::vector<Box>& stack) const;
  bool paving(const Cell& cell, Mask cls);
  bool crosses(const Cell& cell, int j, bool upper);
  bool graph(const Cell& cell, Mask cls);
  bool star(const Cell& cell, Mask cls, const std::vector<int>& w, const std::vector<double>& v,
            const Box& hint);
  bool star_term(const Cell& cell, Mask cls, const std::vector<int>& w,
                 const std::vector<double>& v, const Box& hint, const std::vector<int>& atoms);
  bool factor_gradients(const std::vector<Ival>& b, std::vector<std::vector<Ival>>& grad);
  bool implicit_jacobian(const std::vector<Ival>& b, const std::vector<int>& w,
                         std::vector<Ival>& X);
  bool inside_root(const Box& b) const;
  long lower_bound();
  long upper_bound();

  std::vector<Ival> ivals(const Box& b) const {
    std::vector<Ival> out(b.size() / 2);
    for (size_t v = 0; v < out.size(); ++v) out[v].set(b[2 * v], b[2 * v + 1]);
    return out;
  }
};

}  // namespace cc
