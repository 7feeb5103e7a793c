#pragma once
/// How many processes an MPI launcher (mpirun, mpiexec, srun) started this one among, read from
/// the environment the launchers set: Open MPI's OMPI_COMM_WORLD_SIZE / _RANK, MPICH's and
/// Slurm's PMI_SIZE / PMI_RANK. 1 and 0 when not started by one.
namespace mcdyna::cli {

struct LaunchedProcesses {
  int size = 1;
  int rank = 0;
};

LaunchedProcesses launched_processes();

}  // namespace mcdyna::cli
