// Whether this process was started by an MPI launcher (mpirun, mpiexec, srun with a PMI
// plugin), read from the environment the launchers set, before MPI is initialised (or in a
// build without MPI, which must refuse a job of several processes: each would solve the
// whole problem and write the same outputs).
#pragma once

namespace aspects {

struct Launch {
  bool by_launcher = false;  // OMPI_COMM_WORLD_SIZE, PMI_SIZE or PMIX_RANK is set
  int processes = 1;         // the job's size: 1 without a launcher, or when only PMIx
                             // names the rank (the size is then MPI's to tell)
  int rank = 0;              // this process's rank in it
};

Launch detect_launch();

}  // namespace aspects
