// What `aspects count` and aspects.count report of a count (proofs/counting/exact_count.h):
// the line that states the number, the JSON object of `count --json` (Python reads the same
// object), and the details under the line. One place, so that the two front ends never say
// different things.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "counting/exact_count.h"
#include "model/model.h"

namespace aspects {

// "N aspects (certified: lower = upper)", "between L and U aspects (certified)", or
// "at least L aspects (certified); no upper bound: K piece(s) not proved connected".
std::string count_line(const CountBounds& b);

// count --json's object; `eps`: the first cover's.
nlohmann::json count_json(const Model& m, const CountResult& r, double eps);

// The lines under count_line: the run, the sign classes, and what holds the gap.
void print_count_details(std::ostream& out, const Model& m, const CountResult& r, double eps);

}  // namespace aspects
