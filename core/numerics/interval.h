// RAII interval over MPFI's mpfi_t. Every arithmetic operation here is an MPFI
// operation, hence outward rounded: for all a in [a], b in [b], a op b lies in the
// result. Doubles appear only as *exact* inputs (a double is a real number) or as
// outputs rounded in the documented direction (lo_down, hi_up).
#pragma once

#include <mpfi.h>
#include <mpfr.h>

#include <string>
#include <utility>
#include <vector>

#include "numerics/double_interval.h"

namespace aspects {

// Precision (bits) of every interval created after the call on this thread (MPFR keeps it
// per thread): each thread of a run sets it before it makes an interval; intervals keep
// the precision they were created with. How a run computes at 53 bits is
// core/numerics/arithmetic.h.
void set_working_precision(long bits);
long working_precision();

class Interval {
 public:
  Interval() { mpfi_init(v_); }  // MPFI initialises to NaN; callers assign before use
  Interval(double lo, double hi) {
    mpfi_init(v_);
    mpfi_interv_d(v_, lo, hi);
  }
  explicit Interval(double point) {
    mpfi_init(v_);
    mpfi_set_d(v_, point);
  }
  Interval(const Interval& o) {
    mpfi_init2(v_, mpfi_get_prec(o.v_));
    mpfi_set(v_, o.v_);
  }
  Interval(Interval&& o) noexcept {
    mpfi_init2(v_, mpfi_get_prec(o.v_));
    mpfi_swap(v_, o.v_);
  }
  Interval& operator=(const Interval& o) {
    if (this != &o) mpfi_set(v_, o.v_);
    return *this;
  }
  Interval& operator=(Interval&& o) noexcept {
    mpfi_swap(v_, o.v_);
    return *this;
  }
  ~Interval() { mpfi_clear(v_); }

  mpfi_ptr get() { return v_; }
  mpfi_srcptr get() const { return v_; }

  // Enclosure of a decimal (or hex) literal: never goes through a double.
  static bool from_string(Interval& out, const std::string& text);

  double lo_down() const;  // largest double <= left endpoint
  double hi_up() const;    // smallest double >= right endpoint
  double mid() const;      // a double inside the interval (for choices only)
  double width_up() const; // upper bound on the width
  bool empty() const { return mpfi_is_empty(v_) || mpfi_nan_p(v_); }
  bool bounded() const { return mpfi_bounded_p(v_); }
  bool contains_zero() const { return mpfi_has_zero(v_); }
  bool certainly_pos() const { return mpfi_is_strictly_pos(v_) > 0; }
  bool certainly_neg() const { return mpfi_is_strictly_neg(v_) > 0; }
  bool contains(double x) const { return mpfi_is_inside_d(x, v_) > 0; }
  bool contains(const Interval& o) const { return mpfi_is_inside(o.v_, v_) > 0; }
  // o lies in the topological interior of *this.
  bool strictly_contains(const Interval& o) const;
  bool overlaps(const Interval& o) const;

  // this = this ∩ o; returns false when the intersection is empty.
  bool intersect(const Interval& o);
  void set_hull(double lo, double hi) { mpfi_interv_d(v_, lo, hi); }
  void set_point(double x) { mpfi_set_d(v_, x); }
  void set_entire();

  std::string str() const;

 private:
  mpfi_t v_;
};

// The ends as doubles, rounded outward: a superset, exactly the interval at 53 bits.
inline DInterval to_dinterval(const Interval& x) { return {x.lo_down(), x.hi_up()}; }

// Sign of an interval known to exclude zero: +1, -1, or 0 when it may vanish.
inline int certain_sign(const Interval& a) {
  return a.certainly_pos() ? 1 : a.certainly_neg() ? -1 : 0;
}

// Interval vector; variables in model order.
using Box = std::vector<Interval>;

// Dense matrix, row major: of Interval (IMatrix) or of DInterval (DMatrix, 53 bits).
template <class T>
class Matrix {
 public:
  Matrix() = default;
  Matrix(int rows, int cols) : rows_(rows), cols_(cols), a_(size_t(rows) * cols) {}
  int rows() const { return rows_; }
  int cols() const { return cols_; }
  T& operator()(int i, int j) { return a_[size_t(i) * cols_ + j]; }
  const T& operator()(int i, int j) const { return a_[size_t(i) * cols_ + j]; }

 private:
  int rows_ = 0, cols_ = 0;
  std::vector<T> a_;
};
using IMatrix = Matrix<Interval>;
using DMatrix = Matrix<DInterval>;

// max width over the box (upper bound).
double box_width(const Box& b);

}  // namespace aspects
