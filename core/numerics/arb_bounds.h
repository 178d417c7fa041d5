// Rigorous double bounds of elementary functions at a double point, from Arb (FLINT's
// ball arithmetic). The point is exact (a double); Arb returns a ball that contains the
// value, and its ends rounded outward to doubles are the bounds: lo <= f(t) <= hi, in
// practice the two doubles around f(t). At 53 bits this replaces MPFR's correctly rounded
// functions, several times slower (bench/RESULTS.md, "Arb for sin, cos, asin and acos").
#pragma once

#include <memory>

namespace aspects {

class ArbBounds {
 public:
  ArbBounds();
  ~ArbBounds();
  ArbBounds(const ArbBounds&);  // fresh scratch: nothing is shared
  ArbBounds& operator=(const ArbBounds&) { return *this; }

  void sin_cos(double t, double& s_lo, double& s_hi, double& c_lo, double& c_hi);
  // For t in [−1, 1]; outside, the bounds are NaN.
  void asin(double t, double& lo, double& hi);
  void acos(double t, double& lo, double& hi);

 private:
  struct Balls;  // Arb's scratch, in the .cpp: users need not see arb.h
  std::unique_ptr<Balls> b_;
};

}  // namespace aspects
