#include "solve_command.h"

#include "cli_usage.h"  // kFiniteNumber

namespace aspects {

void add_solve_command(CLI::App& app, SolveCommand& c) {
  SolveOptions& so = c.options;
  auto* solve = c.app =
      app.add_subcommand("solve", "Compute certified CSNCs and the lower bound on aspects");
  solve->add_option("MODEL", so.model_path, "robot model file; default: the embedded RRRRR five-bar");
  solve->add_option("-e,--eps", so.eps, "bisection stops at box width <= EPS")->default_val(0.1)
      ->check(kFiniteNumber);
  solve->add_option("--prec", so.prec, "MPFI precision in bits (>= 24)")->default_val(53);
  solve->add_option("--tau", so.tau, "inflation factor of the Hansen-Sengupta iteration (>= 1)")->default_val(1.01)
      ->check(kFiniteNumber);
  solve->add_option("-o,--out", so.out_dir, "write summary.json, boxes.csv and aspects.cert here");
  solve->add_option("-j,--threads", so.threads, "worker threads (0: one per core); results do not depend on it")
      ->default_val(0);
  solve->add_flag("--progress", so.progress, "progress on stderr even when it is not a terminal");
  auto* no_cert = solve->add_flag("--no-cert", so.no_cert, "do not write the certificate");
  solve->add_flag("--compress-cert", so.compress_cert,
                  "write the certificate compressed by zstd, as aspects.cert.zst (check_cert "
                  "reads it as it reads the text; about 3x smaller)")
      ->excludes(no_cert);
  solve->add_option("--cert-format", so.cert_format,
                    "certificate format: 2 (text) or 3 (the search tree, links and CSNCs in "
                    "binary, 2-8x smaller after compression; ends moved onto the grids it "
                    "codes compactly, so the boxes differ slightly from format 2's)")
      ->check(CLI::IsMember({2, 3}))
      ->default_val(2)
      ->excludes(no_cert);
  solve->add_flag("--all-links", so.all_links,
                  "prove every link between neighbouring solution boxes (default: only those "
                  "that join two components; the same CSNCs)");
  solve->add_flag("--quiet", so.quiet, "print no summary");
  solve->add_flag("--mpfi-only", so.mpfi_only,
                  "compute every interval operation with MPFI, also at 53 bits where doubles "
                  "give the same ends faster (a cross-check: the same certificate)");
  solve->add_option("--bisect", so.bisect,
                    "bisection strategy: round-robin (the paper), pose-first, or verdict (the pose "
                    "where it blocked the proof, else round robin); default: the model's "
                    "`bisect` statement, else round-robin")
      ->check(CLI::IsMember({"round-robin", "pose-first", "verdict"}));
  solve->add_option("--time-limit", so.time_limit,
                    "stop the search after SECONDS and write a partial result (exit 3)")
      ->check(kFiniteNumber);
  solve->add_option("--max-boxes", so.max_boxes,
                    "stop the search after N processed boxes and write a partial result (exit 3; "
                    "not with mpirun -n P, P > 1)");
  solve->add_option("--memory-limit", so.memory_limit,
                    "stop the search before the process (under mpirun: rank 0) needs more than "
                    "GiB of memory (exit 3)")
      ->check(kFiniteNumber);
  solve->add_option("--checkpoint", so.checkpoint,
                    "every SECONDS and when stopped, save a resumable state in the --out "
                    "directory (default with --out: 60, and when stopped; 0: none)")
      ->check(kFiniteNumber);
  solve->add_option("--resume", so.resume_dir,
                    "continue the stopped run of DIR from its checkpoint (same outputs as an "
                    "uninterrupted run)");
  solve->add_option("--subtree-stats", so.subtree_stats,
                    "write each part of the search's cost to FILE (CSV: boxes, CPU and wall "
                    "seconds, message bytes), for the scaling study; the result is unchanged");
  solve->add_option("--cut-depth", so.cut_depth,
                    "cut the search tree into subtrees at this depth (1-16; default 8, in an "
                    "MPI job deep enough for 256 subtrees a thread); the result is unchanged");
}

void record_given_options(SolveCommand& c) {
  for (const char* name : {"MODEL", "--eps", "--prec", "--tau", "--bisect", "--all-links",
                           "--no-cert", "--cert-format", "--out", "--checkpoint"})
    if (c.app->count(name) > 0) c.options.given.push_back(name);
}

}  // namespace aspects
