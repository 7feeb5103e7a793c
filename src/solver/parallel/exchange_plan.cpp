#include "solver/parallel/exchange_plan.hpp"

namespace mcdyna::solver::parallel {

ExchangePlan::ExchangePlan(const core::Communicator& comm, const std::vector<int>& owner,
                           const std::vector<std::uint8_t>& ghost, int width)
    : comm_(comm), width_(width) {
  // Ask each owner for its entities among the ghosts; what the others ask of this process is
  // what it sends them.
  std::vector<std::vector<Index>> wanted(static_cast<std::size_t>(comm_.size()));
  for (std::size_t e = 0; e < ghost.size(); ++e)
    if (ghost[e]) wanted[static_cast<std::size_t>(owner[e])].push_back(static_cast<Index>(e));
  const std::vector<std::vector<Index>> asked = comm_.all_to_all(wanted);
  for (int r = 0; r < comm_.size(); ++r) {
    const auto k = static_cast<std::size_t>(r);
    if (r == comm_.rank() || (wanted[k].empty() && asked[k].empty())) continue;
    peers_.push_back(r);
    receive_.push_back(wanted[k]);
    send_.push_back(asked[k]);
    receive_buffer_.emplace_back(static_cast<std::size_t>(width) * wanted[k].size());
    send_buffer_.emplace_back(static_cast<std::size_t>(width) * asked[k].size());
    ghosts_ += static_cast<Index>(wanted[k].size());
    sent_ += static_cast<Index>(asked[k].size());
  }
}

}  // namespace mcdyna::solver::parallel
