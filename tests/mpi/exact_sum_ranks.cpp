// Run under mpiexec with 1, 2, 3 and 4 processes (tests/CMakeLists.txt): a sum of 20,000 terms
// over 120 binary orders of magnitude, split over the processes in two ways (round robin and
// contiguous blocks), reduced by core::Communicator, must have the bits of the one-process
// ExactSum of all the terms, which every process also computes itself. The same bits for every
// process count follow. The plain MPI_SUM of the partial double sums is printed beside it: it
// generally differs between process counts.
#include <mpi.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "core/communicator.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const mcdyna::core::Communicator world = mcdyna::core::Communicator::world();
  std::mt19937_64 rng(25);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> scale(-60, 60);
  std::vector<double> terms(20000);
  for (double& t : terms)
    t = std::ldexp(unit(rng), scale(rng));
  mcdyna::core::ExactSum all;
  for (const double t : terms)
    all.add(t);
  const double expected = all.value();
  const auto n = static_cast<int>(terms.size());
  mcdyna::core::ExactSum round_robin, block;
  double plain = 0.0;
  for (int i = 0; i < n; ++i) {
    if (i % world.size() == world.rank()) {
      round_robin.add(terms[static_cast<std::size_t>(i)]);
      plain += terms[static_cast<std::size_t>(i)];
    }
    if (i * world.size() / n == world.rank()) block.add(terms[static_cast<std::size_t>(i)]);
  }
  const double a = world.sum(round_robin);
  const double b = world.sum(block);
  double plain_total = 0.0;
  MPI_Allreduce(&plain, &plain_total, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  const bool same = std::memcmp(&a, &expected, sizeof(double)) == 0 &&
                    std::memcmp(&b, &expected, sizeof(double)) == 0;
  const double smallest = world.min(static_cast<double>(world.rank()));
  if (world.rank() == 0)
    std::printf("%d processes: ExactSum %a (one process: %a) %s; plain MPI_SUM %a; min %g\n",
                world.size(), a, expected, same ? "same bits" : "DIFFERENT", plain_total, smallest);
  MPI_Finalize();
  return same && smallest == 0.0 ? 0 : 1;
}
