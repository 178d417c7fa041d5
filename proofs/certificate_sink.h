// Where the search streams its certificate records (certificates/FORMAT.md) while it
// runs. The engine only knows these interfaces; the writer lives in certificates/.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "numerics/interval.h"
#include "model/model.h"

namespace aspects {

struct SolutionProof;

// Tree records of one subtree, in depth-first preorder. Output box ids are local to
// the subtree (0, 1, 2, ... in record order); the writer renumbers them when it
// splices subtrees together.
class TreeSink {
 public:
  virtual ~TreeSink() = default;
  virtual void contraction(int var, double lo, double hi) = 0;
  virtual void split(int var, double at) = 0;
  virtual void discard(const char* hint) = 0;
  virtual void undecided(int32_t local_id, const int8_t* signs) = 0;
  virtual void unexplored(int32_t local_id, const int8_t* signs) = 0;
  virtual void solution(int32_t local_id, const int8_t* signs, const SolutionProof& proof) = 0;
  // The subtree `task` goes here (its records come from subtree(task)).
  virtual void deferred(int32_t task) = 0;
  // No more records for this subtree.
  virtual void finished() {}
};

class CertificateSink {
 public:
  virtual ~CertificateSink() = default;
  // Before the search: the root cell and the sign factors.
  virtual void begin(const Box& domain, const std::vector<Factor>& factors) = 0;
  // The records of the top of the tree, and of each deferred subtree. subtree() is
  // called before the subtrees are searched (possibly in parallel, one sink each).
  virtual TreeSink* top() = 0;
  virtual TreeSink* subtree(int32_t task, const Box& root) = 0;  // root: the subtree's cell
  // The records of subtree `task` as another process's TreeSink wrote them (a distributed
  // search: proofs/pipeline/remote_subtrees.h); then subtree(task) is not called.
  virtual void restore(int32_t task, const std::string& records) = 0;
  // The same records, still held by the process that searched the subtree: `fetch` returns
  // them when the certificate is written (once, on the writer's thread).
  virtual void restore_later(int32_t task, std::function<std::string()> fetch) = 0;
};

}  // namespace aspects
