// One part of the search (proofs/search_state.h: a tree, its output boxes and the
// diagnostics) as bytes: the encoding of the checkpoint (run/checkpoint.*) and of the parts
// an MPI job's ranks send back (distribution/mpi_subtrees.*). Compact, because rank 0 takes every
// part of the job in through one thread and one link, and that intake bounds the job's
// speed-up.
//
// part = u64 L, then L bytes:
//   varint T, then the T nodes depth first, left child before right (the order the search
//   made them in, so the k-th internal node's children are nodes 2k + 1 and 2k + 2):
//     internal: u8 (v | 0x20 when fate and reason follow), f64 split,
//               [u8 fate, zigzag reason]                 (v: the split variable, < 32)
//     leaf:     u8 (0x40 | fate | 0x08 when index follows | 0x10 when reason follows),
//               [zigzag (index − the index expected)]     (expected: one past the previous
//                leaf's index of the same kind, deferred subtrees or output boxes, from 0)
//               [zigzag reason]
//     a node's fate and reason not written are LeafFate::Discarded and −1, its index −1.
//   varint B, then B × 2nv ends (lo, hi per variable), each as its bits XOR those of the
//     same end of the box before (0 for the first): u8 (l << 4 | t), then the 8 − l − t
//     bytes between l leading and t trailing zero bytes (0x80: the same bits);
//   B × u8 (certified | kind << 1);  ⌈B p / 4⌉ bytes: the signs + 1, two bits each, four a
//   byte, box after box;  (2 × kVerdicts + 3) zigzag diagnostics.
// varint: 7 bits a byte, low first, high bit set on all but the last; zigzag: a signed
// integer as a varint of 2v (v >= 0) or −2v − 1.
#pragma once

#include <cstdint>

#include "io/le_reader.h"
#include "io/le_writer.h"
#include "search_state.h"

namespace aspects {

// `p`: the number of sign factors. Throws std::logic_error on a part the search cannot
// have made (a tree not in its order, a sign other than −1, 0, +1).
void write_search_part(LeWriter& out, const SearchPart& part, uint32_t p);

// Reads a part of a model with `nv` variables and `p` factors, checking that its indices
// stay in range (the merge trusts them); `deferred` is the number of subtrees its Deferred
// leaves may name (the top's; 0 for a subtree). A failure is in.fail().
void read_search_part(LeReader& in, SearchPart& part, uint32_t nv, uint32_t p,
                      uint32_t deferred);

}  // namespace aspects
