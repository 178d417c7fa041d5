// `aspects`: thin command-line front end. Exit codes: 0 success, 1 failure,
// 2 usage or input error.
#include <CLI/CLI.hpp>

#include <functional>
#include <iostream>
#include <memory>

#include "aspects_version.h"
#include "cli_usage.h"
#include "count_command.h"
#include "figure_cli.h"
#include "model/model.h"
#include "model/model_info.h"
#include "mpi_launcher.h"
#include "path_command.h"
#include "query_command.h"
#include "results/result_index.h"
#include "run/checkpoint.h"
#include "run/solve_run.h"
#include "solve_command.h"
#include "verify_command.h"
#if ASPECTS_MPI
#include "distribution/mpi_solve.h"
#endif

using namespace aspects;

namespace {

// The subcommands as parsed: each command's options, and which one was chosen.
struct Commands {
  CLI::App* info = nullptr;
  CLI::App* query = nullptr;
  CLI::App* path = nullptr;
  CLI::App* count = nullptr;
  CLI::App* verify = nullptr;
  std::string info_model;
  SolveCommand solve;
  QueryOptions query_options;
  PathOptions path_options;
  FigureCommands figures;  // plot, view, export
  CountOptions count_options;
  VerifyOptions verify_options;
};

void add_info(CLI::App& app, Commands& c) {
  c.info = app.add_subcommand("info",
                              "Print a robot model: variables, equations, Jacobian patterns");
  c.info->add_option("MODEL", c.info_model, "robot model file (.robot)")->required();
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
      "path", "Certified singularity-free path between two poses in one CSNC, or through the "
              "pieces of a count");
  path->add_option("RESULT_DIR", po.result_dir,
                   "directory written by `aspects solve --out` or `aspects count --out`")
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
  path->add_option("--class", po.cls,
                   "with a count directory: stay in this sign class (e.g. +-, one sign a factor)");
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
      ->default_val(CountOptions{}.eps);  // one source of each default: count_command.h
  count->add_option("--min-width", co.min_width,
                    "do not bisect boxes narrower than this fraction of the domain")
      ->check(kFiniteNumber)
      ->default_val(CountOptions{}.min_width);
  count->add_option("--rounds", co.rounds,
                    "stop after this many rounds of refinement (the bounds reached hold)")
      ->check(CLI::Range(1, 1000000))
      ->default_val(200);
  count->add_option("--time-limit", co.time_limit,
                    "stop after SECONDS and print the bounds reached (exit 3)")
      ->check(kFiniteNumber);
  count->add_option("-j,--threads", co.threads, "threads of the first cover's search (0: one per core)")
      ->default_val(0);
  count->add_flag("--json", co.json, "print one JSON object");
  count->add_flag("--progress", co.progress, "progress on stderr even when it is not a terminal");
  count->add_option("--cert", co.cert,
                    "write the count's certificate to FILE (check it with check_cert)");
  count->add_option("--out", co.out,
                    "write DIR/count.pieces (the pieces, charts, centres and joins that "
                    "`aspects path DIR` plans through) and DIR/summary.json");
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

int run_command(Commands& c) {
  if (*c.info) {
    Model m = load_model(c.info_model);
    print_model_info(m, std::cout);
    return 0;
  }
  record_given_options(c.solve);
  if (*c.query) return run_query(c.query_options);
  if (*c.path) return run_path(c.path_options);
  if (figure_command_chosen(c.figures)) return run_figure_command(c.figures);
  if (*c.count) return run_count(c.count_options);
  if (*c.verify) return run_verify(c.verify_options);
  return run_solve(c.solve.options);
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
  record_given_options(c.solve);
  const int status = run_reporting_errors([&] { return run_solve_mpi(c.solve.options, *job); });
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
  add_solve_command(app, commands.solve);
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
  commands.solve.options.program = argv[0];  // a stopped run prints the command that resumes it
  const Launch launch = detect_launch();
  if (*commands.solve.app && launch.by_launcher) return run_solve_in_job(commands, launch);
  return run_reporting_errors([&] { return run_command(commands); });
}
