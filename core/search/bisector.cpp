#include "search/bisector.h"

namespace aspects {

bool splittable(const Interval& x, double eps) {
  if (!(x.width_up() > eps)) return false;
  const double at = x.mid();
  return x.lo_down() < at && at < x.hi_up();
}

SplitChoice Bisector::choose(const Box& box, const SplitContext& ctx) const {
  SplitChoice c;
  bool wide = false;
  for (const auto& x : box) wide = wide || splittable(x, eps_);
  if (!wide) return c;
  c.var = variable(box, ctx);
  c.at = box[c.var].mid();  // a double strictly inside (splittable): both halves are smaller
  if (fraction_ != 0.5) {
    const double lo = box[c.var].lo_down(), hi = box[c.var].hi_up();
    const double at = lo + fraction_ * (hi - lo);
    if (lo < at && at < hi) c.at = at;  // else the middle
  }
  return c;
}

namespace {

// Round robin over the variables to split, starting after the parent's split.
int round_robin(const Box& box, int parent_split, double eps) {
  const int nv = int(box.size());
  for (int s = 1; s <= nv; ++s) {
    int v = parent_split < 0 ? s - 1 : (parent_split + s) % nv;
    if (splittable(box[v], eps)) return v;
  }
  return -1;
}

// The widest of `vars` to split, or -1.
int widest_of(const Box& box, const std::vector<int>& vars, double eps) {
  int best = -1;
  double widest = eps;
  for (int v : vars)
    if (box[v].width_up() > widest && splittable(box[v], eps)) {
      widest = box[v].width_up();
      best = v;
    }
  return best;
}

class RoundRobin : public Bisector {
 public:
  RoundRobin(const Model& m, double eps) : Bisector(m, eps) {}

 protected:
  int variable(const Box& box, const SplitContext& ctx) const override {
    return round_robin(box, ctx.parent_split, eps_);
  }
};

class PoseFirst : public Bisector {
 public:
  PoseFirst(const Model& m, double eps) : Bisector(m, eps) {}

 protected:
  int variable(const Box& box, const SplitContext&) const override {
    int v = widest_of(box, m_.pose, eps_);
    return v >= 0 ? v : widest_of(box, m_.command, eps_);
  }
};

// Cut the pose when it is what blocked the proof: P2 failed (P1 held, so the commands are
// already a function of the pose on this box, and only a narrower pose can make Fx or Fq
// regular), or P1 failed because the pose spread the commands too far. Otherwise (two
// branches, a singular point) the paper's round robin.
class ByVerdict : public Bisector {
 public:
  ByVerdict(const Model& m, double eps) : Bisector(m, eps) {}

 protected:
  int variable(const Box& box, const SplitContext& ctx) const override {
    if (ctx.verdict == Verdict::SingularFx || ctx.verdict == Verdict::SingularFq ||
        ctx.verdict == Verdict::WidePose) {
      int v = widest_of(box, m_.pose, eps_);
      if (v >= 0) return v;
    }
    return round_robin(box, ctx.parent_split, eps_);
  }
};

}  // namespace

bool parse_bisector_kind(const std::string& name, BisectorKind& kind) {
  if (name == "round-robin") kind = BisectorKind::RoundRobin;
  else if (name == "pose-first") kind = BisectorKind::PoseFirst;
  else if (name == "verdict") kind = BisectorKind::Verdict;
  else return false;
  return true;
}

std::unique_ptr<Bisector> make_bisector(BisectorKind kind, const Model& m, double eps) {
  switch (kind) {
    case BisectorKind::PoseFirst: return std::make_unique<PoseFirst>(m, eps);
    case BisectorKind::Verdict: return std::make_unique<ByVerdict>(m, eps);
    case BisectorKind::RoundRobin: break;
  }
  return std::make_unique<RoundRobin>(m, eps);
}

}  // namespace aspects
