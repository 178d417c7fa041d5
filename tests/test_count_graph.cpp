// The graph of pieces and adjacencies (core/aspects/count_graph.h): the two bounds on
// hand-made graphs whose counts are known.
#include <gtest/gtest.h>

#include "aspects/count_graph.h"

using namespace aspects;

namespace {
constexpr auto C = PieceState::Connected;
constexpr auto E = PieceState::Empty;
constexpr auto U = PieceState::Undecided;
constexpr auto N = PieceState::Nonempty;
constexpr auto J = AdjacencyState::Joined;
constexpr auto R = AdjacencyState::Refuted;
constexpr auto O = AdjacencyState::Undecided;
}  // namespace

TEST(CountGraph, ChainsOfJoinedPiecesCountOncePerClass) {
  CountGraph g;
  // Class 0: a chain of three joined pieces; class 1: two joined pieces.
  int a = g.add_piece(0, C), b = g.add_piece(0, C), c = g.add_piece(0, C);
  int d = g.add_piece(1, C), e = g.add_piece(1, C);
  g.add_adjacency(a, b, J);
  g.add_adjacency(b, c, J);
  g.add_adjacency(d, e, J);
  const CountBounds r = g.bounds();
  EXPECT_EQ(r.lower, 2);
  EXPECT_EQ(r.upper, 2);
  EXPECT_TRUE(r.exact());
  EXPECT_EQ(r.open_pieces, 0);
  EXPECT_EQ(r.open_adjacencies, 0);
}

TEST(CountGraph, AnUndecidedAdjacencyLeavesTheGapOpen) {
  CountGraph g;
  int a = g.add_piece(0, C), b = g.add_piece(0, C);
  const int e = g.add_adjacency(a, b, O);
  CountBounds r = g.bounds();
  EXPECT_EQ(r.lower, 1);  // G joins them: they may be one aspect
  EXPECT_EQ(r.upper, 2);  // H does not: they may be two
  EXPECT_FALSE(r.exact());
  EXPECT_EQ(r.open_adjacencies, 1);
  g.set_adjacency_state(e, R);  // refuted: two aspects
  r = g.bounds();
  EXPECT_EQ(r.lower, 2);
  EXPECT_EQ(r.upper, 2);
  g.set_adjacency_state(e, J);  // joined: one
  r = g.bounds();
  EXPECT_EQ(r.lower, 1);
  EXPECT_EQ(r.upper, 1);
}

TEST(CountGraph, NoUpperBoundWhileAPieceIsNotProvedConnected) {
  for (PieceState open : {U, N}) {
    CountGraph g;
    int a = g.add_piece(0, C), b = g.add_piece(0, open);
    g.add_adjacency(a, b, J);
    const CountBounds r = g.bounds();
    EXPECT_EQ(r.lower, 1);
    EXPECT_EQ(r.upper, -1) << piece_state_name(open);
    EXPECT_FALSE(r.exact());
    EXPECT_EQ(r.open_pieces, 1);
  }
}

TEST(CountGraph, EmptyPiecesJoinNothing) {
  CountGraph g;
  // a - x - b with x empty: the adjacencies through x cannot join a and b.
  int a = g.add_piece(0, C), x = g.add_piece(0, E), b = g.add_piece(0, C);
  g.add_adjacency(a, x, O);
  g.add_adjacency(x, b, J);
  const CountBounds r = g.bounds();
  EXPECT_EQ(r.lower, 2);
  EXPECT_EQ(r.upper, 2);
  EXPECT_EQ(g.joined_components()[x], -1);
}

TEST(CountGraph, ALowerBoundCountsOnlyComponentsWithAPieceProvedNonempty) {
  CountGraph g;
  int a = g.add_piece(0, C);
  g.add_piece(0, U);  // alone, maybe empty: counts nothing below
  int n = g.add_piece(1, N);
  (void)a, (void)n;
  const CountBounds r = g.bounds();
  EXPECT_EQ(r.lower, 2);
  EXPECT_EQ(r.upper, -1);
}

TEST(CountGraph, RefusesAnAdjacencyAcrossClasses) {
  CountGraph g;
  int a = g.add_piece(0, C), b = g.add_piece(1, C);
  EXPECT_THROW(g.add_adjacency(a, b, J), std::invalid_argument);
  EXPECT_THROW(g.add_adjacency(a, 7, J), std::out_of_range);
}
