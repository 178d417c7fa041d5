// How a run computes at a working precision of 53 bits: part of the run's plan, handed to
// each evaluator it makes (core/model/eval.h), never a process-wide switch, so that two
// solves in one process each compute as they asked.
#pragma once

namespace aspects {

enum class Arithmetic {
  // On doubles with MPFR's directed rounding (core/numerics/double_interval.h): the same
  // ends as MPFI, faster; MPFI where doubles decline and at every other precision.
  DoublesFirst,
  // Every operation MPFI's (`aspects solve --mpfi-only`): a cross-check that must give the
  // same certificate.
  MpfiOnly,
};

}  // namespace aspects
