// eval_speed.cpp — speed layer of the evaluator (Evaluator::speed, off with --trusted-only,
// where every node is computed at every evaluation and MPFI computes sin and cos):
// incremental evaluation, and sin and cos of an interval and the branch inverses of HC4
// from Arb's balls at the interval's ends (rigorous, and at the usual precisions several
// times cheaper than MPFR's correctly rounded functions), with the last ends of each
// argument kept and, on doubles, a table of ends. test_checker_interval: the ends are
// MPFR's, one ulp at most; cert_verdicts.py: the verdicts are the trusted core's.
#include <arb.h>

#include <cmath>
#include <cstring>

#include "checker.h"

namespace cc {

// A variable whose interval differs from the one the last evaluation saw gets a new time.
void Evaluator::note_changes(const Ival* box) {
  for (int v = 0; v < nv(); ++v) {
    Ival& s = seen_[v];
    if (same(s, Lo, box[v], Lo) && same(s, Hi, box[v], Hi)) continue;
    s = box[v];  // NaN ends compare unequal: such a variable is always new
    changed_at_[v] = ++clock_;
  }
}

// A node's value and status are kept when it was computed after the last change of every
// variable it mentions (its value is a function of theirs) and not narrowed by HC4 since.
bool Evaluator::fresh(int id) const {
  const uint64_t t = stamp_[id];
  if (t == 0) return false;
  for (uint64_t d = m_.nodes[id].dep; d; d &= d - 1)
    if (changed_at_[__builtin_ctzll(d)] > t) return false;
  return true;
}

// Enclosures of f(x) (and g(x)) at an end x of an interval, from Arb's balls rounded
// outward to the certificate's precision p. A ball whose rounding is more than one ulp
// wide is recomputed at twice the precision (as MPFR's Ziv loop does), up to 16 p bits: a
// value within a hair of a p-bit number (sin x for tiny x, cos x near 1) would otherwise
// be two ulps wide where MPFR's correctly rounded value and its neighbour are one, and a
// wider enclosure can fail a claim the solver made with little slack.
struct Evaluator::Balls {
  arb_t x, f, g;
  arf_t end;
  const slong p = slong(mpfr_get_default_prec());
  mpfr_t m;  // an end, exactly
  Balls() {
    arb_init(x);
    arb_init(f);
    arb_init(g);
    arf_init(end);
    mpfr_init2(m, std::max<slong>(p, 53));
  }
  ~Balls() {
    arb_clear(x);
    arb_clear(f);
    arb_clear(g);
    arf_clear(end);
    mpfr_clear(m);
  }
  // F := fn's ball f rounded outward, G := its ball g (when given).
  template <class Fn>
  void compute(const Ival& a, End e, Fn fn, Ival& F, Ival* G) {
    if (Ival::doubles) {
      arb_set_d(x, e == Lo ? a.lo() : a.hi());  // exact, without an MPFR number between
    } else {
      get_end(m, a, e);
      arf_set_mpfr(end, m);
      arb_set_arf(x, end);
    }
    for (slong prec = p + 9;; prec *= 2) {
      fn(prec);
      get(f, F);
      if (G) get(g, *G);
      if (prec >= 16 * p || (one_ulp(F) && (!G || one_ulp(*G)))) return;
    }
  }
  // out := the ball b rounded outward; the entire line if b is not finite.
  void get(const arb_t b, Ival& out) {
    for (End e : {Lo, Hi}) {
      if (e == Lo) arb_get_lbound_arf(end, b, 2 * p);
      else arb_get_ubound_arf(end, b, 2 * p);
      if (Ival::doubles) {  // Arb's directed rounding to a double: MPFR's end, cheaper
        out.set_end(e, arf_get_d(end, e == Lo ? ARF_RND_FLOOR : ARF_RND_CEIL));
      } else {
        arf_get_mpfr(m, end, e == Lo ? MPFR_RNDD : MPFR_RNDU);
        set_end(out, e, m);
      }
    }
    if (out.nan()) out.entire();
  }
};

// Widens v (an enclosure of sin or cos on a) to ±1 where an extremum t = (j + off)π may
// lie in a (off = 1/2 for sin, 0 for cos; the value there is (−1)^j). Candidates j come
// from a double computation with a margin of 1; each is confirmed in intervals, and an unsure
// case counts as inside (a sound overestimate).
void Evaluator::extremum(Ival& v, const Ival& a, double off, double lo, double hi) {
  const double PI = 3.141592653589793;
  const double margin = 1e-9 * (1 + std::fabs(lo) + std::fabs(hi));  // ≫ double error
  for (double j = std::floor(lo / PI - off) - 1; j <= std::ceil(hi / PI - off) + 1; ++j) {
    double t = (j + off) * PI;
    if (t < lo - margin || t > hi + margin) continue;
    mul_d(t3_, pi_, j + off);
    if (less(t3_, Hi, a, Lo) || less(a, Hi, t3_, Lo)) continue;
    if (std::fmod(std::fabs(j), 2.0) == 0) v.set_end(Hi, 1);
    else v.set_end(Lo, -1);
  }
}

// sin and cos of an interval: the hull of Arb's enclosures at both ends, widened to ±1
// where an extremum may lie inside. Wide or huge arguments go to MPFI (apply_fn).
void Evaluator::arb_sincos(TrigCache& cache, const Ival& a) {
  Ival& s = cache.sin;
  Ival& c = cache.cos;
  const double lo = a.lo();
  const double hi = a.hi();
  if (!(hi - lo < 6.0) || !(std::fabs(lo) < 1e6) || !(std::fabs(hi) < 1e6)) {
    apply_fn(Fn::Sin, s, a);
    apply_fn(Fn::Cos, c, a);
    return;
  }
  for (End x : {Lo, Hi}) {
    int k = same(cache.end[0], Lo, a, x) ? 0 : same(cache.end[1], Lo, a, x) ? 1 : -1;
    if (k < 0) {  // NaN, the initial end, equals nothing
      k = cache.last ^= 1;
      point(cache.end[k], a, x);
      ends_sin_cos(a, x, cache.end_sin[k], cache.end_cos[k]);
    }
    if (x == Lo) {
      s = cache.end_sin[k];
      c = cache.end_cos[k];
    } else {
      hull(s, s, cache.end_sin[k]);
      hull(c, c, cache.end_cos[k]);
    }
  }
  extremum(s, a, 0.5, lo, hi);
  extremum(c, a, 0.0, lo, hi);
}

// s, c := sin and cos of an end of a. On doubles, remembered in a direct-mapped table: a
// cell's ends are its parent's and its siblings' too.
void Evaluator::ends_sin_cos(const Ival& a, End x, Ival& s, Ival& c) {
  const double t = x == Lo ? a.lo() : a.hi();
  uint64_t key = 0;
  std::memcpy(&key, &t, sizeof t);
  Memo* m = Ival::doubles ? &memo_[(key * 0x9E3779B97F4A7C15ull) >> 54] : nullptr;
  if (m && m->t == t) {  // a NaN end is never found
    s.set(m->s[0], m->s[1]);
    c.set(m->c[0], m->c[1]);
    return;
  }
  Balls& B = balls();
  B.compute(a, x, [&B](slong prec) { arb_sin_cos(B.f, B.g, B.x, prec); }, s, &c);
  if (m) *m = Memo{t, {s.lo(), s.hi()}, {c.lo(), c.hi()}};
}

// out := asin or acos (op Sin or Cos) of r's end e.
void Evaluator::arb_inverse(Op op, const Ival& r, End e, Ival& out) {
  Balls& B = balls();
  B.compute(
      r, e,
      [&B, op](slong prec) {
        if (op == Op::Sin) arb_asin(B.f, B.x, prec);
        else arb_acos(B.f, B.x, prec);
      },
      out, nullptr);
}

Evaluator::Balls& Evaluator::balls() {
  if (!balls_) balls_.reset(new Balls);
  return *balls_;
}

void Evaluator::FreeBalls::operator()(Balls* b) const { delete b; }

}  // namespace cc
