#include "results/pose.h"

#include <cmath>
#include <cstdio>

#include "results/number_text.h"
#include "results/usage_error.h"

namespace aspects {

namespace {

std::string pose_names(const Model& m) {
  std::string s;
  for (size_t j = 0; j < m.pose.size(); ++j) s += (j ? "," : "") + m.vars[m.pose[j]].name;
  return s;
}

}  // namespace

std::vector<double> parse_pose(const std::string& text, const std::string& option,
                               const Model& model) {
  const std::string usage = option + " expects " + std::to_string(model.pose.size()) +
                            " numbers separated by commas (" + pose_names(model) + ")";
  std::vector<double> pose;
  size_t start = 0;
  while (true) {
    size_t comma = text.find(',', start);
    std::string item = text.substr(start, comma == std::string::npos ? comma : comma - start);
    double x = 0;
    const NumberText outcome = parse_number(item, x);
    if (outcome != NumberText::Finite)
      throw UsageError(usage + ", got '" + text + "' (" + number_problem(outcome, item) + ")");
    pose.push_back(x);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (pose.size() != model.pose.size())
    throw UsageError(usage + ", got " + std::to_string(pose.size()) + " in '" + text + "'");
  for (size_t j = 0; j < pose.size(); ++j) {
    const Variable& v = model.vars[model.pose[j]];
    if (v.periodic && std::fabs(pose[j]) > kMaxPeriodicCoordinate)
      throw UsageError(option + ": " + v.name + " is periodic; give it within +-1e6");
    if (v.periodic) continue;
    if (!v.domain.contains(pose[j])) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "%s: %s = %.17g is outside its declared domain [%.17g, %.17g]",
                    option.c_str(), v.name.c_str(), pose[j], v.domain.lo_down(), v.domain.hi_up());
      throw UsageError(buf);
    }
  }
  return pose;
}

int shifted_sign(double p, long k, double b, mpfr_prec_t max_prec) {
  // In double first: the rounding error of d (2π rounded, a product, two sums) is below
  // 9 units of 2^-53 times 7|k| + |p| + |b|.
  const double d = p + double(k) * (2 * M_PI) - b;
  const double err = 1e-15 * (7 * std::fabs(double(k)) + std::fabs(p) + std::fabs(b));
  if (d > err) return 1;
  if (d < -err) return -1;
  mpfr_t gap, lo, hi;  // b − p exactly (2200 bits hold the difference of any two doubles)
  mpfr_init2(gap, 2200);
  mpfr_set_d(gap, b, MPFR_RNDN);
  mpfr_sub_d(gap, gap, p, MPFR_RNDN);
  int sign = 0;
  for (mpfr_prec_t prec = 128; sign == 0 && prec <= max_prec; prec *= 2) {
    mpfr_inits2(prec, lo, hi, static_cast<mpfr_ptr>(nullptr));
    mpfr_const_pi(lo, MPFR_RNDD);
    mpfr_const_pi(hi, MPFR_RNDU);
    // [lo, hi] ∋ 2πk, rounded outward (k < 0 swaps the ends).
    const bool up = k > 0;
    mpfr_mul_si(lo, lo, 2 * k, up ? MPFR_RNDD : MPFR_RNDU);
    mpfr_mul_si(hi, hi, 2 * k, up ? MPFR_RNDU : MPFR_RNDD);
    if (!up) mpfr_swap(lo, hi);
    if (mpfr_cmp(lo, gap) > 0) sign = 1;
    if (mpfr_cmp(hi, gap) < 0) sign = -1;
    mpfr_clears(lo, hi, static_cast<mpfr_ptr>(nullptr));
  }
  mpfr_clear(gap);
  return sign;
}

Membership coordinate_membership(double p, double lo, double hi, bool periodic, long& turns,
                                 mpfr_prec_t max_prec) {
  turns = 0;
  if (lo <= p && p <= hi) return Membership::Inside;
  if (!periodic) return Membership::Outside;
  // Every k with p + 2πk ∈ [lo, hi] lies in [first, last]: the quotients are within 1 of
  // the exact ones. A periodic box is at most one period wide, so there are a few k.
  const double first = std::ceil((lo - p) / (2 * M_PI)) - 1;
  const double last = std::floor((hi - p) / (2 * M_PI)) + 1;
  if (!(last - first <= 16 && std::fabs(first) < 1e9)) return Membership::Undecided;
  Membership m = Membership::Outside;
  for (long k = long(first); k <= long(last); ++k) {
    if (k == 0) continue;
    const int above_lo = shifted_sign(p, k, lo, max_prec);
    const int below_hi = -shifted_sign(p, k, hi, max_prec);
    if (above_lo > 0 && below_hi > 0) {
      turns = k;
      return Membership::Inside;
    }
    if (above_lo >= 0 && below_hi >= 0) m = Membership::Undecided;  // neither side certain
  }
  return m;
}

namespace {

// Inside when every coordinate is, Outside when one is.
Membership both(Membership a, Membership b) {
  if (a == Membership::Outside || b == Membership::Outside) return Membership::Outside;
  return a == Membership::Inside ? b : Membership::Undecided;
}

}  // namespace

Membership pose_in_box(const Model& m, const std::vector<double>& pose, const double* lo,
                       const double* hi, std::vector<long>* turns) {
  Membership in = Membership::Inside;
  if (turns) turns->assign(pose.size(), 0);
  for (size_t j = 0; j < pose.size() && in != Membership::Outside; ++j) {
    const int v = m.pose[j];
    long k = 0;
    in = both(in, coordinate_membership(pose[j], lo[v], hi[v], m.vars[v].periodic, k));
    if (turns) (*turns)[j] = k;
  }
  return in;
}

Membership pose_in_pose_box(const std::vector<bool>& periodic, const std::vector<double>& pose,
                            const double* lo, const double* hi) {
  Membership in = Membership::Inside;
  for (size_t j = 0; j < pose.size() && in != Membership::Outside; ++j) {
    long k = 0;
    in = both(in, coordinate_membership(pose[j], lo[j], hi[j], periodic[j], k));
  }
  return in;
}

double pose_distance(const std::vector<double>& a, const std::vector<double>& b,
                     const std::vector<bool>& periodic) {
  double s = 0;
  for (size_t j = 0; j < a.size(); ++j) {
    double d = std::fabs(a[j] - b[j]);
    if (periodic[j]) d = std::fabs(std::remainder(d, 2 * M_PI));
    s += d * d;
  }
  return std::sqrt(s);
}

std::string format_pose(const std::vector<double>& pose) {
  std::string s;
  char buf[40];
  for (size_t j = 0; j < pose.size(); ++j) {
    std::snprintf(buf, sizeof buf, "%s%.10g", j ? ", " : "", pose[j]);
    s += buf;
  }
  return "(" + s + ")";
}

std::vector<double> checked_pose(const std::vector<double>& pose, const std::string& what,
                                 const Model& model) {
  if (pose.empty())
    throw UsageError(what + ": give " + std::to_string(model.pose.size()) + " numbers");
  std::string text;
  for (double x : pose) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    text += (text.empty() ? "" : ",") + std::string(buf);
  }
  return parse_pose(text, what, model);
}

}  // namespace aspects
