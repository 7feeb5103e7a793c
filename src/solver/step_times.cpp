#include "solver/step_times.hpp"

namespace mcdyna::solver {

const char* PhaseTimes::name(int p) {
  static const char* kNames[kCount] = {"elements",
                                       "boundary conditions",
                                       "rigid bodies",
                                       "output",
                                       "other",
                                       "SPG neighbour search",
                                       "SPG shape functions",
                                       "SPG smoothing",
                                       "SPG stress",
                                       "SPG stabilisation",
                                       "SPG forces",
                                       "SPG bond failure",
                                       "SPG step estimate",
                                       "contact",
                                       "exchange"};
  return kNames[p];
}

}  // namespace mcdyna::solver
