#include "mpi_launcher.h"

#include <cstdlib>
#include <utility>

namespace aspects {

namespace {

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  if (!v || !*v) return fallback;
  char* end = nullptr;
  const long x = std::strtol(v, &end, 10);
  return *end == '\0' && x >= 0 && x < (1L << 30) ? int(x) : fallback;
}

}  // namespace

Launch detect_launch() {
  Launch l;
  // Open MPI's mpirun sets OMPI_COMM_WORLD_*; MPICH's Hydra and srun --mpi=pmi2 set PMI_*.
  for (const auto& names : {std::pair<const char*, const char*>{"OMPI_COMM_WORLD_SIZE",
                                                                "OMPI_COMM_WORLD_RANK"},
                            std::pair<const char*, const char*>{"PMI_SIZE", "PMI_RANK"}}) {
    const int size = env_int(names.first, -1);
    if (size < 1) continue;
    l.by_launcher = true;
    l.processes = size;
    l.rank = env_int(names.second, 0);
    break;
  }
  // srun --mpi=pmix (and Open MPI's PRRTE) name the rank but not the size, which MPI
  // gives once initialised.
  if (!l.by_launcher && std::getenv("PMIX_RANK")) {
    l.by_launcher = true;
    l.rank = env_int("PMIX_RANK", 0);
  }
  return l;
}

}  // namespace aspects
