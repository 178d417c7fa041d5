// proofs.cpp — trusted core: Hansen–Sengupta (proof and contraction), strong regularity,
// factor enclosures and refutation. Preconditioners are plain doubles: the recorded ones are
// hints, and the checker's own (for refutation) come from a small Gauss–Jordan inverse of
// the midpoint matrix; any real matrix is sound because every product that feeds a
// verdict is an outward-rounded interval operation (interval.h) on the exact doubles.
#include "checker.h"

#include <algorithm>
#include <cmath>

namespace cc {

// Approximate inverse of the n×n matrix M (row major) by Gauss–Jordan with partial
// pivoting, in double. Only a heuristic choice: its result is never trusted.
bool invert(std::vector<double>& M, int n, std::vector<double>& inv) {  // M is spoilt
  inv.assign(size_t(n) * n, 0.0);
  for (int i = 0; i < n; ++i) inv[i * n + i] = 1;
  for (int c = 0; c < n; ++c) {
    int p = c;
    for (int r = c + 1; r < n; ++r)
      if (std::fabs(M[r * n + c]) > std::fabs(M[p * n + c])) p = r;
    double piv = M[p * n + c];
    if (piv == 0 || !std::isfinite(piv)) return false;
    for (int k = 0; k < n; ++k) {
      std::swap(M[c * n + k], M[p * n + k]);
      std::swap(inv[c * n + k], inv[p * n + k]);
    }
    for (int k = 0; k < n; ++k) {
      M[c * n + k] /= piv;
      inv[c * n + k] /= piv;
    }
    for (int r = 0; r < n; ++r) {
      double f = M[r * n + c];
      if (r == c || f == 0) continue;
      for (int k = 0; k < n; ++k) {
        M[r * n + k] -= f * M[c * n + k];
        inv[r * n + k] -= f * inv[c * n + k];
      }
    }
  }
  for (double v : inv)
    if (!std::isfinite(v)) return false;
  return true;
}

// Determinant by cofactor expansion along the first row (MPFI throughout); for n > 6 (n!
// products) the entire line, so that no sign is proved.
void det(const std::vector<Ival>& M, int n, Ival& out) {
  if (n > 6) return out.entire();
  if (n == 1) {
    out = M[0];
    return;
  }
  set_si(out, 0);
  std::vector<Ival> minor(size_t(n - 1) * (n - 1));
  Ival cof, term;
  for (int j = 0; j < n; ++j) {
    int k = 0;
    for (int r = 1; r < n; ++r)
      for (int c = 0; c < n; ++c)
        if (c != j) minor[k++] = M[r * n + c];
    det(minor, n - 1, cof);
    mul(term, M[j], cof);
    if (j % 2) sub(out, out, term);
    else add(out, out, term);
  }
}

Prover::Prover(Evaluator& ev) : ev_(ev), m_(ev.model()), n_(m_.n()), nv_(ev.nv()) {
  box.resize(nv_);
  w_.resize(nv_);
  y.resize(n_);
  Jx_.resize(size_t(n_) * n_);
  Jq_.resize(size_t(n_) * n_);
  A_.resize(size_t(n_) * n_);
  b_.resize(n_);
  X_.resize(n_);
  c_.resize(n_);
  w1_.resize(nv_);
  w2_.resize(nv_);
  for (int j : m_.command) cmd_mask_ |= uint64_t(1) << j;
  for (int j : m_.pose) pose_mask_ |= uint64_t(1) << j;
  all_mask_ = nv_ >= 64 ? ~uint64_t(0) : (uint64_t(1) << nv_) - 1;
}

void Prover::load(const double* lohi) {
  for (int v = 0; v < nv_; ++v) box[v].set(lohi[2 * v], lohi[2 * v + 1]);
}

// out := Σ_k C[k]·x[k] (k < n), each term an exact double times an interval, outward rounded.
void Prover::dot(Ival& out, const double* C, const Ival* const* x) {
  set_si(out, 0);
  for (int k = 0; k < n_; ++k) {
    mul_d(t1_, *x[k], C[k]);
    add(out, out, t1_);
  }
}

void Prover::product(const std::vector<Ival>& J, const double* C, std::vector<Ival>& out) {
  std::vector<const Ival*> column(n_);
  for (int i = 0; i < n_; ++i)
    for (int j = 0; j < n_; ++j) {
      for (int k = 0; k < n_; ++k) column[k] = &J[k * n_ + j];
      dot(out[i * n_ + j], C + i * n_, column.data());
    }
}

// b_ := C·f with f the values of the equations just evaluated.
void Prover::rhs(const double* C) {
  std::vector<const Ival*> f(n_);
  for (int k = 0; k < n_; ++k) f[k] = &ev_.val(m_.eqs[k]);
  for (int i = 0; i < n_; ++i) dot(b_[i], C + i * n_, f.data());
}

// Row i of Gauss–Seidel for C·f = 0 on q ∈ X around the centre c (both indexed by command):
// t1_ := (b_i + Σ_{j≠i} A_ij·(X_j − c_j)) / A_ii.
void Prover::gs_row(int i, const std::vector<Ival>& X, const std::vector<Ival>& c) {
  t1_ = b_[i];
  for (int j = 0; j < n_; ++j) {
    if (j == i) continue;
    sub(t2_, X[j], c[j]);
    mul(t2_, t2_, A_[i * n_ + j]);
    add(t1_, t1_, t2_);
  }
  div(t1_, t1_, A_[i * n_ + i]);
}

// J := the derivatives eval_ad() just computed w.r.t. the variables `cols`.
void Prover::read_jacobian(const std::vector<int>& cols, std::vector<Ival>& J) {
  for (int i = 0; i < n_; ++i)
    for (int j = 0; j < n_; ++j) J[i * n_ + j] = ev_.der(m_.eqs[i], cols[j]);
}

const char* Prover::newton(const double* Q, const double* C, bool pose) {
  const std::vector<int>& u = pose ? m_.pose : m_.command;  // the unknowns
  std::vector<Ival>& X = X_;  // the unknowns' box and centre
  std::vector<Ival>& c = c_;
  w_ = box;
  for (int j = 0; j < n_; ++j) {
    X[j].set(Q[2 * j], Q[2 * j + 1]);
    w_[u[j]] = X[j];
  }
  if (!ev_.eval_ad(ev_.all_eqs, w_.data(), pose ? pose_mask_ : cmd_mask_))
    return "the Jacobian is not defined on the Newton box";
  read_jacobian(u, Jq_);  // Fx in Jq_ when `pose`
  if (!C && !(C = own_preconditioner(Jq_))) return "the midpoint of the Jacobian is singular";
  product(Jq_, C, A_);
  // q̌: the binary64 midpoint of Q~, clamped into it (any point of Q~ is sound).
  for (int j = 0; j < n_; ++j) {
    const double lo = Q[2 * j];
    const double hi = Q[2 * j + 1];
    const double mid = std::min(std::max(lo + 0.5 * (hi - lo), lo), hi);
    c[j].set(mid, mid);
    w_[u[j]] = c[j];
  }
  if (!ev_.eval(ev_.all_eqs, w_.data(), Mode::Proof)) return "f is not defined at the centre";
  rhs(C);
  // In command order; row i uses X_j = Q~_j ∩ y_j for j < i.
  for (int i = 0; i < n_; ++i) {
    const Ival& aii = A_[i * n_ + i];
    if (aii.has_zero() || !aii.bounded()) return "a diagonal entry of C*J contains 0";
    gs_row(i, X, c);
    sub(y[i], c[i], t1_);
    if (!y[i].bounded() || y[i].empty()) return "Hansen-Sengupta image is unbounded";
    if (!X[i].meet(y[i])) return "Gauss-Seidel step left Q~";
  }
  return nullptr;
}

bool Prover::jacobians() {
  if (!ev_.eval_ad(ev_.all_eqs, box.data(), all_mask_)) return false;
  read_jacobian(m_.pose, Jx_);
  read_jacobian(m_.command, Jq_);
  return true;
}

// Row-wise strict diagonal dominance of M = C·J·diag(D), D > 0 (then every real matrix in
// J is nonsingular): mig(M_ii) > Σ_{j≠i} mag(M_ij), compared on the outward-rounded
// bounds (left end of |M_ii| against the right end of the sum).
bool Prover::dominant(const std::vector<Ival>& J, const double* C, const double* D) {
  product(J, C, A_);
  for (int i = 0; i < n_; ++i) {
    set_si(t2_, 0);
    for (int j = 0; j < n_; ++j) {
      if (!A_[i * n_ + j].bounded()) return false;
      if (j == i) continue;
      abs(t1_, A_[i * n_ + j]);
      mul_d(t1_, t1_, D[j]);
      add(t2_, t2_, t1_);
    }
    abs(t1_, A_[i * n_ + i]);
    mul_d(t1_, t1_, D[i]);
    if (!less(t2_, Hi, t1_, Lo)) return false;
  }
  return true;
}

const char* Prover::regular(const double* CX, const double* CQ, const double* DX,
                            const double* DQ) {
  if (!jacobians()) return "Jacobian not defined on the box";
  if (!CX && !(CX = own_preconditioner(Jx_))) return "the midpoint of Fx is singular";
  if (!dominant(Jx_, CX, DX)) return "C_X*Fx*D_X is not strictly diagonally dominant";
  if (!CQ && !(CQ = own_preconditioner(Jq_))) return "the midpoint of Fq is singular";
  if (!dominant(Jq_, CQ, DQ)) return "C_Q*Fq*D_Q is not strictly diagonally dominant";
  return nullptr;
}

bool Prover::factor(const Factor& f, bool jac, Ival& out) {
  if (f.kind == Factor::User) {
    if (!ev_.eval(ev_.factor_prog[f.arg], box.data(), Mode::Proof)) return false;
    out = ev_.val(m_.factors[f.arg]);
    return true;
  }
  if (!jac && !jacobians()) return false;
  const std::vector<Ival>& J = (f.kind == Factor::DetFx || f.kind == Factor::DiagFx) ? Jx_ : Jq_;
  if (f.kind == Factor::DetFx || f.kind == Factor::DetFq) det(J, n_, out);
  else out = J[f.arg * n_ + f.arg];
  return out.bounded();
}

// The checker's own preconditioner for J (format 3 records none): the approximate inverse
// of its midpoint, in own_; nullptr when that is singular.
const double* Prover::own_preconditioner(const std::vector<Ival>& J) {
  M_.resize(size_t(n_) * n_);
  for (size_t k = 0; k < M_.size(); ++k) M_[k] = 0.5 * (J[k].lo() + J[k].hi());
  return invert(M_, n_, own_) ? own_.data() : nullptr;
}

// Hansen–Sengupta contraction of the commands of b (x an interval parameter), with the
// checker's own preconditioner. −1: no solution in b; 0: not applicable; 1: applied.
int Prover::hs_contract(std::vector<Ival>& b) {
  if (!ev_.eval_ad(ev_.all_eqs, b.data(), cmd_mask_)) return 0;  // f must be C¹ on b
  read_jacobian(m_.command, Jq_);
  const double* C = own_preconditioner(Jq_);
  if (!C) return 0;
  product(Jq_, C, A_);
  std::vector<Ival>& X = X_;
  std::vector<Ival>& c = c_;
  w_ = b;
  for (int j = 0; j < n_; ++j) {  // the centre: a point of b near its middle
    X[j] = b[m_.command[j]];
    mid(c[j], X[j]);
    w_[m_.command[j]] = c[j];
  }
  if (!ev_.eval(ev_.all_eqs, w_.data(), Mode::Proof)) return 0;
  rhs(C);
  for (int i = 0; i < n_; ++i) {
    if (A_[i * n_ + i].has_zero()) continue;
    gs_row(i, X, c);
    sub(t2_, c[i], t1_);
    if (!t2_.nan() && !X[i].meet(t2_)) return -1;
  }
  for (int j = 0; j < n_; ++j) b[m_.command[j]] = X[j];
  return 1;
}

// A Hansen–Sengupta contraction, then HC4 over all equations until no variable shrinks by
// more than 1%, then Hansen–Sengupta again; repeated while either makes progress. False: b
// holds no feasible solution. (Hansen–Sengupta first: the solver's contraction records end
// where its own Hansen–Sengupta step left them, which HC4 alone reaches in many rounds.)
bool Prover::contract(std::vector<Ival>& b) {
  std::vector<double>& w = w1_;
  std::vector<double>& w2 = w2_;
  auto widths = [&](std::vector<double>& out) {
    for (int v = 0; v < nv_; ++v) out[v] = b[v].hi() - b[v].lo();
  };
  auto shrank = [&]() {
    for (int v = 0; v < nv_; ++v)
      if (w2[v] < 0.99 * w[v]) return true;
    return false;
  };
  // Cheapest tests first: a natural evaluation of each equation excluding 0, a constraint
  // False on the box.
  if (!ev_.eval(ev_.all_eqs, b.data(), Mode::Refute)) return false;
  for (int e : m_.eqs)
    if (ev_.val(e).sign()) return false;
  if (ev_.feasible(b.data()) == 0) return false;
  if (hs_contract(b) < 0) return false;
  widths(w);
  for (int round = 0; round < 50; ++round) {
    for (int i = 0; i < n_; ++i)
      if (!ev_.hc4(i, b.data())) return false;
    widths(w2);
    if (!shrank()) {
      if (hs_contract(b) < 0) return false;
      widths(w2);
      if (!shrank()) break;
    }
    w = w2;
  }
  return ev_.feasible(b.data()) != 0;
}

bool Prover::refute_rec(std::vector<Ival>& b, int depth, int& budget) {
  ++refute_boxes;
  if (!contract(b)) return true;
  if (depth >= 12 || budget < 2) return false;
  int v = 0;
  double best = -1;
  for (int k = 0; k < nv_; ++k) {
    double w = b[k].hi() - b[k].lo();
    if (w > best) {
      best = w;
      v = k;
    }
  }
  if (!(best > 0)) return false;
  std::vector<Ival> c = b;
  Ival m;
  mid(m, b[v]);
  copy_end(b[v], Hi, m, Lo);
  copy_end(c[v], Lo, m, Lo);
  budget -= 2;
  return refute_rec(b, depth + 1, budget) && refute_rec(c, depth + 1, budget);
}

bool Prover::refute() {
  ++refutations;
  std::vector<Ival>& b = rb_;
  b = box;
  int budget = 4096 - 1;
  return refute_rec(b, 0, budget);
}

}  // namespace cc
