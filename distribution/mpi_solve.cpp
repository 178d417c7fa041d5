#include "distribution/mpi_solve.h"

#include <sched.h>

#include <exception>
#include <iostream>
#include <memory>
#include <optional>
#include <utility>

#include "distribution/mpi_identity.h"
#include "distribution/mpi_resume.h"
#include "distribution/mpi_subtrees.h"
#include "model/model.h"
#include "run/checkpoint.h"
#include "run/solve_config.h"
#include "run/solve_outputs.h"
#include "run/solve_plan.h"
#include "run/solve_run.h"

namespace aspects {

namespace {

// What a distributed search cannot do: a box budget counts the boxes one process searched
// (exactly, before each box), and the other ranks' boxes are known only when their
// subtrees come back.
void refuse_unsupported(const SolveOptions& o) {
  if (o.max_boxes != -1)
    throw UsageError("--max-boxes is not supported in a distributed run (mpirun with more "
                     "than one process): the budget counts one process's boxes; use "
                     "--time-limit, or run it as one process");
}

// The cores this rank may run on: mpirun binds each rank to one core by default (then
// `--threads 0` means one thread, not one per core of the node).
int cores_of_this_rank() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 0;
  return CPU_COUNT(&set);
}

// The exit status run_reporting_errors (apps/aspects_main.cpp) gives an error.
int exit_status_of(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const ModelError&) {
    return 2;
  } catch (const UsageError&) {
    return 2;
  } catch (const CheckpointError&) {
    return 2;
  } catch (...) {
    return 1;
  }
}

std::string what_of(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const std::exception& x) {
    return x.what();
  } catch (...) {
    return "unknown error";
  }
}

// What one rank made of the command line before the ranks compare: the run's plan (the
// checkpoint of a resumed run and the output directory's lock: rank 0's, it alone writes
// the outputs) and identity, or the error that stopped it (reported through agree_on_run).
struct PreparedRun {
  SolvePlan plan;
  RunIdentity identity;
  std::exception_ptr failure;
};

// The plan's steps (run/solve_plan.h), each rank's, with what rank 0 read of a resumed run
// shared between them. Collective (a resumed run's options and model go from rank 0 to the
// others).
PreparedRun prepare_run(const SolveOptions& given, MpiJob& job) {
  PreparedRun run;
  SolveOptions& o = run.plan.options;
  o = given;
  try {
    validate_solve_options(o);
    refuse_unsupported(o);
    if (job.rank() == 0) {
      run.plan.lock = lock_outputs(o);  // before its checkpoint is read
      run.plan.resumed = open_resumed_run(o);
    }
  } catch (...) {
    run.failure = std::current_exception();
  }
  std::optional<ResumedModel> shared_model;
  const bool resuming = rank0_resumes(job, o);
  if (resuming) {
    std::optional<ResumedModel> mine;
    if (run.plan.resumed) {
      const CheckpointHeader& h = run.plan.resumed->header;
      mine = ResumedModel{h.model_text, h.model_file.empty() ? "(embedded RRRRR)" : h.model_file};
    }
    try {
      shared_model = share_resumed_run(job, o, mine ? &*mine : nullptr);
      if (job.rank() != 0 && !shared_model)
        throw std::runtime_error("rank 0 could not resume the run");  // rank 0 says why
    } catch (...) {
      if (!run.failure) run.failure = std::current_exception();
    }
  }
  if (run.failure) return run;
  try {
    complete_options(o);
    set_precision(o);
    run.plan.model = shared_model ? parse_model(shared_model->text, shared_model->name)
                                  : solve_model(o, run.plan.resumed.get());
    if (!resuming) choose_bisect(o, run.plan.model);  // a resumed run has its checkpoint's
    run.identity = identity_of(o, run.plan.model);
  } catch (...) {
    run.failure = std::current_exception();
  }
  return run;
}

}  // namespace

int run_solve_mpi(const SolveOptions& opts, MpiJob& job) {
  SolveOptions o = opts;
  if (o.threads == 0) o.threads = cores_of_this_rank();  // 0 still: one per core
  if (job.size() == 1) return run_solve(o);
  PreparedRun run = prepare_run(o, job);
  const SolveOptions& planned = run.plan.options;
  const std::exception_ptr& failure = run.failure;
  const Agreement agreed =
      agree_on_run(job, failure ? nullptr : &run.identity, failure ? exit_status_of(failure) : 0);
  if (agreed.outcome == RankAgreement::FailedOnRank0) {
    if (job.rank() == 0) std::rethrow_exception(failure);
    return agreed.exit_code;
  }
  if (failure && job.rank() != 0)
    std::cerr << "aspects: rank " << job.rank() << ": " << what_of(failure) << '\n';
  if (agreed.outcome != RankAgreement::Agreed) {
    if (job.rank() != 0) return agreed.exit_code;
    if (agreed.exit_code == 2) throw UsageError(refusal_message(agreed));
    throw std::runtime_error(refusal_message(agreed));
  }

  const int node_ranks = job.ranks_on_this_node();  // collective: every rank asks
  job.set_workers(WorkerState::Searching);
  if (job.rank() == 0) {
    MpiSubtreeServer server(job, int(run.plan.model.vars.size()));
    // After the search the other ranks only wait (polling with sleeps): rank 0's later
    // phases take the threads of those on its node (2 ranks × 1 thread on 2 cores: 2).
    const SharedSearch shared{&server, defer_depth_for(job.size(), planned.threads),
                              planned.threads * node_ranks};
    return run_solve(std::move(run.plan), &shared);
  }
  try {
    std::optional<HeldRecords> held;
    if (!planned.no_cert) held.emplace(job.rank());
    search_subtrees_for_rank0(job, run.plan.model, engine_config(planned),
                              held ? &*held : nullptr);
    return serve_held_records_until_exit(job, held ? &*held : nullptr);
  } catch (const std::exception& e) {
    std::cerr << "aspects: rank " << job.rank() << ": " << e.what() << '\n';
    job.abort(1);
  }
}

}  // namespace aspects
