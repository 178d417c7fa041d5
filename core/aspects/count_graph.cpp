#include "aspects/count_graph.h"

#include <boost/pending/disjoint_sets.hpp>

#include <stdexcept>

namespace aspects {

int32_t CountGraph::add_piece(uint32_t cls, PieceState state) {
  piece_state_.push_back(state);
  piece_class_.push_back(cls);
  return int32_t(piece_state_.size()) - 1;
}

int32_t CountGraph::add_adjacency(int32_t a, int32_t b, AdjacencyState state) {
  if (a < 0 || b < 0 || a >= pieces() || b >= pieces())
    throw std::out_of_range("count graph: adjacency to no piece");
  // Pieces of two classes never meet: W_s and W_t are disjoint.
  if (piece_class_[a] != piece_class_[b])
    throw std::invalid_argument("count graph: adjacency between two sign classes");
  adj_state_.push_back(state);
  adj_a_.push_back(a);
  adj_b_.push_back(b);
  return int32_t(adj_state_.size()) - 1;
}

std::vector<int32_t> CountGraph::components(bool joined_only) const {
  const int32_t n = pieces();
  std::vector<int32_t> rank(n), parent(n);
  boost::disjoint_sets<int32_t*, int32_t*> sets(rank.data(), parent.data());
  for (int32_t p = 0; p < n; ++p) sets.make_set(p);
  for (int32_t e = 0; e < adjacencies(); ++e) {
    const AdjacencyState s = adj_state_[e];
    if (s == AdjacencyState::Refuted || (joined_only && s != AdjacencyState::Joined)) continue;
    const int32_t a = adj_a_[e], b = adj_b_[e];
    // An empty piece has no point to share.
    if (piece_state_[a] == PieceState::Empty || piece_state_[b] == PieceState::Empty) continue;
    sets.union_set(a, b);
  }
  std::vector<int32_t> label(n, -1), of_root(n, -1);
  int32_t next = 0;
  for (int32_t p = 0; p < n; ++p) {
    if (piece_state_[p] == PieceState::Empty) continue;
    int32_t& l = of_root[sets.find_set(p)];
    if (l < 0) l = next++;
    label[p] = l;
  }
  return label;
}

std::vector<int32_t> CountGraph::joined_components() const { return components(true); }
std::vector<int32_t> CountGraph::unrefuted_components() const { return components(false); }

CountBounds CountGraph::bounds() const {
  CountBounds b;
  const std::vector<int32_t> g = unrefuted_components();
  const std::vector<int32_t> h = joined_components();
  // Lower: components of G holding a piece proved nonempty.
  std::vector<uint8_t> counted;
  for (int32_t p = 0; p < pieces(); ++p) {
    if (g[p] < 0) continue;
    if (size_t(g[p]) >= counted.size()) counted.resize(size_t(g[p]) + 1, 0);
    const PieceState s = piece_state_[p];
    if ((s == PieceState::Connected || s == PieceState::Nonempty) && !counted[g[p]]) {
      counted[g[p]] = 1;
      ++b.lower;
    }
  }
  // Upper: every piece decided, then the components of H.
  int32_t h_count = 0;
  for (int32_t p = 0; p < pieces(); ++p) {
    if (piece_state_[p] == PieceState::Empty) continue;
    if (piece_state_[p] != PieceState::Connected) ++b.open_pieces;
    if (h[p] + 1 > h_count) h_count = h[p] + 1;
  }
  for (int32_t e = 0; e < adjacencies(); ++e) {
    if (adj_state_[e] != AdjacencyState::Undecided) continue;
    const int32_t a = adj_a_[e], bb = adj_b_[e];
    if (h[a] >= 0 && h[bb] >= 0 && h[a] != h[bb]) ++b.open_adjacencies;
  }
  b.upper = b.open_pieces == 0 ? h_count : -1;
  return b;
}

const char* piece_state_name(PieceState s) {
  switch (s) {
    case PieceState::Empty: return "empty";
    case PieceState::Connected: return "connected";
    case PieceState::Nonempty: return "nonempty";
    case PieceState::Undecided: return "undecided";
  }
  return "?";
}

const char* adjacency_state_name(AdjacencyState s) {
  switch (s) {
    case AdjacencyState::Joined: return "joined";
    case AdjacencyState::Refuted: return "refuted";
    case AdjacencyState::Undecided: return "undecided";
  }
  return "?";
}

}  // namespace aspects
