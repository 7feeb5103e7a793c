#pragma once
/// glstat's internal and hourglass energy of a finite-element block whose elements carry both
/// (solids, shells): eroded elements' energies go to the eroded terms, summed in element order.
#include "solver/energy.hpp"

namespace mcdyna::solver::fe {

template <class Elements>
void add_element_energies(const Elements& el, EnergySummary& e) {
  for (std::size_t i = 0; i < el.ids.size(); ++i) {
    (el.eroded[i] ? e.eroded_internal : e.internal) += el.internal_energy[i];
    (el.eroded[i] ? e.eroded_hourglass : e.hourglass) += el.hourglass_energy[i];
  }
}

}  // namespace mcdyna::solver::fe
