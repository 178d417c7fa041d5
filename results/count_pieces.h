// The pieces file of a count directory (`aspects count MODEL --out DIR` writes
// DIR/count.pieces beside DIR/summary.json): what `aspects path DIR` plans through
// (planning/piece_path.h). It holds the model text, the count's bounds, and of its final
// cover only what a path can use: each box holding a piece proved connected, the chart of
// that box (its w), each such piece with how it was proved connected (the whole graph
// over the box's u, or star-shaped about a centre) and its centre, and every joined
// adjacency between two such pieces (a point of W_s in both boxes, or a bridge chart).
//
// Like the result index, it is the engine's record, not a certificate: path re-proves every
// point it goes through, every bridge and every piece it crosses; only its refusal "in
// different aspects" rests on the recorded bounds and joins.
// Binary, little-endian, versioned, ending with a SHA-256 of its bytes; any anomaly is an
// IndexError naming the file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "counting/exact_count.h"
#include "model/model.h"

namespace aspects {

constexpr uint32_t kCountPiecesVersion = 1;
constexpr const char* kCountPiecesName = "count.pieces";

struct CountPiece {
  enum How : uint8_t { Graph = 1, Star = 2 } how = Graph;
  uint32_t cls = 0;            // bit i set: factor i positive
  // The centre (Star) or a point of the piece (Graph; may be absent): the chart's u-values
  // at u_vars (model order of the u's) and an enclosure of w there (n lo/hi pairs).
  std::vector<int> w_vars;     // empty: no point
  std::vector<double> u, hint;
};

struct CountPieceCell {
  int32_t id = 0;              // the count's cell id
  std::vector<double> box;     // nv lo/hi pairs, model order
  std::vector<int> w;          // the chart's w (n variables; the commands for a solve's box)
  std::vector<CountPiece> pieces;  // the pieces proved connected, by increasing class
};

struct CountJoin {
  int32_t a = 0, b = 0;        // cell ids, both in `cells`
  uint32_t cls = 0;
  std::vector<int8_t> shift;   // k per variable: the join is in a ∩ (b + 2πk)
  bool bridge = false;
  std::vector<int> w;          // the point's w, or the bridge chart's
  std::vector<double> u, hint; // the point (not a bridge)
};

struct CountPieces {
  std::string model_file, model_source;
  long precision_bits = 53;
  double eps = 0.5;            // the first cover's
  int lower = 0, upper = -1;   // the count's bounds (-1: no upper bound)
  bool exact() const { return upper >= 0 && upper == lower; }
  std::vector<std::string> factors;  // their texts, in class-bit order
  uint32_t nv = 0, n = 0;
  std::vector<CountPieceCell> cells;  // by increasing id
  std::vector<CountJoin> joins;
  std::string sha256;          // of the file, set when read
};

// From a finished count whose records were kept (CountConfig::keep_records).
CountPieces count_pieces_of(const Model& model, const CountResult& r, double eps,
                            long precision_bits);

// Written under a temporary name and renamed.
void write_count_pieces(const std::string& path, const CountPieces& pieces);

std::string encode_count_pieces(const CountPieces& pieces);
CountPieces decode_count_pieces(const std::string& bytes, const std::string& what);

// Whether DIR holds a count.pieces file.
bool is_count_directory(const std::string& dir);

// Reads DIR/count.pieces; throws IndexError (no such directory, no file, malformed).
CountPieces read_count_pieces(const std::string& dir);

}  // namespace aspects
