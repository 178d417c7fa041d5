// The binary records of certificate format 3 (certificates/FORMAT.md, "Format 3"): the
// same records as format 2, in the same order, with the bulky ones (the search tree, the
// links and the CSNCs) coded in bytes. Each end is a small integer on the grid of an
// interval the checker already holds (proofs/certificate_grid.h), or its 8 bytes.
// Preconditioners are left out: the checker computes its own.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "certificate_grid.h"
#include "numerics/interval.h"

namespace aspects {

// Low-level coding, shared by the tree and the sections.
namespace compact {
void varint(std::string& out, uint64_t x);
void u64(std::string& out, uint64_t x);  // 8 bytes, little-endian
void raw(std::string& out, double x);    // its binary64 as u64()
// The ends of a box as lo/hi pairs of doubles, the form the coders take.
std::vector<double> ends(const Box& box);
// An end x on the grid of [a, b] from r (an end of it), offset by `offset` steps; its
// 8 bytes when it is not on it.
void end(std::string& out, double x, double a, double b, double r, int64_t offset = 0,
         int bits = grid::kBits);
// "+-0" characters (p of them, or "."), two bits each.
void signs(std::string& out, const char* s, int p);
}  // namespace compact

// Codes the tree records of one subtree in format 3, following its cells as the checker
// does from the subtree's root cell. Output ids are implied, so the records of subtrees
// are spliced as they are.
class CompactTree {
 public:
  // root: lo/hi pairs per variable; command: the commands' variable indices.
  CompactTree(std::vector<double> root, std::vector<int> command, int factors);
  // Each appends one record to `out` (P, B, X, U or N, S).
  void contraction(int v, double lo, double hi, std::string& out);
  void split(int v, double at, std::string& out);
  void discard(const char* hint, std::string& out);
  void leaf(bool unexplored, const int8_t* signs, std::string& out);
  // Q, image: lo/hi pairs per command; weights: DX then DQ.
  void solution(const int8_t* signs, const std::vector<double>& Q,
                const std::vector<double>& image, const std::vector<double>& weights,
                std::string& out);
  void deferred();  // this node is a subtree whose records are written elsewhere

 private:
  using Cell = std::vector<double>;
  void end(std::string& out, double x, const double* ref, bool upper, int64_t offset = 0,
           int bits = grid::kBits);
  Cell& current();
  std::vector<Cell> stack_;
  Cell cell_;
  bool open_ = false;  // cell_ is the node being written
  std::vector<int> command_;
  int p_;
};

}  // namespace aspects
