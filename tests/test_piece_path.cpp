// The path through a count's pieces (planning/piece_path.h) re-proves what it crosses: a
// forged pieces file that claims a connected piece where there is none does not make it
// print a path. And the pieces file itself: encoded and decoded to the same records.
#include <gtest/gtest.h>

#include <filesystem>

#include "counting/exact_count.h"
#include "counting/factor_gradients.h"
#include "model/model.h"
#include "results/count_pieces.h"
#include "results/result_index.h"
#include "piece_path.h"

using namespace aspects;

namespace {

// The bow tie with a neck (3 aspects: the middle, class +; top and bottom, class -),
// counted with its records kept, as `aspects count --out` writes it.
CountPieces bow_tie_pieces() {
  Model m = load_model(std::string(ASPECTS_TEST_MODELS_DIR) + "/count_bow_tie_neck.robot");
  CountConfig cfg;
  cfg.keep_records = true;
  const CountResult r = count_aspects(m, cfg);
  EXPECT_TRUE(r.bounds.exact());
  EXPECT_EQ(r.bounds.lower, 3);
  return count_pieces_of(m, r, cfg.eps, working_precision());
}

CountDirectory directory_of(const CountPieces& P, const std::string& name) {
  const std::string dir = testing::TempDir() + "/" + name;
  std::filesystem::create_directories(dir);
  write_count_pieces(dir + "/" + kCountPiecesName, P);
  return load_count_directory(dir);
}

PiecePathResult plan(CountDirectory& d, std::vector<double> from, std::vector<double> to) {
  FactorGradients fg(d.model, d.factor_nodes);
  ModelEvaluator ev(d.model);
  return plan_piece_path(d, ev, fg, from, to, -1);
}

}  // namespace

TEST(PiecePath, FileRoundTrip) {
  const CountPieces P = bow_tie_pieces();
  ASSERT_FALSE(P.cells.empty());
  ASSERT_FALSE(P.joins.empty());
  const CountPieces Q = decode_count_pieces(encode_count_pieces(P), "test");
  EXPECT_EQ(Q.lower, 3);
  EXPECT_EQ(Q.upper, 3);
  EXPECT_EQ(Q.factors, P.factors);
  ASSERT_EQ(Q.cells.size(), P.cells.size());
  for (size_t i = 0; i < P.cells.size(); ++i) {
    EXPECT_EQ(Q.cells[i].id, P.cells[i].id);
    EXPECT_EQ(Q.cells[i].box, P.cells[i].box);
    EXPECT_EQ(Q.cells[i].w, P.cells[i].w);
    ASSERT_EQ(Q.cells[i].pieces.size(), P.cells[i].pieces.size());
    for (size_t k = 0; k < P.cells[i].pieces.size(); ++k) {
      EXPECT_EQ(Q.cells[i].pieces[k].cls, P.cells[i].pieces[k].cls);
      EXPECT_EQ(Q.cells[i].pieces[k].how, P.cells[i].pieces[k].how);
      EXPECT_EQ(Q.cells[i].pieces[k].u, P.cells[i].pieces[k].u);
      EXPECT_EQ(Q.cells[i].pieces[k].hint, P.cells[i].pieces[k].hint);
    }
  }
  ASSERT_EQ(Q.joins.size(), P.joins.size());
  for (size_t j = 0; j < P.joins.size(); ++j) {
    EXPECT_EQ(Q.joins[j].a, P.joins[j].a);
    EXPECT_EQ(Q.joins[j].b, P.joins[j].b);
    EXPECT_EQ(Q.joins[j].shift, P.joins[j].shift);
    EXPECT_EQ(Q.joins[j].u, P.joins[j].u);
  }
}

// A forged cell spanning the top and bottom aspects (class -, disjoint), claimed one
// star-shaped piece about a point of the top, or the whole graph: were it trusted, the path
// would run from the top to the bottom through it. Proved again, it is refused.
TEST(PiecePath, ForgedPieceIsProvedAgainAndRefused) {
  CountPieces P = bow_tie_pieces();
  {
    CountDirectory d = directory_of(P, "genuine");
    const PiecePathResult r = plan(d, {0.5, 0.9}, {0.5, -0.9});
    EXPECT_EQ(r.outcome, PiecePathOutcome::DifferentAspects);
  }
  CountPieceCell forged;
  forged.id = P.cells.back().id + 1;
  forged.box = {0.4, 0.6, -1, 1, 0.4, 0.6, -5, 5};  // x1, x2, q1, q2
  forged.w = {2, 3};                                // the commands over the pose
  CountPiece star;
  star.how = CountPiece::Star;
  star.cls = 0;  // class -
  star.w_vars = {2, 3};
  star.u = {0.5, 0.9};
  const double q2 = 0.9 * 0.9 * 0.9 / 3 - (0.25 + 0.0001) * 0.9;  // on the top branch
  star.hint = {0.5 - 1e-9, 0.5 + 1e-9, q2 - 1e-9, q2 + 1e-9};
  forged.pieces.push_back(star);
  P.cells.push_back(forged);
  {
    CountDirectory d = directory_of(P, "forged");
    const PiecePathResult r = plan(d, {0.5, 0.9}, {0.5, -0.9});
    EXPECT_EQ(r.outcome, PiecePathOutcome::ProofFailed);
    EXPECT_NE(r.failure.find("piece of class - was not proved connected again (star-shaped test)"),
              std::string::npos)
        << r.failure;
  }
  // Claimed the whole graph over its pose part (as a solve's solution box): proved again too.
  P.cells.back().pieces.back().how = CountPiece::Graph;
  CountDirectory d = directory_of(P, "forged_solution");
  const PiecePathResult r = plan(d, {0.5, 0.9}, {0.5, -0.9});
  EXPECT_EQ(r.outcome, PiecePathOutcome::ProofFailed);
  EXPECT_NE(r.failure.find("piece of class - was not proved connected again"), std::string::npos)
      << r.failure;
}

// A constrained model's count (its pieces star-shaped with the constraints' atoms among their
// constraints) is not planned through: the segments proved here know only factors and faces.
TEST(PiecePath, ACountWithConstraintsIsRefused) {
  Model m = load_model(std::string(ASPECTS_TEST_MODELS_DIR) + "/count_circle_closed.robot");
  CountConfig cfg;
  cfg.keep_records = true;
  const CountResult r = count_aspects(m, cfg);
  ASSERT_TRUE(r.bounds.exact());
  const CountPieces P = count_pieces_of(m, r, cfg.eps, working_precision());
  const std::string dir = testing::TempDir() + "/constrained_count";
  std::filesystem::create_directories(dir);
  write_count_pieces(dir + "/" + kCountPiecesName, P);
  try {
    load_count_directory(dir);
    FAIL() << "a constrained count's pieces were loaded";
  } catch (const IndexError& e) {
    EXPECT_NE(std::string(e.what()).find("`constraint` statements"), std::string::npos) << e.what();
  }
}
