// count_connected.cpp — trusted core: what proves a count's upper bound (count_check.h):
// pieces connected as a graph over a chart's U, or by the star-shaped test re-run here with
// implicit gradients (second derivatives from derivative.cpp); joined adjacencies (a point,
// or a bridge chart); the upper bound from them.
#include "count_check.h"

namespace cc {

// ---------------------------------------------------------------- connected pieces and joins

// Non-periodic variables of b lie in the root cell (V ∩ b is then the graph itself, not a
// part of it outside D).
bool CountCheck::inside_root(const Box& b) const {
  for (int v = 0; v < nv_; ++v)
    if (!c_.periodic[v] && !within(c_.root[2 * v], c_.root[2 * v + 1], b[2 * v], b[2 * v + 1]))
      return false;
  return true;
}

// The graph of the cell's chart may cross the lower (upper) face of its box's w_j: the chart's
// image reaches beyond it, and the closed slab of U × (W̃ ∩ image) beyond the face is not
// refuted (the solver's image and the checker's differ in the last bits at such an end).
bool CountCheck::crosses(const Cell& cell, int j, bool upper) {
  const int v = cell.w[j];
  const double face = cell.box[2 * v + upper];
  if (upper ? cmp(cell.range[j], Hi, face) <= 0 : cmp(cell.range[j], Lo, face) >= 0) return false;
  Box slab = cell.box;
  for (int k = 0; k < n_; ++k) {
    Ival x;
    x.set(cell.w_tilde[2 * k], cell.w_tilde[2 * k + 1]);
    if (!x.meet(cell.range[k])) return false;  // no solution at all
    put(slab, cell.w[k], x.lo(), x.hi());
  }
  if (upper ? face >= slab[2 * v + 1] : face <= slab[2 * v]) return true;
  if (upper) slab[2 * v] = face;
  else slab[2 * v + 1] = face;
  return !refute(slab);
}

// A fit's box whose chart's image lies in its w, inside the root cell, every factor of the
// class's sign on it: W_s ∩ box = V ∩ box is the graph of the continuous w over U, connected
// and nonempty.
bool CountCheck::graph(const Cell& cell, Mask cls) {
  if (cell.w.empty() || !inside_root(cell.box)) return false;
  for (int j = 0; j < n_; ++j)
    if (crosses(cell, j, false) || crosses(cell, j, true)) return false;
  std::vector<Ival> g;
  if (!factors(ivals(cell.box), g)) return false;
  for (int i = 0; i < c_.p; ++i)
    if (g[i].sign() != ((cls >> i) & 1 ? 1 : -1)) return false;
  return feasible(ivals(cell.box));  // the whole graph feasible
}

// ∂g_i/∂x_v for every factor i over b, from the Jacobian's nodes and their AD: for a
// determinant, Σ_r det(J with row r replaced by ∂J_r/∂x_v) (Jacobi's formula).
bool CountCheck::factor_gradients(const std::vector<Ival>& b,
                                  std::vector<std::vector<Ival>>& grad) {
  if (!dm_) {
    dm_.reset(new Model(c_.m));
    jn_ = jacobian_nodes(*dm_);
    std::vector<int> roots;
    for (const auto& row : jn_)
      for (int e : row) {
        if (e < 0) jn_ok_ = false;
        else roots.push_back(e);
      }
    jprog_ = closure(*dm_, roots);
    dev_.reset(new Evaluator(*dm_));
  }
  if (!jn_ok_) return false;
  dev_->work_limit = c_.work_limit();
  if (!dev_->eval_ad(jprog_, b.data(), ~uint64_t(0) >> (64 - nv_))) return false;
  const int n = n_;
  grad.assign(c_.p, std::vector<Ival>(nv_));
  std::vector<Ival> M(size_t(n) * n);
  for (int i = 0; i < c_.p; ++i) {
    const Factor& f = c_.factors[i];
    const bool fx = f.kind == Factor::DetFx || f.kind == Factor::DiagFx;
    const std::vector<int>& cols = fx ? c_.m.pose : c_.m.command;
    for (int t = 0; t < nv_; ++t) {
      if (f.kind == Factor::DiagFx || f.kind == Factor::DiagFq) {
        grad[i][t] = dev_->der(jn_[f.arg][cols[f.arg]], t);
        continue;
      }
      set_si(grad[i][t], 0);
      Ival term;
      for (int r = 0; r < n; ++r) {
        for (int a = 0; a < n; ++a)
          for (int c = 0; c < n; ++c)
            M[a * n + c] = a == r ? dev_->der(jn_[a][cols[c]], t) : dev_->val(jn_[a][cols[c]]);
        det(M, n, term);
        add(grad[i][t], grad[i][t], term);
      }
      if (!grad[i][t].bounded()) return false;
    }
  }
  return true;
}

// X = (∂_w f)^{-1} ∂_u f over b (n×n, row major; dw/du = −X), by a verified solve: with C
// an approximate inverse of mid ∂_w f, A = C·∂_w f, B = C·∂_u f, E = I − A and β = ‖E‖_∞ < 1,
// every point of b has X = B + E·X, so ‖X_{·k}‖_∞ ≤ ρ_k = max_l |B_lk| / (1 − β) and X_jk ∈
// B_jk + Σ_l E_jl·[−ρ_k, ρ_k]. β < 1 also proves ∂_w f regular on b (w is C¹ there).
bool CountCheck::implicit_jacobian(const std::vector<Ival>& b, const std::vector<int>& w,
                                   std::vector<Ival>& X) {
  Evaluator& ev = *c_.ev;
  const int n = n_;
  std::vector<int> u;
  for (int v = 0; v < nv_; ++v)
    if (std::find(w.begin(), w.end(), v) == w.end()) u.push_back(v);
  limit();
  if (!ev.eval_ad(ev.all_eqs, b.data(), ~uint64_t(0) >> (64 - nv_))) return false;
  std::vector<double> M(size_t(n) * n), C;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Ival& d = ev.der(c_.m.eqs[i], w[j]);
      M[i * n + j] = 0.5 * (d.lo() + d.hi());
    }
  if (!invert(M, n, C)) return false;
  std::vector<Ival> E(size_t(n) * n), B(size_t(n) * n);
  Ival t, beta, row;
  set_si(beta, 0);
  for (int i = 0; i < n; ++i) {
    set_si(row, 0);
    for (int j = 0; j < n; ++j) {
      set_si(E[i * n + j], i == j ? 1 : 0);
      set_si(B[i * n + j], 0);
      for (int k = 0; k < n; ++k) {
        mul_d(t, ev.der(c_.m.eqs[k], w[j]), C[i * n + k]);
        sub(E[i * n + j], E[i * n + j], t);
        mul_d(t, ev.der(c_.m.eqs[k], u[j]), C[i * n + k]);
        add(B[i * n + j], B[i * n + j], t);
      }
      abs(t, E[i * n + j]);
      add(row, row, t);
    }
    max(beta, beta, row);
  }
  Ival gap;  // 1 − β
  si_sub(gap, 1, beta);
  if (gap.sign() <= 0) return false;
  X.resize(size_t(n) * n);
  for (int k = 0; k < n; ++k) {
    Ival rho;
    set_si(rho, 0);
    for (int l = 0; l < n; ++l) {
      abs(t, B[l * n + k]);
      max(rho, rho, t);
    }
    div(rho, rho, gap);
    Ival r;
    r.set(-rho.hi(), rho.hi());
    for (int j = 0; j < n; ++j) {
      X[j * n + k] = B[j * n + k];
      for (int l = 0; l < n; ++l) {
        mul(t, E[j * n + l], r);
        add(X[j * n + k], X[j * n + k], t);
      }
      if (!X[j * n + k].bounded()) return false;
    }
  }
  return true;
}

// The star-shaped test (FORMAT.md C4) about the centre v, on the cell's chart: the piece is
// {u ∈ U : φ_i(u) = s_i g_i(u, w(u)) > 0 for the factors not of sign s_i on the whole box,
// ψ(u) ≥ 0 for the faces of the box's w that the chart's image crosses}. The checker paves U
// itself: a part is cleared when a constraint is certainly < 0 on it, or when every
// constraint that case (i) or (ii) needs is certainly > 0 there or has ∇·(part − v)
// certainly < 0; else it is halved (widest u relative to the box, down to 10^-6 of it, at
// most 8192 parts).
bool CountCheck::star(const Cell& cell, Mask cls, const std::vector<int>& w,
                      const std::vector<double>& v, const Box& hint) {
  // The model's constraints on the box (C7): False, or an `or` left with more terms than
  // kMaxTerms: not tested; else the piece is the union over the terms of the graph over
  // {u : the factors, the faces and the term's atoms hold}, star-shaped about v when each is.
  Dnf terms;
  const Reduced reduced = reduce(ivals(cell.box), terms);
  if (reduced == Reduced::False || (reduced == Reduced::Disjunction && terms.empty())) return false;
  if (reduced == Reduced::True) terms = {{}};
  for (const std::vector<int>& atoms : terms)
    if (!star_term(cell, cls, w, v, hint, atoms)) return false;
  return true;
}

// One term: the star-shaped test with the term's atoms (formula ids) among the constraints.
bool CountCheck::star_term(const Cell& cell, Mask cls, const std::vector<int>& w,
                           const std::vector<double>& v, const Box& hint,
                           const std::vector<int>& atoms) {
  if (cell.w.empty() || w != cell.w || !inside_root(cell.box)) return false;
  std::vector<int> uv;
  for (int x = 0; x < nv_; ++x)
    if (std::find(w.begin(), w.end(), x) == w.end()) uv.push_back(x);
  struct Constraint {
    int kind;  // 0 factor, 1 lower face, 2 upper face, 3 strict atom, 4 closed atom
    int index;  // the factor, the chart's w_j, or the atom's formula
    bool strict() const { return kind == 0 || kind == 3; }
  };
  std::vector<Constraint> cs;
  std::vector<Ival> g;
  const bool on_box = factors(ivals(cell.box), g);
  for (int i = 0; i < c_.p; ++i)
    if (!on_box || g[i].sign() != ((cls >> i) & 1 ? 1 : -1)) cs.push_back({0, i});
  for (int j = 0; j < n_; ++j) {
    if (crosses(cell, j, false)) cs.push_back({1, j});
    if (crosses(cell, j, true)) cs.push_back({2, j});
  }
  // Each atom of the term is one more constraint, strict or closed.
  for (int f : atoms) cs.push_back({c_.m.formulas[f].strict ? 3 : 4, f});
  auto atom_values = [&](const std::vector<Ival>& b) {
    limit();
    return c_.ev->eval(c_.ev->all_atoms, b.data(), Mode::Proof);
  };
  if (!atoms.empty()) {
    // Continuous on the graph over U: every atom defined on U × (W̃ ∩ the chart's image).
    std::vector<Ival> all = ivals(cell.box);
    for (int j = 0; j < n_; ++j) {
      all[w[j]].set(cell.w_tilde[2 * j], cell.w_tilde[2 * j + 1]);
      if (!all[w[j]].meet(cell.range[j])) return false;
    }
    if (!atom_values(all)) return false;
  }
  // The centre: a point of the piece with every constraint > 0 there.
  std::vector<Ival> wv;
  if (!point(cell.box, w, v, hint, cls, &wv)) return false;
  for (const Constraint& c : cs) {
    const int x = c.kind == 1 || c.kind == 2 ? w[c.index] : 0;
    if (c.kind == 1 && cmp(wv[c.index], Lo, cell.box[2 * x]) <= 0) return false;
    if (c.kind == 2 && cmp(wv[c.index], Hi, cell.box[2 * x + 1]) >= 0) return false;
  }
  if (!atoms.empty()) {
    std::vector<Ival> at(nv_);
    for (int k = 0; k < n_; ++k) at[uv[k]].set(v[k], v[k]);
    for (int j = 0; j < n_; ++j) at[w[j]] = wv[j];
    if (!atom_values(at)) return false;
    for (const Constraint& c : cs)
      if (c.kind >= 3 && c_.ev->val(c_.m.formulas[c.index].expr).sign() <= 0) return false;
  }
  std::vector<Box> stack{cell.box};
  long parts = 0;
  std::vector<Ival> y, X, psi(cs.size());
  std::vector<std::vector<Ival>> grad;
  Ival t, d;
  while (!stack.empty()) {
    Box z = std::move(stack.back());
    stack.pop_back();
    if (++parts > kStarParts) return false;
    // w over the part: in W̃ (unique) and in every image of the step on part × (W̃ ∩ ...).
    std::vector<Ival> b = ivals(z);
    if (!narrow_w(cell, b)) continue;  // no point of the graph over this part
    const bool defined = factors(b, g);
    const bool atoms_defined = !atoms.empty() && atom_values(b);
    bool negative = false, strict_can_be_positive = true;
    for (size_t k = 0; k < cs.size(); ++k) {
      const Constraint& c = cs[k];
      if (c.kind == 0) {
        if (!defined) {
          psi[k].entire();
          continue;
        }
        psi[k] = g[c.index];
        if (!((cls >> c.index) & 1)) neg(psi[k], psi[k]);
        if (psi[k].end_sign(Hi) <= 0) strict_can_be_positive = false;
      } else if (c.kind >= 3) {
        if (!atoms_defined) {
          psi[k].entire();
          continue;
        }
        psi[k] = c_.ev->val(c_.m.formulas[c.index].expr);
        if (c.kind == 3 && psi[k].end_sign(Hi) <= 0) strict_can_be_positive = false;
      } else {
        const double bound = cell.box[2 * w[c.index] + (c.kind == 2)];
        t.set(bound, bound);
        if (c.kind == 1) sub(psi[k], b[w[c.index]], t);
        else sub(psi[k], t, b[w[c.index]]);
      }
      negative = negative || psi[k].sign() < 0;
    }
    if (negative) continue;
    bool cleared = true, have_x = false, x_ok = false, have_g = false, g_ok = false;
    for (size_t k = 0; k < cs.size() && cleared; ++k) {
      const Constraint& c = cs[k];
      if (!c.strict() && !strict_can_be_positive) continue;  // case (ii) impossible here
      if (psi[k].sign() > 0) continue;                  // ≠ 0 on the part
      if (!have_x) have_x = true, x_ok = implicit_jacobian(b, w, X);
      cleared = false;
      if (!x_ok) break;
      std::vector<Ival> gr(n_);
      if (c.kind == 0) {
        if (!have_g) have_g = true, g_ok = factor_gradients(b, grad);
        if (!g_ok) break;
        const bool positive = (cls >> c.index) & 1;
        for (int k2 = 0; k2 < n_; ++k2) {  // ∂_u g − ∂_w g·X, times s_i
          gr[k2] = grad[c.index][uv[k2]];
          for (int j = 0; j < n_; ++j) {
            mul(t, grad[c.index][w[j]], X[j * n_ + k2]);
            sub(gr[k2], gr[k2], t);
          }
          if (!positive) neg(gr[k2], gr[k2]);
        }
      } else if (c.kind >= 3) {
        // ∂_u g − ∂_w g·X, by the checker's AD of the atom's expression (none where it is
        // not differentiable: min, max, abs at 0).
        limit();
        if (!c_.ev->eval_ad(c_.ev->all_atoms, b.data(), ~uint64_t(0) >> (64 - nv_))) break;
        const int e = c_.m.formulas[c.index].expr;
        for (int k2 = 0; k2 < n_; ++k2) {
          gr[k2] = c_.ev->der(e, uv[k2]);
          for (int j = 0; j < n_; ++j) {
            mul(t, c_.ev->der(e, w[j]), X[j * n_ + k2]);
            sub(gr[k2], gr[k2], t);
          }
        }
      } else {
        for (int k2 = 0; k2 < n_; ++k2) {  // ∇w_j = −X_j·
          gr[k2] = X[c.index * n_ + k2];
          if (c.kind == 1) neg(gr[k2], gr[k2]);
        }
      }
      set_si(d, 0);
      for (int k2 = 0; k2 < n_; ++k2) {
        t.set(v[k2], v[k2]);
        Ival du;
        sub(du, b[uv[k2]], t);
        mul(t, gr[k2], du);
        add(d, d, t);
      }
      cleared = d.sign() < 0;
    }
    if (cleared) continue;
    if (!halve_widest_u(cell, uv, 1e-8, std::move(z), stack)) return false;
  }
  return true;
}

// joined A B CLASS SHIFT point W U HINT | bridge W W~: a point of W_s in A ∩ (B + 2πk)
// (the ends of B + 2πk rounded inward), or a bridge: with C the hull of A and B + 2πk (ends
// rounded outward), the step on C_u × W̃ (W̃ ⊇ C_w) has its image H in int W̃ and, on a
// non-periodic w, in the root cell, and every factor has the class's sign on C_u × H: V ∩ C
// is then the graph of w over C_u ∩ the root, connected, in W_s, holding both pieces.
void CountCheck::joined() {
  const long a = c_.index(cells_.size());
  const long b = c_.index(cells_.size());
  const Mask cls = class_field();
  if (!(a < b)) reject("joined needs A < B");
  for (long x : {a, b})
    if (cells_[x].state != State::Live) reject("joined: a cell that is not in the final cover");
  const std::string_view shift = c_.rd.word();
  if (shift.size() != size_t(nv_) || shift.find_first_not_of("-0+") != shift.npos)
    malformed(rec(), "bad SHIFT field");
  const std::string how(c_.rd.word());
  if (how == "point") c_.rd.count(6 + 4 * size_t(n_));
  else if (how == "bridge") c_.rd.count(6 + 3 * size_t(n_));
  else malformed(rec(), "joined: unknown proof '" + how + "'");
  const std::vector<int> w = chart_vars();
  Box inner = cells_[a].box, hull = cells_[a].box;
  Ival t;
  for (int v = 0; v < nv_; ++v) {
    const int k = shift[v] == '-' ? -1 : shift[v] == '+' ? 1 : 0;
    if (k && !c_.periodic[v]) reject("joined: a shift on a variable that is not periodic");
    double lo = cells_[b].box[2 * v], hi = cells_[b].box[2 * v + 1];
    double ilo = lo, ihi = hi, olo = lo, ohi = hi;
    if (k) {
      shift_by_periods(t, c_.ev->two_pi, k, lo);
      ilo = t.hi(), olo = t.lo();
      shift_by_periods(t, c_.ev->two_pi, k, hi);
      ihi = t.lo(), ohi = t.hi();
    }
    put(inner, v, std::max(inner[2 * v], ilo), std::min(inner[2 * v + 1], ihi));
    put(hull, v, std::min(hull[2 * v], olo), std::max(hull[2 * v + 1], ohi));
  }
  if (how == "point") {
    const std::vector<double> u = c_.rd.reals(n_);
    const Box hint = reals_box(n_);
    for (int v = 0; v < nv_; ++v)
      if (!(inner[2 * v] <= inner[2 * v + 1])) reject("joined: the boxes do not meet");
    if (!point(inner, w, u, hint, cls)) reject("joined: no point of the class proved in both boxes");
  } else {
    const Box wt = reals_box(n_);
    std::vector<Ival> box = ivals(hull), y;
    for (int j = 0; j < n_; ++j) {
      const int v = w[j];
      if (!within(wt[2 * j], wt[2 * j + 1], hull[2 * v], hull[2 * v + 1]))
        reject("joined: the bridge's W~ does not hold the hull");
      box[v].set(wt[2 * j], wt[2 * j + 1]);
    }
    if (hansen_sengupta(box, w, y) != Hs::Image) reject("joined: the bridge's chart fails");
    for (int j = 0; j < n_; ++j) {
      const int v = w[j];
      if (!inside(y[j], wt[2 * j], wt[2 * j + 1], true))
        reject("joined: the bridge's image is not inside the interior of W~");
      if (!c_.periodic[v] && !inside(y[j], c_.root[2 * v], c_.root[2 * v + 1], false))
        reject("joined: the bridge's graph leaves the domain");
      box[v] = y[j];
    }
    std::vector<Ival> g;
    if (!factors(box, g)) reject("joined: a factor is not defined on the bridge");
    for (int i = 0; i < c_.p; ++i)
      if (g[i].sign() != ((cls >> i) & 1 ? 1 : -1))
        reject("joined: a factor's sign on the bridge is not the class's");
    if (!feasible(box)) reject("joined: a constraint is not True on the bridge");
  }
  joined_[{a, b}] |= Mask(1) << cls;
}

// The graph H of FORMAT.md (C6): per class, the same nodes as the lower bound's, joined by the
// verified joins. −1 unless every node's piece is proved connected.
long CountCheck::upper_bound() {
  const int classes = 1 << c_.p;
  std::vector<long> index(cells_.size(), -1);
  std::vector<Mask> nodes;
  long m = 0;
  for (size_t id = 0; id < cells_.size(); ++id) {
    const Cell& cell = cells_[id];
    if (cell.state != State::Live) continue;
    index[id] = m++;
    const Mask all = (c_.p >= 6 ? ~Mask(0) : (Mask(1) << classes) - 1);
    const Mask node = all & ~(excluded(cell.box) | excluded(cell.origin)) & ~cell.empty;
    if (node & ~cell.connected) {
      for (int s = 0; s < classes; ++s)
        if ((node & ~cell.connected) >> s & 1)
          upper_open_ = "the piece of class " + std::to_string(s) + " of cell " +
                        std::to_string(id) + " is not proved connected";
      return -1;
    }
    nodes.push_back(node);
  }
  std::vector<UnionFind> uf(classes);
  for (UnionFind& u : uf) u.reset(size_t(m));
  for (const auto& e : joined_)
    for (int s = 0; s < classes; ++s)
      if ((e.second >> s & 1) && (nodes[index[e.first.first]] >> s & 1) &&
          (nodes[index[e.first.second]] >> s & 1))
        uf[s].unite(int(index[e.first.first]), int(index[e.first.second]));
  long bound = 0;
  for (int s = 0; s < classes; ++s)
    for (long i = 0; i < m; ++i)
      if ((nodes[i] >> s & 1) && uf[s].find(int(i)) == int(i)) ++bound;
  return bound;
}

}  // namespace cc
