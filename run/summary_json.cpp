#include "run/summary_json.h"

#include <algorithm>

#include "aspects_version.h"
#include "results/sha256.h"
#include "run/solve_progress.h"
#include "search/stop_condition.h"

namespace aspects {

namespace {

using nlohmann::json;

// The program and the options of the run.
void add_run(json& j, const Model& m, const SolveOptions& o) {
  j["version"] = ASPECTS_VERSION;
  j["git_commit"] = *ASPECTS_GIT_COMMIT ? json(ASPECTS_GIT_COMMIT) : json(nullptr);
  j["robot"] = m.name;
  j["model"] = o.model_path.empty() ? std::string("(embedded default)") : o.model_path;
  j["eps"] = o.eps;
  j["precision_bits"] = o.prec;
  j["tau"] = o.tau;
  j["threads"] = o.threads;
  j["bisect"] = o.bisect;
  j["all_links"] = o.all_links;
}

void add_time_and_phases(json& j, const AspectsResult& r) {
  j["time_seconds"] = r.seconds;
  // A stopped run is a partial result: its claims hold, its search did not finish.
  j["complete"] = r.complete();
  j["stopped_by"] = r.complete() ? json(nullptr) : json(stop_reason_name(r.stopped_by));
  // The phase the stop cut short; the phases after it kept only what was established.
  j["stopped_in"] = r.complete() ? json(nullptr) : json(r.stopped_in);
  for (const auto& [phase, sec] : r.phase_seconds) j["phase_seconds"][phase] = sec;
  // The same phases in their order (JSON objects are not ordered), with the peak memory.
  j["phases"] = json::array();
  for (size_t k = 0; k < r.phase_seconds.size(); ++k)
    j["phases"].push_back({{"name", r.phase_seconds[k].first},
                           {"seconds", r.phase_seconds[k].second},
                           {"peak_memory_mib", r.phase_peak_mib[k].second}});
}

json boxes_json(const AspectsResult& r) {
  json boxes = {{"total", r.boxes.size()},
                {"solution", r.solutions},
                {"undecided", r.undecided},
                {"unexplored", r.unexplored},
                {"discarded", r.discarded},
                {"processed", r.processed}};
  long singular = 0, boundary = 0;
  for (int b = 0; b < r.boxes.size(); ++b) {
    if (r.boxes.certified(b) || r.boxes.unexplored(b)) continue;
    singular += r.boxes.kind(b) == UndecidedKind::Singular;
    boundary += r.boxes.kind(b) == UndecidedKind::Constraint;
  }
  boxes["undecided_not_p1"] = r.undecided - singular - boundary;
  boxes["undecided_not_p2"] = singular;
  boxes["undecided_constraint_boundary"] = boundary;
  return boxes;
}

// The classes that count toward the bound, as sign strings over the factors in their
// listed order ("+-+": d1 > 0, d2 < 0, d3 > 0), with the components each one counts.
json separated_classes_json(const SeparationResult& s, size_t factors) {
  json classes = json::array();
  for (size_t c = 0; c < s.per_class.size(); ++c) {
    if (s.per_class[c] == 0) continue;
    std::string signs;
    for (size_t i = 0; i < factors; ++i) signs += (c >> i) & 1 ? '+' : '-';
    classes.push_back({{"signs", signs}, {"components", s.per_class[c]}});
  }
  return classes;
}

json csncs_json(const AspectsResult& r) {
  int64_t kept_boxes = 0;
  for (int i = 0; i < r.filtered; ++i) kept_boxes += r.csnc_sizes[i];
  return {{"count", r.csnc_sizes.size()},
          {"filtered", r.filtered},
          {"filtered_boxes", kept_boxes},
          {"separated_lower_bound", r.separation.lower_bound},
          {"separated_representatives", r.separation.representatives},
          {"separated_classes", separated_classes_json(r.separation, r.factors.size())},
          {"sizes", r.csnc_sizes}};
}

// One CSNC's witnesses of either kind; `next` is where its pose witnesses start (the
// witnesses are grouped by CSNC, in CSNC order).
json csnc_witnesses_json(const CuspidalWitnesses& w, size_t c, int64_t assembly, size_t& next) {
  json examples = json::array();
  while (w.count[c] > 0 && w.pose[next].csnc != int32_t(c)) ++next;
  for (size_t i = next; i < next + std::min<size_t>(3, size_t(w.count[c])); ++i)
    examples.push_back({w.pose[i].a, w.pose[i].b});
  json e = {{"csnc", c},
            {"one_pose_two_commands", w.count[c]},
            {"search", witness_search_name(w.search[c])},
            {"examples", examples},
            {"one_command_two_poses", assembly}};
  if (c < w.command_search.size()) e["assembly_search"] = witness_search_name(w.command_search[c]);
  return e;
}

// Cuspidality witnesses (certified in the certificate's cuspidal and assembly sections):
// per CSNC with a witness of either kind, the counts of (a) "one pose, two commands" and
// (b) "one command, two poses", whether each search listed them all, a few pairs of (a).
json cuspidal_json(const AspectsResult& r) {
  const CuspidalWitnesses& w = r.cuspidal;
  json per = json::array();
  size_t next = 0;
  int64_t with_pose = 0, with_command = 0, capped = 0;
  for (WitnessSearch s : w.command_search) capped += s == WitnessSearch::Capped;
  for (size_t c = 0; c < w.count.size(); ++c) {
    const int64_t assembly = c < w.command_count.size() ? w.command_count[c] : 0;
    with_pose += w.count[c] > 0;
    with_command += assembly > 0;
    if (w.count[c] == 0 && assembly == 0) continue;
    per.push_back(csnc_witnesses_json(w, c, assembly, next));
  }
  return {{"witnesses", w.pose.size()},
          {"csncs_with_witness", with_pose},
          {"assembly_witnesses", w.command.size()},
          {"csncs_with_assembly_witness", with_command},
          {"csncs_assembly_search_capped", capped},
          {"per_csnc", per}};
}

// Why boxes were decided as they were: each verdict of Prove on every box that
// survived Prune, the verdict on each undecided leaf, and what refuted discarded boxes.
json diagnostics_json(const SearchDiagnostics& d) {
  json attempts, undecided;
  for (int k = 0; k < kVerdicts; ++k) {
    attempts[verdict_name(Verdict(k))] = d.attempts[k];
    if (Verdict(k) != Verdict::Solution) undecided[verdict_name(Verdict(k))] = d.undecided[k];
  }
  return {{"prove_verdicts", attempts},
          {"undecided_verdicts", undecided},
          {"refuted", {{"hc4", d.refuted_by_equation},
                       {"hansen_sengupta", d.refuted_by_newton},
                       {"constraint", d.refuted_by_constraint}}}};
}

// The hashes that tie the directory's files to one run; checked by query, path and
// `aspects verify`.
void add_hashes(json& j, const Model& m, const OutputHashes& h) {
  auto or_null = [](const std::string& s) { return s.empty() ? json(nullptr) : json(s); };
  j["model_sha256"] = sha256_hex_of(m.source);
  j["certificate"] = or_null(h.certificate.file);
  j["certificate_sha256"] = or_null(h.certificate.sha256);
  j["index_sha256"] = or_null(h.index_sha256);
}

}  // namespace

json summary_json(const Model& m, const SolveOptions& o, const AspectsResult& r,
                  const OutputHashes& hashes) {
  json j;
  add_run(j, m, o);
  add_hashes(j, m, hashes);
  add_time_and_phases(j, r);
  // The number of aspects, as `aspects count --json` states it: a solve certifies a lower
  // bound only (the separated one, Section 4.4.2).
  j["lower_bound"] = r.separation.lower_bound;
  j["upper_bound"] = nullptr;
  j["exact"] = false;
  j["boxes"] = boxes_json(r);
  j["links"] = {{"neighbor", r.neighbor_count}, {"certified", r.certified_links.size()}};
  j["constraints"] = m.constraints.size();
  j["csncs"] = csncs_json(r);
  j["cuspidal"] = cuspidal_json(r);
  json f = json::array();
  for (const auto& x : r.factors) f.push_back({{"expression", x.text}, {"origin", x.origin}});
  j["factors"] = f;
  j["diagnostics"] = diagnostics_json(r.diagnostics);
  j["peak_memory_mib"] = peak_resident_bytes() / (1024.0 * 1024.0);  // the run's, outputs included
  j["domain_decided"] = decided_share(m, r);  // share of the domain's volume; 1 when complete
  return j;
}

}  // namespace aspects
