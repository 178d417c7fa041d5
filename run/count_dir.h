// A count's directory (`aspects count MODEL --out DIR`, Python's aspects.count(out=DIR)):
// DIR/count.pieces, what `aspects path DIR` plans through (results/count_pieces.h), and
// DIR/summary.json, count --json's object.
#pragma once

#include <string>

#include "counting/exact_count.h"
#include "model/model.h"

namespace aspects {

// Before any work: DIR is made if missing; a file, or a solve's result directory (`aspects
// path` would no longer know which it is), is refused. Throws UsageError naming `option`.
void prepare_count_dir(const std::string& dir, const std::string& option);

// Both files, each written under a temporary name and renamed. The count must have kept its
// records (CountConfig::keep_records).
void write_count_dir(const std::string& dir, const Model& m, const CountResult& r, double eps);

}  // namespace aspects
