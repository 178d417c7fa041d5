// Is a periodic variable's declared domain exactly one period?
//
// The proofs treat a periodic variable modulo 2π: the root cell must cover every angle
// once. An interval test (does hi − lo overlap 2π?) is not enough: bounds written as
// decimals close to ±π pass it at any fixed precision and leave a sliver of angles out of
// the domain, where a branch of solutions can hide and split an aspect (the bound is then
// false). So the bounds must be exactly a·π + b with rational a, b, and hi − lo = 2π
// exactly, decided with GMP rationals on the bound expressions as written.
#pragma once

#include <string>
#include <unordered_map>

#include "model/expr.h"

namespace aspects {

// What each constant node of the bound expressions stands for, exactly: the text of a
// decimal literal, or "pi". An empty text marks a node that stands for two different
// values (the DAG shares equal enclosures): never exact.
using ConstantMeanings = std::unordered_map<int, std::string>;

// True when lo and hi are exactly a·π + b (a, b rational, through +, −, ×, / by a nonzero
// rational, unary −) and hi − lo = 2π. False when the form is not recognised or the
// rationals would grow beyond a fixed budget (a hostile model must not exhaust memory).
bool exactly_one_period(const Dag& dag, const ConstantMeanings& meanings, int lo, int hi);

}  // namespace aspects
