// One part of the search (proofs/search_state.h: a tree, its output boxes and the
// diagnostics) as little-endian bytes: the encoding of the checkpoint (apps/checkpoint.*)
// and of the parts an MPI job's ranks send back (apps/mpi_subtrees.*).
//
// part = u32 T  T × (i32 left  i32 right  i32 split_var  f64 split  i32 leaf  u8 fate
//                    i32 reason)
//        u32 B  B × nv × (f64 lo  f64 hi)  B × u8 certified  B × u8 undecided_kind
//        B × p × i8 sign  (2 × kVerdicts + 3) × i64 diagnostics
#pragma once

#include <cstdint>

#include "le_reader.h"
#include "le_writer.h"
#include "search_state.h"

namespace aspects {

// `p`: the number of sign factors.
void write_search_part(LeWriter& out, const SearchPart& part, uint32_t p);

// Reads a part of a model with `nv` variables and `p` factors, checking that its indices
// stay in range (the merge trusts them); `deferred` is the number of subtrees its Deferred
// leaves may name (the top's; 0 for a subtree). A failure is in.fail().
void read_search_part(LeReader& in, SearchPart& part, uint32_t nv, uint32_t p,
                      uint32_t deferred);

}  // namespace aspects
