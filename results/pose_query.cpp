#include "results/pose_query.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "generalized_aspects.h"  // UndecidedKind
#include "results/pose.h"
#include "results/same_command.h"

namespace aspects {

const char* query_outcome_name(QueryOutcome o) {
  switch (o) {
    case QueryOutcome::Answered: return "answered";
    case QueryOutcome::NotProved: return "not_proved";
    case QueryOutcome::UndecidedRegion: return "undecided_region";
    case QueryOutcome::OutsideWorkspace: return "outside_workspace";
    case QueryOutcome::MembershipUnknown: return "membership_unknown";
  }
  return "?";
}

BoxesAtPose solution_boxes_at(const LoadedResult& r, const std::vector<double>& pose) {
  BoxesAtPose found;
  for (size_t i = 0; i < r.index.solutions.size(); ++i) {
    const IndexSolutionBox& s = r.index.solutions[i];
    Membership in = pose_in_box(r.model, pose, s.lo.data(), s.hi.data());
    if (in == Membership::Inside) found.inside.push_back(i);
    if (in == Membership::Undecided) found.unknown.push_back(i);
  }
  return found;
}

namespace {

// Each solution once: answers proved one (same_command.h) are merged into the first of
// them, in the order given; pairs of the remaining answers neither proved one nor
// distinct are recorded.
void merge_same_commands(ModelEvaluator& ev, const std::vector<double>& pose, double tau,
                         HsWorkspace& ws, QueryResult& q) {
  const size_t n = q.answers.size();
  if (n < 2) return;
  std::vector<SameCommand> outcome(n * n, SameCommand::Unknown);
  std::vector<size_t> group(n);  // joined: each points to an earlier one, or to itself
  auto root = [&](size_t i) {
    while (group[i] != i) i = group[i];
    return i;
  };
  for (size_t i = 0; i < n; ++i) {
    group[i] = i;
    for (size_t k = 0; k < i; ++k) {
      SameCommand& o = outcome[i * n + k];
      o = same_command(ev, pose, q.answers[k].command, q.answers[i].command, tau, ws);
      outcome[k * n + i] = o;
      if (o != SameCommand::Same) continue;
      const size_t a = root(i), b = root(k);  // one solution: the earlier root stays
      group[std::max(a, b)] = std::min(a, b);
    }
  }
  for (size_t i = 0; i < n; ++i) group[i] = root(i);
  // A group's members are one solution: two groups are distinct when some pair is.
  std::vector<QueryAnswer> kept;
  std::vector<size_t> first;  // the answer each kept one came from
  for (size_t i = 0; i < n; ++i) {
    if (group[i] == i) {
      kept.push_back(std::move(q.answers[i]));
      first.push_back(i);
      continue;
    }
    QueryAnswer& into = kept[size_t(std::find(first.begin(), first.end(), group[i]) - first.begin())];
    into.same_boxes.push_back(q.answers[i].box);
    into.same_csncs.push_back(q.answers[i].csnc);
  }
  for (size_t a = 0; a < first.size(); ++a)
    for (size_t b = a + 1; b < first.size(); ++b) {
      bool distinct = false;
      for (size_t i = 0; i < n && !distinct; ++i)
        for (size_t k = 0; k < n && !distinct; ++k)
          distinct = group[i] == first[a] && group[k] == first[b] &&
                     outcome[i * n + k] == SameCommand::Distinct;
      if (!distinct) q.not_proved_distinct.push_back({kept[a].box, kept[b].box});
    }
  q.answers = std::move(kept);
}

}  // namespace

QueryResult query_pose(const LoadedResult& r, ModelEvaluator& ev, const std::vector<double>& pose) {
  QueryResult q;
  HsWorkspace ws;
  const BoxesAtPose at = solution_boxes_at(r, pose);
  for (size_t i : at.unknown) q.unknown.push_back(r.index.solutions[i].id);
  for (size_t i : at.inside) {
    const IndexSolutionBox& s = r.index.solutions[i];
    PointCommand c = certified_command(ev, s.lo.data(), s.hi.data(), pose, r.index.tau, ws);
    if (c.status == PointCommandStatus::Certified)
      q.answers.push_back({s.csnc, s.id, i, std::move(c), {}, {}});
    else
      q.unproved.push_back(s.id);
  }
  std::stable_sort(q.answers.begin(), q.answers.end(),
                   [](const QueryAnswer& a, const QueryAnswer& b) { return a.csnc < b.csnc; });
  merge_same_commands(ev, pose, r.index.tau, ws, q);
  if (!q.answers.empty()) {
    q.outcome = QueryOutcome::Answered;
    return q;
  }
  if (!q.unproved.empty()) {
    q.outcome = QueryOutcome::NotProved;
    return q;
  }
  for (const IndexUndecidedBox& u : r.index.undecided) {
    Membership in = pose_in_pose_box(r.pose_periodic, pose, u.lo.data(), u.hi.data());
    if (in == Membership::Undecided) q.unknown.push_back(u.id);
    if (in != Membership::Inside) continue;
    q.undecided.push_back(u.id);
    q.unexplored += u.kind == uint8_t(UndecidedKind::Unexplored);
  }
  // "Only in undecided boxes" and "in no box" need every membership decided.
  q.outcome = !q.unknown.empty()      ? QueryOutcome::MembershipUnknown
              : q.undecided.empty() ? QueryOutcome::OutsideWorkspace
                                    : QueryOutcome::UndecidedRegion;
  return q;
}

nlohmann::json query_json(const std::vector<double>& pose, const QueryResult& q,
                          const LoadedResult& r) {
  nlohmann::json j;
  j["pose"] = pose;
  j["outcome"] = query_outcome_name(q.outcome);
  j["answers"] = nlohmann::json::array();
  for (const QueryAnswer& a : q.answers) {
    // same_boxes: the other boxes proved to hold this command, with their CSNCs.
    j["answers"].push_back({{"csnc", a.csnc},
                            {"box", a.box},
                            {"same_boxes", a.same_boxes},
                            {"same_csncs", a.same_csncs},
                            {"command_lo", a.command.lo},
                            {"command_hi", a.command.hi},
                            {"width", a.command.width()},
                            {"signs", r.index.solutions[a.solution].signs}});
  }
  j["not_proved_distinct"] = nlohmann::json::array();
  for (const auto& [a, b] : q.not_proved_distinct) j["not_proved_distinct"].push_back({a, b});
  j["unproved_boxes"] = q.unproved;
  j["undecided_boxes"] = q.undecided;
  j["membership_unknown_boxes"] = q.unknown;
  return j;
}

}  // namespace aspects
