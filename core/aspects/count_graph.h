// The graph of pieces and adjacencies that bounds the number of aspects from both sides
// (certificates/FORMAT.md, "Counting"; ../notes: counting.md).
//
// A piece is W_s ∩ B: the nonsingular configurations of sign class s in a closed box B of a
// cover of the solution set V. An adjacency joins two pieces of one class whose boxes touch.
//  - Lower bound: components of G (edges: every adjacency not refuted) that hold a piece
//    proved nonempty. Their unions are disjoint, relatively open and closed in W_s, so each
//    holds at least one aspect of its own.
//  - Upper bound: components of H (edges: joined adjacencies, a witness point of W_s lying in
//    both boxes). Valid only when every piece is decided (empty, or nonempty and connected):
//    then each component of H has a connected union, and W_s is the union of the pieces.
// Lower = upper is the exact count. This file is combinatorics only; what proves each state
// lives in proofs/counting/.
#pragma once

#include <cstdint>
#include <vector>

namespace aspects {

enum class PieceState : uint8_t {
  Empty,      // proved: W_s ∩ B = ∅ (no solution in B, or a factor certainly of another sign)
  Connected,  // proved: nonempty and connected
  Nonempty,   // proved nonempty (a witness), connectedness not proved
  Undecided,  // nothing proved
};

enum class AdjacencyState : uint8_t {
  Joined,     // a point of W_s lies in both boxes
  Refuted,    // no point of W_s lies in both boxes
  Undecided,
};

struct CountBounds {
  int lower = 0;
  int upper = -1;        // -1: no upper bound (an undecided or unconnected piece remains)
  bool exact() const { return upper >= 0 && upper == lower; }
  // What holds the gap: pieces not proved connected (and not empty), and undecided
  // adjacencies between pieces in different components of H.
  long open_pieces = 0;
  long open_adjacencies = 0;
};

class CountGraph {
 public:
  // A piece of class `cls` (bit i set: factor i positive); returns its id.
  int32_t add_piece(uint32_t cls, PieceState state);
  // An adjacency between two pieces of one class; returns its id.
  int32_t add_adjacency(int32_t a, int32_t b, AdjacencyState state);

  int32_t pieces() const { return int32_t(piece_state_.size()); }
  int32_t adjacencies() const { return int32_t(adj_state_.size()); }
  PieceState piece_state(int32_t p) const { return piece_state_[p]; }
  uint32_t piece_class(int32_t p) const { return piece_class_[p]; }
  AdjacencyState adjacency_state(int32_t e) const { return adj_state_[e]; }
  int32_t end_a(int32_t e) const { return adj_a_[e]; }
  int32_t end_b(int32_t e) const { return adj_b_[e]; }
  void set_piece_state(int32_t p, PieceState s) { piece_state_[p] = s; }
  void set_adjacency_state(int32_t e, AdjacencyState s) { adj_state_[e] = s; }

  // The components of H (joined adjacencies between pieces that are not empty): a label
  // per piece (-1 for an empty piece), labels 0..k-1.
  std::vector<int32_t> joined_components() const;
  // The components of G (adjacencies not refuted), labelled the same way.
  std::vector<int32_t> unrefuted_components() const;

  CountBounds bounds() const;

 private:
  std::vector<int32_t> components(bool joined_only) const;

  std::vector<PieceState> piece_state_;
  std::vector<uint32_t> piece_class_;
  std::vector<AdjacencyState> adj_state_;
  std::vector<int32_t> adj_a_, adj_b_;
};

const char* piece_state_name(PieceState s);
const char* adjacency_state_name(AdjacencyState s);

}  // namespace aspects
