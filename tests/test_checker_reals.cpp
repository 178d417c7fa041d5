// check_cert's reader of reals (certificates/checker/cert_reader.cpp, parse_real) against
// its definition in certificates/FORMAT.md: a field is a real exactly when printf("%a")
// of strtod(field) gives the field back, and its value is strtod's. Checked on the %a form
// of random doubles of every class and on random edits of them. (Seen failing when the
// reader accepted "p-0" as an exponent, and when it took 14 fraction digits.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "../certificates/checker/checker.h"

namespace {

// The definition: accepted (and its value) or not.
bool reference(const std::string& s, double& v) {
  v = std::strtod(s.c_str(), nullptr);
  char back[64];
  std::snprintf(back, sizeof back, "%a", v);
  return std::isfinite(v) && s == back;
}

bool reader(const std::string& s, double& v) {
  try {
    v = cc::parse_real(s, 1);
    return true;
  } catch (const cc::CertError&) {
    return false;
  }
}

double random_double(std::mt19937_64& rng) {
  uint64_t bits = rng();
  switch (rng() % 4) {
    case 0: bits &= 0x800fffffffffffffULL; break;                    // subnormal or zero
    case 1: bits &= 0x8000000000000000ULL | (rng() % 16) << 48; break;  // short fraction
    default: break;
  }
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return std::isfinite(x) ? x : 1.5;
}

TEST(CheckerReals, ReaderAcceptsExactlyThePrintedForm) {
  std::mt19937_64 rng(17);
  const std::string alphabet = "0123456789abcdefABCDEFxXp+-. ";
  long accepted = 0, refused = 0;
  for (int trial = 0; trial < 400000; ++trial) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", random_double(rng));
    std::string s = buf;
    for (int edits = int(rng() % 3); edits > 0 && !s.empty(); --edits) {
      const size_t at = rng() % (s.size() + 1);
      const char c = alphabet[rng() % alphabet.size()];
      switch (rng() % 3) {
        case 0: s.insert(s.begin() + long(at), c); break;
        case 1: if (at < s.size()) s.erase(at, 1); break;
        default: if (at < s.size()) s[at] = c; break;
      }
    }
    if (s.empty() || s.find(' ') != std::string::npos) continue;  // not a field
    double want = 0, got = 0;
    const bool ok = reference(s, want);
    ASSERT_EQ(reader(s, got), ok) << s;
    if (ok) {
      EXPECT_EQ(std::memcmp(&got, &want, sizeof got), 0) << s;
      ++accepted;
    } else {
      ++refused;
    }
  }
  EXPECT_GT(accepted, 100000);
  EXPECT_GT(refused, 100000);
  for (const char* s : {"0x0p+0", "-0x0p+0", "0x1p+0", "0x0.0000000000001p-1022",
                        "0x1.fffffffffffffp+1023", "0x1p-1022", "0x0.fffffffffffffp-1022"}) {
    double v = 0, w = 0;
    EXPECT_TRUE(reader(s, v) && reference(s, w) && v == w) << s;
  }
  for (const char* s : {"0x1p-0", "0x1.0p+0", "0x1.10p+0", "0x0p-0", "0x0.1p+0", "0x1p+01",
                        "0x1.00000000000000p+0", "0x1p+1024", "0x2p+0", "inf", "nan", "1.0"}) {
    double v = 0;
    EXPECT_FALSE(reader(s, v)) << s;
  }
}

}  // namespace
