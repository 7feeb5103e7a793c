#pragma once
// The MPI test programs' start: a deck read and compiled on every process, or every process
// stopped (exit 2) when it does not compile.
#include <mpi.h>

#include <cstdio>
#include <memory>
#include <sstream>

#include "cli/load.hpp"
#include "solver/run/compile.hpp"

inline std::unique_ptr<mcdyna::solver::State> compiled_deck(const char* path) {
  std::ostringstream report;
  mcdyna::cli::LoadedDeck d = mcdyna::cli::load_deck(path, report);
  mcdyna::core::Diagnostics diags;
  std::unique_ptr<mcdyna::solver::State> s = mcdyna::solver::compile(d.built.model, diags);
  if (d.diags.has_errors() || !s) {
    std::fprintf(stderr, "%s does not compile\n", path);
    MPI_Abort(MPI_COMM_WORLD, 2);
  }
  return s;
}
