// `aspects`: thin command-line front end. Exit codes: 0 success, 1 failure,
// 2 usage or input error.
#include <CLI/CLI.hpp>

#include <functional>
#include <iostream>
#include <memory>

#include "aspects_version.h"
#include "checkpoint.h"
#include "cli_usage.h"
#include "count_command.h"
#include "figure_cli.h"
#include "model/model.h"
#include "model/model_info.h"
#include "mpi_launcher.h"
#include "number_text.h"
#include "path_command.h"
#include "query_command.h"
#include "result_index.h"
#include "solve_command.h"
#include "verify_command.h"
#if ASPECTS_MPI
#include "mpi_solve.h"
#endif

using namespace aspects;

namespace {

// The subcommands as parsed: each command's options, and which one was chosen.
struct Commands {
  CLI::App* info = nullptr;
  CLI::App* solve = nullptr;
  CLI::App* query = nullptr;
  CLI::App* path = nullptr;
  CLI::App* count = nullptr;
  CLI::App* verify = nullptr;
  std::string info_model;
  SolveOptions solve_options;
  QueryOptions query_options;
  PathOptions path_options;
  FigureCommands figures;  // plot, view, export
  CountOptions count_options;
  VerifyOptions verify_options;
};

// The numeric options are read as a pose's numbers are (apps/number_text.h): a subnormal is
// kept; inf, nan and overflow are refused, naming the option (CLI11 prefixes its name).
const CLI::Validator kFiniteNumber(
    [](std::string& text) {
      double x = 0;
      return number_problem(parse_number(text, x), text);
    },
    "");

void add_info(CLI::App& app, Commands& c) {
  c.info = app.add_subcommand("info",
                              "Print a robot model: variables, equations, Jacobian patterns");
  c.info->add_option("MODEL", c.info_model, "robot model file (.robot)")->required();
}

void add_solve(CLI::App& app, Commands& c) {
  SolveOptions& so = c.solve_options;
  auto* solve = c.solve =
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

void add_query(CLI::App& app, Commands& c) {
  QueryOptions& qo = c.query_options;
  auto* query = c.query =
      app.add_subcommand("query", "Certified commands of a pose, from a result directory");
  query->add_option("RESULT_DIR", qo.result_dir, "directory written by `aspects solve --out`")
      ->required();
  query->add_option("--pose", qo.pose, "the pose, comma-separated in pose order (e.g. 3,5)")
      ->required();
  query->add_flag("--json", qo.json, "print one JSON object");
}

void add_path(CLI::App& app, Commands& c) {
  PathOptions& po = c.path_options;
  auto* path = c.path = app.add_subcommand(
      "path", "Certified singularity-free path between two poses in one CSNC");
  path->add_option("RESULT_DIR", po.result_dir, "directory written by `aspects solve --out`")
      ->required();
  path->add_option("--from", po.from, "start pose, comma-separated in pose order")->required();
  path->add_option("--to", po.to, "goal pose, comma-separated in pose order")->required();
  // -1, the default's value inside, is refused when given: it would mean "any CSNC".
  path->add_option("--csnc", po.csnc, "stay in this CSNC (default: the largest holding both)")
      ->check([](const std::string& v) {
        return v.empty() || v[0] != '-' ? std::string()
                                        : "CSNCs are numbered from 0 (leave --csnc out for any "
                                          "CSNC), got " + v;
      });
  path->add_flag("--json", po.json, "print one JSON object");
  path->add_option("--out", po.out, "write the waypoints to FILE.csv or FILE.json (temporary name, then renamed)");
  path->add_option("--plot", po.plot, "write a PNG of the CSNC and the path (python3, matplotlib)");
}

void add_count(CLI::App& app, Commands& c) {
  CountOptions& co = c.count_options;
  auto* count = c.count = app.add_subcommand(
      "count", "Certified number of aspects (lower = upper), or certified bounds on it");
  count->add_option("MODEL", co.model_path, "robot model file; default: the embedded RRRRR five-bar");
  count->add_option("-e,--eps", co.eps, "epsilon of the first cover (refinement is adaptive after it)")
      ->check(kFiniteNumber)
      ->default_val(0.5);
  count->add_option("--min-width", co.min_width,
                    "do not bisect boxes narrower than this fraction of the domain")
      ->check(kFiniteNumber)
      ->default_val(1e-4);
  count->add_option("--time-limit", co.time_limit,
                    "stop after SECONDS and print the bounds reached (exit 3)")
      ->check(kFiniteNumber);
  count->add_option("-j,--threads", co.threads, "threads of the first cover's search (0: one per core)")
      ->default_val(0);
  count->add_flag("--json", co.json, "print one JSON object");
  count->add_flag("--progress", co.progress, "progress on stderr even when it is not a terminal");
  count->add_option("--cert", co.cert,
                    "write the count's certificate to FILE (check it with check_cert)");
}

void add_verify(CLI::App& app, Commands& c) {
  VerifyOptions& vo = c.verify_options;
  auto* verify = c.verify = app.add_subcommand(
      "verify", "Run check_cert on a result's certificate, and check that its index and "
                "summary are of the same run (hashes and counts)");
  verify->add_option("RESULT_DIR", vo.result_dir, "directory written by `aspects solve --out`")
      ->required();
  verify->add_option("-j,--threads", vo.threads, "check_cert's threads (0: its default)")
      ->check(CLI::NonNegativeNumber)
      ->default_val(0);
  verify->add_flag("--json", vo.json, "print one JSON object");
}

// The options of `solve` given on the command line: a resumed run refuses those that
// differ from its checkpoint, and the model's `bisect` statement yields to --bisect.
void record_given_options(Commands& c) {
  for (const char* name : {"MODEL", "--eps", "--prec", "--tau", "--bisect", "--all-links",
                           "--no-cert", "--cert-format", "--out", "--checkpoint"})
    if (c.solve->count(name) > 0) c.solve_options.given.push_back(name);
}

int run_command(Commands& c) {
  if (*c.info) {
    Model m = load_model(c.info_model);
    print_model_info(m, std::cout);
    return 0;
  }
  record_given_options(c);
  if (*c.query) return run_query(c.query_options);
  if (*c.path) return run_path(c.path_options);
  if (figure_command_chosen(c.figures)) return run_figure_command(c.figures);
  if (*c.count) return run_count(c.count_options);
  if (*c.verify) return run_verify(c.verify_options);
  return run_solve(c.solve_options);
}

// Runs `body`; an error is reported on stderr with its exit status.
int run_reporting_errors(const std::function<int()>& body) {
  try {
    return body();
  } catch (const IndexError& e) {
    std::cerr << "aspects: " << e.what() << '\n';
    return 2;
  } catch (const ModelError& e) {
    std::cerr << e.what() << '\n';
    return 2;
  } catch (const CheckpointError& e) {
    std::cerr << "aspects: " << e.what() << '\n';
    return 2;
  } catch (const UsageError& e) {
    std::cerr << "aspects: " << e.what() << '\n';
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "aspects: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "aspects: " << e.what() << '\n';
    return 1;
  }
}

// `aspects solve` started by an MPI launcher: an MPI job in the MPI build; refused before
// any work otherwise, since each process would solve the whole problem and write the same
// outputs.
int run_solve_in_job(Commands& c, const Launch& launch) {
#if ASPECTS_MPI
  (void)launch;
  std::unique_ptr<MpiJob> job;
  try {
    job = std::make_unique<MpiJob>();
  } catch (const std::exception& e) {
    std::cerr << "aspects: " << e.what() << '\n';
    return 1;
  }
  record_given_options(c);
  const int status = run_reporting_errors([&] { return run_solve_mpi(c.solve_options, *job); });
  job->finish(status);
  return status;
#else
  if (launch.processes == 1) return run_reporting_errors([&] { return run_command(c); });
  if (launch.rank == 0)
    std::cerr << "aspects: started by an MPI launcher as " << launch.processes
              << " processes, but this aspects was built without MPI: each process would "
                 "solve the whole problem and write the same outputs. Run it as one process, "
                 "or rebuild with -DASPECTS_MPI=ON (README \"Distributed runs (MPI)\")\n";
  return 2;
#endif
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Certified generalized aspects of parallel robots (branch and prune)", "aspects"};
  app.require_subcommand(1);
  // CLI11 handles it like --help: given to the main command it prints and exits 0, whatever
  // else is on the line; after a subcommand it is an unknown option of that subcommand.
  app.set_version_flag("--version", std::string("aspects ") + ASPECTS_VERSION +
                                        (*ASPECTS_GIT_COMMIT ? " (git " ASPECTS_GIT_COMMIT ")" : ""));

  Commands commands;
  add_info(app, commands);
  add_solve(app, commands);
  add_query(app, commands);
  add_path(app, commands);
  add_figure_commands(app, commands.figures);
  add_count(app, commands);
  add_verify(app, commands);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return report_parse_error(app, e, argc, argv);
  }
  commands.solve_options.program = argv[0];  // a stopped run prints the command that resumes it
  const Launch launch = detect_launch();
  if (*commands.solve && launch.by_launcher) return run_solve_in_job(commands, launch);
  return run_reporting_errors([&] { return run_command(commands); });
}
