#pragma once
/// The inertia of a run's deformable parts (issue 47): their kinetic over internal energy and the
/// mass DT2MS added to them, followed at every output so the run's summary says whether a run
/// meant to be quasi-static stayed so, the check LS-DYNA users make on glstat and matsum. Rigid
/// bodies are left out: a spinning screw's kinetic energy says nothing of the plate's inertia.
#include <Eigen/Core>

#include <iosfwd>
#include <vector>

#include "solver/state.hpp"

namespace mcdyna::io {

class InertiaRecord {
 public:
  /// One sample at an output (process 0, after the outputs' gather); `previous` = v^{n-1/2}.
  void add(const solver::State& s, const Eigen::Matrix3Xd& previous);
  /// The summary lines; nothing without a sample or a deformable part.
  void print(std::ostream& out) const;

  /// Samples with internal energy below this share of its largest are left out of the largest
  /// KE/IE: at the first touch both energies are round-off and their ratio says nothing.
  static constexpr double kInternalFloor = 0.01;

 private:
  struct Sample {
    double time = 0.0, kinetic = 0.0, internal = 0.0, added_mass = 0.0;
  };
  std::vector<Sample> samples_;
  bool deformable_ = false;
};

}  // namespace mcdyna::io
