#include "query_command.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "generalized_aspects.h"  // UndecidedKind
#include "pose.h"
#include "same_command.h"

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

namespace {

std::string signs_text(const std::vector<int8_t>& s) {
  std::string t;
  for (size_t k = 0; k < s.size(); ++k) {
    if (k) t += ',';
    t += s[k] > 0 ? '+' : s[k] < 0 ? '-' : '0';
  }
  return t;
}

void print_text(const LoadedResult& r, const std::vector<double>& pose, const QueryResult& q) {
  const Model& m = r.model;
  std::printf("robot %s  eps %g  pose %s\n", m.name.c_str(), r.index.eps,
              format_pose(pose).c_str());
  std::string names;
  for (size_t k = 0; k < r.index.factors.size(); ++k)
    names += (k ? "; " : "") + r.index.factors[k].origin;
  switch (q.outcome) {
    case QueryOutcome::Answered: {
      std::printf("%zu certified command(s)%s; signs of: %s\n", q.answers.size(),
                  q.not_proved_distinct.empty() ? "" : " (some may be one: below)",
                  names.c_str());
      int32_t last = -2;
      for (const QueryAnswer& a : q.answers) {
        const IndexSolutionBox& s = r.index.solutions[a.solution];
        if (a.csnc != last)
          std::printf("CSNC %d%s  signs %s\n", a.csnc,
                      uint32_t(a.csnc) < r.index.filtered ? "" : " (filtered out: small)",
                      signs_text(s.signs).c_str());
        last = a.csnc;
        std::printf("  box %u", a.box);
        for (size_t k = 0; k < a.same_boxes.size(); ++k) {
          std::printf(k ? ", %u" : a.same_boxes.size() > 1 ? " (and boxes %u" : " (and box %u",
                      a.same_boxes[k]);
          if (a.same_csncs[k] != a.csnc) std::printf(" of CSNC %d", a.same_csncs[k]);
        }
        if (!a.same_boxes.empty()) std::printf(": the same command, proved)");
        std::printf(":");
        for (int j = 0; j < m.n(); ++j)
          std::printf(" %s in [%.17g, %.17g]", m.vars[m.command[j]].name.c_str(), a.command.lo[j],
                      a.command.hi[j]);
        std::printf("  width %.3g\n", a.command.width());
      }
      break;
    }
    case QueryOutcome::NotProved:
      std::printf("the pose lies in %zu solution box(es) but no command enclosure could be "
                  "proved (close to a singularity)\n", q.unproved.size());
      break;
    case QueryOutcome::UndecidedRegion:
      if (q.unexplored)  // a partial result (aspects solve stopped early)
        std::printf("no command: the pose lies in no solution box, only in %zu undecided box(es), "
                    "%zu of them not searched (the run was stopped)\n",
                    q.undecided.size(), q.unexplored);
      else
        std::printf("no command: the pose lies in no solution box, only in %zu undecided box(es): "
                    "near a singularity or a constraint boundary, or not resolved at eps %g\n",
                    q.undecided.size(), r.index.eps);
      break;
    case QueryOutcome::OutsideWorkspace:
      std::printf("no command: the pose lies in no box of the result, so no feasible command "
                  "in the declared domain reaches it (outside the workspace)\n");
      break;
    case QueryOutcome::MembershipUnknown:
      std::printf("no claim: no certified command, and whether the pose lies in %zu box(es) "
                  "(first: %u) could not be decided (a periodic coordinate too close to a "
                  "face)\n", q.unknown.size(), q.unknown.front());
      break;
  }
  for (const auto& [a, b] : q.not_proved_distinct)
    std::printf("  (the commands of boxes %u and %u were proved neither one solution nor two: "
                "both are listed, and may be one)\n", a, b);
  for (uint32_t id : q.unproved)
    if (q.outcome == QueryOutcome::Answered)
      std::printf("  (box %u also contains the pose; its command could not be proved)\n", id);
}

}  // namespace

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

int run_query(const QueryOptions& opts) {
  LoadedResult r = load_result(opts.result_dir);
  if (const std::string note = certificate_note(r); !note.empty())
    std::cerr << "aspects: note: " << note << '\n';
  std::vector<double> pose = parse_pose(opts.pose, "--pose", r.model);
  ModelEvaluator ev(r.model);
  QueryResult q = query_pose(r, ev, pose);
  if (opts.json)
    std::cout << query_json(pose, q, r).dump() << '\n';
  else
    print_text(r, pose, q);
  return q.outcome == QueryOutcome::Answered ? 0 : 1;
}

}  // namespace aspects
