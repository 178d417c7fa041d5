#include "solve_command.h"

#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <chrono>
#include <exception>
#include <functional>
#include <future>
#include <memory>
#include <thread>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "aspects_version.h"
#include "io/atomic_file.h"
#include "certificate_writer.h"
#include "generalized_aspects.h"
#include "model/model.h"
#include "result_index.h"
#include "checkpoint.h"
#include "solve_resume.h"
#include "solve_progress.h"
#include "search_state.h"
#include "search/stop_condition.h"

namespace aspects {

namespace {

double resident_mib() { return resident_bytes() / (1024.0 * 1024.0); }

constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
// Memory still needed per output box after the search stops, for the merge, the
// neighbourhood graph, the links and the outputs (the peak minus the peak of the search,
// summary.json's phases): 123 and 128 bytes per output box on 3-RPR at eps 0.6 and 0.3 with
// the certificate's link proofs, 51 without (commit 00e75b6); 261 on RRRRR at eps 0.1,
// where the fixed costs weigh more. It was 1 KiB, measured before the graph phase was cut,
// and stopped 3-RPR at eps 0.1 under a 20 GiB limit with 3.6 GiB used
// (tests/long_runs.py, case memory_limit, checks a run stopped by the limit stays below it).
constexpr double kReservePerBox = 320;

void validate(const SolveOptions& o) {
  if (!(o.eps > 0) || !std::isfinite(o.eps))
    throw UsageError("--eps must be a positive number (got " + std::to_string(o.eps) + ")");
  if (!(o.tau >= 1) || !std::isfinite(o.tau))
    throw UsageError("--tau must be >= 1 (got " + std::to_string(o.tau) + ")");
  if (o.prec < 24 || o.prec > 4096)
    throw UsageError("--prec must be between 24 and 4096 bits (got " + std::to_string(o.prec) + ")");
  if (o.threads < 0 || o.threads > 1024)
    throw UsageError("--threads must be between 0 (one per core) and 1024");
  // Sentinels are -1 (the defaults); a value the user gave must make sense.
  if (o.time_limit != -1 && !(o.time_limit > 0 && o.time_limit < 1e9))
    throw UsageError("--time-limit must be a positive number of seconds (got " +
                     std::to_string(o.time_limit) + ")");
  if (o.max_boxes != -1 && o.max_boxes < 1)
    throw UsageError("--max-boxes must be at least 1 (got " + std::to_string(o.max_boxes) + ")");
  if (o.memory_limit != -1 && !(o.memory_limit > 0 && o.memory_limit < 1e6))
    throw UsageError("--memory-limit must be a positive number of GiB (got " +
                     std::to_string(o.memory_limit) + ")");
}

std::string fmt_double(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);  // round-trips exactly
  return buf;
}

void write_boxes_csv(const Model& m, const AspectsResult& r, const std::string& path) {
  AtomicFile f(path);
  // Written in pieces: on 3-RPR at eps 0.3 the whole file is about 2 GB.
  std::string buf = "id,status,csnc,kept";
  for (const auto& v : m.vars) buf += ',' + v.name + "_lo," + v.name + "_hi";
  buf += ",boundary\n";
  for (int b = 0; b < r.boxes.size(); ++b) {
    int c = r.csnc[b];
    const bool unexplored = r.boxes.kind(b) == UndecidedKind::Unexplored;
    buf += std::to_string(b);
    buf += r.boxes.certified(b) ? ",solution," : unexplored ? ",unexplored," : ",undecided,";
    buf += std::to_string(c);
    buf += c >= 0 && c < r.filtered ? ",1" : ",0";
    for (int v = 0; v < r.boxes.nv(); ++v) {
      buf += ',';
      buf += fmt_double(r.boxes.lo(b, v));
      buf += ',';
      buf += fmt_double(r.boxes.hi(b, v));
    }
    // Why a box stayed undecided: `constraint` (on the boundary of an additional
    // constraint, the paper's blue boxes) or `singular` (P1 or P2 failed, red and
    // black); empty for solution and unexplored boxes.
    const char* why = r.boxes.certified(b) || unexplored ? ""
                      : r.boxes.kind(b) == UndecidedKind::Constraint ? "constraint"
                                                                         : "singular";
    buf += ',';
    buf += why;
    buf += '\n';
    if (buf.size() >= (size_t(1) << 20)) {
      f.write(buf);
      buf.clear();
    }
  }
  f.write(buf);
  f.commit();
}

// Cuspidality witnesses (certified in the certificate's cuspidal and assembly sections):
// per CSNC with a witness of either kind, the counts of (a) "one pose, two commands" and
// (b) "one command, two poses", whether each search listed them all, a few pairs of (a).
nlohmann::json cuspidal_json(const AspectsResult& r) {
  const CuspidalWitnesses& w = r.cuspidal;
  nlohmann::json per = nlohmann::json::array();
  size_t next = 0;
  int64_t with_pose = 0, with_command = 0, capped = 0;
  for (WitnessSearch s : w.command_search) capped += s == WitnessSearch::Capped;
  for (size_t c = 0; c < w.count.size(); ++c) {
    const int64_t assembly = c < w.command_count.size() ? w.command_count[c] : 0;
    with_pose += w.count[c] > 0;
    with_command += assembly > 0;
    if (w.count[c] == 0 && assembly == 0) continue;
    nlohmann::json examples = nlohmann::json::array();
    while (w.count[c] > 0 && w.pose[next].csnc != int32_t(c)) ++next;
    for (size_t i = next; i < next + std::min<size_t>(3, size_t(w.count[c])); ++i)
      examples.push_back({w.pose[i].a, w.pose[i].b});
    nlohmann::json e = {{"csnc", c},
                        {"one_pose_two_commands", w.count[c]},
                        {"search", witness_search_name(w.search[c])},
                        {"examples", examples},
                        {"one_command_two_poses", assembly}};
    if (c < w.command_search.size())
      e["assembly_search"] = witness_search_name(w.command_search[c]);
    per.push_back(e);
  }
  return {{"witnesses", w.pose.size()},
          {"csncs_with_witness", with_pose},
          {"assembly_witnesses", w.command.size()},
          {"csncs_with_assembly_witness", with_command},
          {"csncs_assembly_search_capped", capped},
          {"per_csnc", per}};
}

nlohmann::json summary_json(const Model& m, const SolveOptions& o, const AspectsResult& r) {
  nlohmann::json j;
  j["version"] = ASPECTS_VERSION;
  j["git_commit"] = *ASPECTS_GIT_COMMIT ? nlohmann::json(ASPECTS_GIT_COMMIT) : nlohmann::json(nullptr);
  j["robot"] = m.name;
  j["model"] = o.model_path.empty() ? std::string("(embedded default)") : o.model_path;
  j["eps"] = o.eps;
  j["precision_bits"] = o.prec;
  j["tau"] = o.tau;
  j["threads"] = o.threads;
  j["bisect"] = o.bisect;
  j["all_links"] = o.all_links;
  j["time_seconds"] = r.seconds;
  // A stopped run is a partial result: its claims hold, its search did not finish.
  j["complete"] = r.complete();
  j["stopped_by"] = r.complete() ? nlohmann::json(nullptr) : nlohmann::json(stop_reason_name(r.stopped_by));
  for (const auto& [phase, sec] : r.phase_seconds) j["phase_seconds"][phase] = sec;
  // The same phases in their order (JSON objects are not ordered), with the peak memory.
  j["phases"] = nlohmann::json::array();
  for (size_t k = 0; k < r.phase_seconds.size(); ++k)
    j["phases"].push_back({{"name", r.phase_seconds[k].first},
                           {"seconds", r.phase_seconds[k].second},
                           {"peak_memory_mib", r.phase_peak_mib[k].second}});
  j["boxes"] = {{"total", r.boxes.size()},
                {"solution", r.solutions},
                {"undecided", r.undecided},
                {"unexplored", r.unexplored},
                {"discarded", r.discarded},
                {"processed", r.processed}};
  j["links"] = {{"neighbor", r.neighbor_count}, {"certified", r.certified_links.size()}};
  long singular = 0, boundary = 0;
  for (int b = 0; b < r.boxes.size(); ++b) {
    if (r.boxes.certified(b) || r.boxes.kind(b) == UndecidedKind::Unexplored) continue;
    singular += r.boxes.kind(b) == UndecidedKind::Singular;
    boundary += r.boxes.kind(b) == UndecidedKind::Constraint;
  }
  j["boxes"]["undecided_not_p1"] = r.undecided - singular - boundary;
  j["boxes"]["undecided_not_p2"] = singular;
  j["boxes"]["undecided_constraint_boundary"] = boundary;
  j["constraints"] = m.constraints.size();
  int64_t kept_boxes = 0;
  for (int i = 0; i < r.filtered; ++i) kept_boxes += r.csnc_sizes[i];
  j["csncs"] = {{"count", r.csnc_sizes.size()},
                {"filtered", r.filtered},
                {"filtered_boxes", kept_boxes},
                {"separated_lower_bound", r.separation.lower_bound},
                {"separated_representatives", r.separation.representatives},
                {"sizes", r.csnc_sizes}};
  j["cuspidal"] = cuspidal_json(r);
  nlohmann::json f = nlohmann::json::array();
  for (const auto& x : r.factors) f.push_back({{"expression", x.text}, {"origin", x.origin}});
  j["factors"] = f;
  // Why boxes were decided as they were: each verdict of Prove on every box that
  // survived Prune, the verdict on each undecided leaf, and what refuted discarded boxes.
  nlohmann::json attempts, undecided;
  for (int k = 0; k < kVerdicts; ++k) {
    attempts[verdict_name(Verdict(k))] = r.diagnostics.attempts[k];
    if (Verdict(k) != Verdict::Solution)
      undecided[verdict_name(Verdict(k))] = r.diagnostics.undecided[k];
  }
  j["diagnostics"] = {{"prove_verdicts", attempts},
                      {"undecided_verdicts", undecided},
                      {"refuted", {{"hc4", r.diagnostics.refuted_by_equation},
                                   {"hansen_sengupta", r.diagnostics.refuted_by_newton},
                                   {"constraint", r.diagnostics.refuted_by_constraint}}}};
  j["peak_memory_mib"] = peak_resident_bytes() / (1024.0 * 1024.0);  // the run's, outputs included
  j["domain_decided"] = decided_share(m, r);  // share of the domain's volume; 1 when complete
  return j;
}

}  // namespace

int run_solve(const SolveOptions& opts) {
  validate(opts);
#ifdef __GLIBC__
  // Blocks from 1 MiB up in their own mappings, returned to the system when freed. glibc's
  // default threshold rises with every large block freed, after which the search parts'
  // arrays, freed one by one as they are merged, stayed in the heap: on 3-RPR at eps 0.6
  // the merge raised the peak by 267 MiB instead of 96.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
  SolveOptions o = opts;
  // Resuming: the options and the model come from the checkpoint (checked against any
  // given again); the parts it holds are not searched again.
  std::unique_ptr<Checkpoint> resumed;
  if (!o.resume_dir.empty()) {
    resumed = std::make_unique<Checkpoint>(read_checkpoint(o.resume_dir + "/" + kCheckpointName));
    adopt_checkpoint(o, resumed->header);
    remove_stale_temporaries(o.out_dir);  // a killed run's
  }
  if (o.checkpoint > 0 && o.out_dir.empty())
    throw UsageError("--checkpoint needs --out DIR (the checkpoint is written there)");
  if (o.threads == 0) o.threads = int(std::max(1u, std::thread::hardware_concurrency()));
  set_working_precision(o.prec);
  set_double_fast_path(!o.mpfi_only);
  Model model = resumed ? resumed_model(o, resumed->header)
                : o.model_path.empty() ? parse_model(kDefaultModelText, "(embedded RRRRR)")
                                       : load_model(o.model_path);

  // The model's `bisect` statement chooses unless --bisect is given (a resumed run has the
  // one its checkpoint names).
  if (!resumed && !o.was_given("--bisect") && !model.bisect.empty()) o.bisect = model.bisect;

  AspectsConfig cfg;
  cfg.eps = o.eps;
  cfg.tau = o.tau;
  cfg.keep_link_proofs = !o.no_cert;
  cfg.all_links = o.all_links;
  cfg.threads = o.threads;
  parse_bisector_kind(o.bisect, cfg.bisector);  // CLI11 already checked the name
  // Limits and signals: the search stops cleanly and the outputs are a partial result.
  StopCondition stop;
  if (o.time_limit > 0) stop.set_time_limit(o.time_limit);
  if (o.max_boxes > 0) stop.set_max_boxes(o.max_boxes);
  if (o.memory_limit > 0) stop.set_memory_limit(o.memory_limit * kGiB, kReservePerBox);
  stop.set_watch_signals(true);
  watch_stop_signals();
  cfg.stop = &stop;
  const bool tty = isatty(STDERR_FILENO);
  const bool show = o.progress || tty;
  SolveProgress progress(tty);
  if (show) cfg.progress = [&](const SearchStats& s) { progress.tick(s); };

  std::unique_ptr<CertificateWriter> cert;
  if (!o.out_dir.empty()) {
    std::filesystem::create_directories(o.out_dir);
    if (!o.no_cert) {
      cert = std::make_unique<CertificateWriter>(
          o.out_dir + (o.compress_cert ? "/aspects.cert.zst" : "/aspects.cert"), model, o.prec,
          o.tau, o.eps, o.compress_cert);
      cfg.certificate = cert.get();
    }
  }
  if (resumed) {
    SearchState& st = resumed->state;
    if (cert && st.top_done) {
      cert->restore(-1, resumed->top_records);
      for (size_t k = 0; k < st.deferred.size(); ++k)
        if (st.done[k]) cert->restore(int32_t(k), resumed->records[k]);
    }
    cfg.resume = &st;
  }
  // Checkpoints: the header names what the state belongs to; a failed write keeps the
  // previous checkpoint and is reported (the run goes on; a failed last one is an error).
  CheckpointHeader header;
  bool checkpoint_failed = false;
  const std::string checkpoint_path = o.out_dir + "/" + kCheckpointName;
  if (o.checkpoint > 0) {
    header.version = ASPECTS_VERSION_FULL;
    header.model_sha256 = sha256_hex(model.source);
    header.model_text = model.source;
    header.model_file = o.model_path;
    header.eps = o.eps;
    header.tau = o.tau;
    header.precision = o.prec;
    header.bisect = o.bisect;
    header.all_links = o.all_links;
    header.no_cert = o.no_cert;
    header.defer_depth = cfg.defer_depth;
    header.checkpoint_seconds = o.checkpoint;
    header.nv = uint32_t(model.vars.size());
    cfg.checkpoint_seconds = o.checkpoint;
    cfg.checkpoint = [&](const SearchState& st, const std::vector<uint8_t>& done) {
      header.p = uint32_t(st.top.boxes.factors());
      try {
        write_checkpoint(checkpoint_path, header, st, done, cert.get());
        checkpoint_failed = false;
      } catch (const std::exception& e) {
        std::fprintf(stderr, "aspects: %s; the previous checkpoint is kept\n", e.what());
        checkpoint_failed = true;
      }
    };
  }
  AspectsResult r = compute_aspects(model, cfg);
  if (show) progress.done(model, r, resident_mib());

  if (!o.out_dir.empty()) {
    const auto outputs_start = std::chrono::steady_clock::now();
    // Three files that only read `r`, written at once: one after the other they took 116 s
    // of 3-RPR at eps 0.3 (15 GB). Each is complete or absent (atomic rename); the first
    // failure is reported once all three have ended. The index is written record by
    // record on this thread.
    auto in_thread = [&](std::function<void()> write) {
      return std::async(std::launch::async, [&o, write] {
        set_working_precision(o.prec);  // a new thread starts at MPFR's default
        write();
      });
    };
    std::future<void> certificate = in_thread([&] {
      if (cert) cert->finish(model, r);
    });
    std::future<void> csv = in_thread([&] { write_boxes_csv(model, r, o.out_dir + "/boxes.csv"); });
    std::exception_ptr failure;
    try {
      // What `aspects query` and `aspects path` read instead of re-solving.
      const std::string model_file = o.model_path.empty() ? "(embedded RRRRR)" : o.model_path;
      write_result_index(o.out_dir + "/" + kResultIndexName, model, r, o.prec, o.tau, o.eps,
                         model_file);
    } catch (...) {
      failure = std::current_exception();
    }
    for (std::future<void>* f : {&certificate, &csv}) {
      try {
        f->get();
      } catch (...) {
        if (!failure) failure = std::current_exception();
      }
    }
    if (failure) std::rethrow_exception(failure);
    // Not in time_seconds (the solver's own time, as in the paper's Table 1).
    r.phase_seconds.emplace_back(
        "outputs",
        std::chrono::duration<double>(std::chrono::steady_clock::now() - outputs_start).count());
    r.phase_peak_mib.emplace_back("outputs", peak_resident_bytes() / (1024.0 * 1024.0));
    write_file_atomically(o.out_dir + "/summary.json", summary_json(model, o, r).dump(2) + "\n");
  }
  if (!o.quiet) {
    std::printf("robot %s  eps %g  precision %ld bits  tau %g  bisect %s\n", model.name.c_str(),
                o.eps, o.prec, o.tau, o.bisect.c_str());
    if (r.complete())
      std::printf("boxes: %d (%ld solution, %ld undecided)\n", r.boxes.size(), r.solutions,
                  r.undecided);
    else
      std::printf("boxes: %d (%ld solution, %ld undecided, %ld unexplored)\n", r.boxes.size(),
                  r.solutions, r.undecided, r.unexplored);
    std::printf("links: %zu neighbour pairs, %zu certified\n", r.neighbor_count,
                r.certified_links.size());
    std::printf("CSNCs: %zu, filtered: %d\n", r.csnc_sizes.size(), r.filtered);
    std::printf("separated lower bound on the number of aspects: %d\n", r.separation.lower_bound);
    std::printf("cuspidality witnesses: %zu one pose/two commands, %zu one command/two poses\n",
                r.cuspidal.pose.size(), r.cuspidal.command.size());
    std::printf("time: %.3f s\n", r.seconds);
  }
  if (r.complete() && !o.out_dir.empty()) std::remove(checkpoint_path.c_str());  // done with it
  if (!r.complete() && checkpoint_failed) {
    std::fprintf(stderr, "aspects: stopped by %s, but the checkpoint could not be written: "
                         "this run cannot be resumed\n", stop_reason_name(r.stopped_by));
    return 1;
  }
  if (!r.complete()) {
    // On stderr even with --quiet: scripts see exit 3, a user sees why.
    std::fprintf(stderr,
                 "aspects: stopped by %s: partial result (%ld boxes unexplored); every claim "
                 "above holds, the bound counts unexplored boxes like undecided ones\n",
                 stop_reason_name(r.stopped_by), r.unexplored);
    return kExitStopped;
  }
  return 0;
}

}  // namespace aspects
