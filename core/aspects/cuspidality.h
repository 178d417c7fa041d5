// Certified cuspidality (paper Section 3.2), "one pose, two commands": two solution boxes
// A < B of the same CSNC whose pose parts overlap (B shifted by 2πk on periodic pose
// variables) and whose command parts are disjoint (modulo 2π on periodic commands). P1 on
// both boxes then gives, for every pose of the overlap, two distinct commands in one CSNC,
// hence in one aspect. The tests are exactly those of check_cert (certificates/FORMAT.md,
// "Cuspidality witnesses"): shifted ends rounded inward for the overlap, outward for the
// disjointness. Found by a sort-and-sweep on one pose coordinate within each CSNC.
//
// "One command, two poses" (a non-singular assembly-mode change): two solution boxes A < B
// of one CSNC whose command parts overlap (B shifted by 2πk on periodic commands) and whose
// pose parts are disjoint (modulo 2π), with, at a point command q* of the overlap, an
// interval-Newton existence proof in x inside each box (proofs/assembly_witness.h). Found
// by the same sweep with the roles of x and q swapped; check_cert's V records.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "search/box_store.h"
#include "aspects/for_each_index.h"
#include "numerics/interval.h"

namespace aspects {

struct PoseWitness {
  int32_t csnc, a, b;       // a < b, solution boxes of CSNC `csnc`
  uint32_t shift_code = 0;  // pack_shift over all variables (0 on commands): b + 2πk meets a
  int shift(int v) const { return int((shift_code >> (2 * v)) & 3u) - 1; }
};

// Whether the search of a CSNC listed every witness or stopped at the cap.
enum class WitnessSearch : uint8_t { Complete = 0, Capped = 1 };
const char* witness_search_name(WitnessSearch s);

// A proved "one command, two poses" witness: f(x, q) = 0 has a zero in xa (inside box a's
// pose part) and one in xb (inside box b's), both at the command q (model command order),
// which lies in box a and in box b + 2πk. xa, xb: the Newton iterates (double ends) with
// H ⊂ int x~; ca, cb: their preconditioners (row major).
struct CommandWitness {
  int32_t csnc, a, b;
  uint32_t shift_code = 0;  // pack_shift, nonzero on periodic commands only
  std::vector<double> q;
  std::vector<Interval> xa, xb;
  std::vector<double> ca, cb;
  int shift(int v) const { return int((shift_code >> (2 * v)) & 3u) - 1; }
};

struct CuspidalWitnesses {
  std::vector<PoseWitness> pose;      // sorted by (csnc, a, b), each pair once
  std::vector<int64_t> count;         // per CSNC: witnesses in `pose`
  std::vector<WitnessSearch> search;  // per CSNC
  std::vector<CommandWitness> command;        // sorted by (csnc, a, b), each pair once
  std::vector<int64_t> command_count;         // per CSNC: witnesses in `command`
  std::vector<WitnessSearch> command_search;  // per CSNC
};

// The variables of a model, and 2π at the working precision (made by the constructor).
struct WitnessSpace {
  std::vector<int> pose;  // indices into the variables
  std::vector<int> command;
  std::vector<bool> periodic;
  Interval two_pi;
  WitnessSpace(std::vector<int> pose, std::vector<int> command, std::vector<bool> periodic);
};

// Box b + 2πk meets box a on every pose variable, the shifted ends of b rounded inward (k
// = 0 on non-periodic variables): a nonempty inner intersection.
bool poses_overlap(const BoxStore& R, int a, int b, const std::vector<int>& k,
                   const WitnessSpace& s);
// For every command, [a] and [b] + 2πm are disjoint for every integer m (m = 0 only when
// the command is not periodic), proved with the shifted ends rounded outward.
bool commands_disjoint(const BoxStore& R, int a, int b, const WitnessSpace& s);

// The searches run a ForEachIndex over CSNCs and over the candidates of one CSNC.

// csnc: CSNC of each box (-1: not a solution box); csncs: number of CSNCs. At most `cap`
// witnesses per CSNC.
CuspidalWitnesses find_pose_witnesses(const BoxStore& R, const std::vector<int32_t>& csnc,
                                      int csncs, const WitnessSpace& s, int64_t cap = 10000,
                                      const ForEachIndex& for_each = serial_for_each);

// Fills q, xa, xb, ca, cb of a candidate (csnc, a, b, shift_code set) and returns true when
// the existence proofs succeed. Called from several threads at once when for_each runs
// CSNCs in parallel.
using ProveCommandWitness = std::function<bool(CommandWitness&)>;

// Candidates: boxes of one CSNC with meeting commands and disjoint poses, in sweep order,
// each shift k of a pair a candidate; the first min(attempts, max(attempts / 10,
// attempts_per_box × boxes of the CSNC)) of them are proved (then the search is Capped):
// past a floor, the cost follows the size of the CSNC, and the proved ones go to w.command in that order, each pair once,
// at most `cap` per CSNC (then Capped), with the per-CSNC count and search.
void find_command_witnesses(const BoxStore& R, const std::vector<int32_t>& csnc, int csncs,
                            const WitnessSpace& s, const ProveCommandWitness& prove,
                            CuspidalWitnesses& w, int64_t cap = 1000, int64_t attempts = 100000,
                            int64_t attempts_per_box = 2,
                            const ForEachIndex& for_each = serial_for_each);

}  // namespace aspects
