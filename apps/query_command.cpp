#include "query_command.h"

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "results/loaded_result.h"
#include "results/pose.h"
#include "results/pose_query.h"

namespace aspects {

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
