// Where the search streams its certificate records (certificates/FORMAT.md) while it
// runs. The engine only knows this interface; the writer lives in certificates/.
#pragma once

#include <cstdint>
#include <vector>

#include "interval.h"
#include "model.h"

namespace aspects {

struct SolutionProof;

class CertificateSink {
 public:
  virtual ~CertificateSink() = default;
  // Before the search: the root cell and the sign factors.
  virtual void begin(const Box& domain, const std::vector<Factor>& factors) = 0;
  // Tree records, in depth-first preorder.
  virtual void contraction(int var, double lo, double hi) = 0;
  virtual void split(int var, double at) = 0;
  virtual void discard(const char* hint) = 0;
  virtual void undecided(int32_t id, const int8_t* signs) = 0;
  virtual void solution(int32_t id, const int8_t* signs, const SolutionProof& proof) = 0;
};

}  // namespace aspects
