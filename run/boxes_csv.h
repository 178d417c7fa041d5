// boxes.csv of `aspects solve --out`: one row per output box (id, status, CSNC, whether
// its CSNC survived filtering, its endpoints, why it stayed undecided). Endpoints are
// printed with 17 significant digits, so they read back as the same doubles.
#pragma once

#include <string>

#include "generalized_aspects.h"
#include "model/model.h"

namespace aspects {

// Writes `path` atomically (complete or absent); throws std::runtime_error naming it.
void write_boxes_csv(const Model& m, const AspectsResult& r, const std::string& path);

}  // namespace aspects
