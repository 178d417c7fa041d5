#include "model/exact_period.h"

#include <gmp.h>

#include <algorithm>
#include <unordered_set>
#include <vector>

namespace aspects {

namespace {

// a·π + b, exact.
struct PiAffine {
  mpq_t a, b;
  bool known = false;
  PiAffine() {
    mpq_init(a);
    mpq_init(b);
  }
  ~PiAffine() {
    mpq_clear(a);
    mpq_clear(b);
  }
  PiAffine(const PiAffine&) = delete;
  PiAffine& operator=(const PiAffine&) = delete;
};

// The exact value of a decimal literal as the lexer reads it: digits with at most one
// '.', then optionally e or E, an optional sign and digits.
bool decimal_value(const std::string& text, mpq_t out) {
  std::string digits;
  long fraction_digits = 0;
  bool after_point = false;
  size_t i = 0;
  for (; i < text.size() && text[i] != 'e' && text[i] != 'E'; ++i) {
    if (text[i] == '.') {
      after_point = true;
      continue;
    }
    digits += text[i];
    if (after_point) ++fraction_digits;
  }
  long exponent = 0;
  if (i < text.size()) {
    std::string e = text.substr(i + 1);
    if (e.size() > 7) return false;  // |exponent| < 10^6 keeps the rational small
    exponent = std::stol(e);
  }
  long scale = exponent - fraction_digits;
  if (digits.empty() || digits.size() > 10000 || scale > 10000 || scale < -10000) return false;
  mpz_t power;
  mpz_init(power);
  mpz_ui_pow_ui(power, 10, static_cast<unsigned long>(scale < 0 ? -scale : scale));
  mpz_set_str(mpq_numref(out), digits.c_str(), 10);
  mpz_set_ui(mpq_denref(out), 1);
  if (scale >= 0)
    mpz_mul(mpq_numref(out), mpq_numref(out), power);
  else
    mpz_set(mpq_denref(out), power);
  mpq_canonicalize(out);
  mpz_clear(power);
  return true;
}

size_t size_in_bits(const mpq_t q) {
  return mpz_sizeinbase(mpq_numref(q), 2) + mpz_sizeinbase(mpq_denref(q), 2);
}

}  // namespace

bool exactly_one_period(const Dag& dag, const ConstantMeanings& meanings, int lo, int hi) {
  // The nodes the two bounds use, in increasing ids (children before parents). Found by a
  // walk from the bounds, not a scan of every id below them: the parser calls this once per
  // periodic variable, and the DAG may already hold a large model.
  std::vector<int> used{lo, hi}, stack{lo, hi};
  std::unordered_set<int> seen{lo, hi};
  while (!stack.empty()) {
    const Node& n = dag.node(stack.back());
    stack.pop_back();
    for (int c : {n.a, n.b})
      if (c >= 0 && seen.insert(c).second) {
        used.push_back(c);
        stack.push_back(c);
      }
  }
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  auto slot = [&](int id) {
    return size_t(std::lower_bound(used.begin(), used.end(), id) - used.begin());
  };
  std::vector<PiAffine> value(used.size());
  size_t budget = size_t(1) << 24;  // bits of rationals in all
  for (size_t i = 0; i < used.size(); ++i) {
    const int id = used[i];
    const Node& n = dag.node(id);
    PiAffine& r = value[i];
    const PiAffine* x = n.a >= 0 ? &value[slot(n.a)] : nullptr;
    const PiAffine* y = n.b >= 0 ? &value[slot(n.b)] : nullptr;
    if ((x && !x->known) || (y && !y->known)) continue;
    switch (n.op) {
      case Op::Const: {
        auto it = meanings.find(id);
        if (it == meanings.end() || it->second.empty()) break;
        if (it->second == "pi")
          mpq_set_ui(r.a, 1, 1);
        else if (!decimal_value(it->second, r.b))
          break;
        r.known = true;
        break;
      }
      case Op::Add:
        mpq_add(r.a, x->a, y->a);
        mpq_add(r.b, x->b, y->b);
        r.known = true;
        break;
      case Op::Sub:
        mpq_sub(r.a, x->a, y->a);
        mpq_sub(r.b, x->b, y->b);
        r.known = true;
        break;
      case Op::Neg:
        mpq_neg(r.a, x->a);
        mpq_neg(r.b, x->b);
        r.known = true;
        break;
      case Op::Mul: {
        // One factor must be rational: π² is not of the form.
        const PiAffine* rational = mpq_sgn(y->a) == 0 ? y : mpq_sgn(x->a) == 0 ? x : nullptr;
        if (!rational) break;
        const PiAffine* other = rational == y ? x : y;
        mpq_mul(r.a, other->a, rational->b);
        mpq_mul(r.b, other->b, rational->b);
        r.known = true;
        break;
      }
      case Op::Div:
        if (mpq_sgn(y->a) != 0 || mpq_sgn(y->b) == 0) break;  // by a nonzero rational only
        mpq_div(r.a, x->a, y->b);
        mpq_div(r.b, x->b, y->b);
        r.known = true;
        break;
      default:
        break;
    }
    if (!r.known) continue;
    size_t bits = size_in_bits(r.a) + size_in_bits(r.b);
    if (bits > budget) return false;
    budget -= bits;
  }
  const PiAffine &low = value[slot(lo)], &high = value[slot(hi)];
  if (!low.known || !high.known) return false;
  PiAffine width;
  mpq_sub(width.a, high.a, low.a);
  mpq_sub(width.b, high.b, low.b);
  return mpq_cmp_ui(width.a, 2, 1) == 0 && mpq_sgn(width.b) == 0;
}

}  // namespace aspects
