#pragma once
/// Point-to-point copies of owned values into the processes that read them (issue 25): the
/// ghost nodes of the hexahedra and SPG rows (x, v), the ghost particles of the MC-SPG scatter
/// (a) and gather (u-hat). Built once from who owns each entity and which entities this process
/// reads without owning them; then every exchange sends each peer the same entities in the same
/// (ascending) order, `width` doubles each.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/communicator.hpp"
namespace mcdyna::solver {
using Index = std::int32_t;
}  // namespace mcdyna::solver

namespace mcdyna::solver::parallel {

class ExchangePlan {
 public:
  ExchangePlan() = default;
  /// Collective. `owner`: the process of each entity; `ghost`: per entity, this process reads it
  /// and another owns it.
  ExchangePlan(const core::Communicator& comm, const std::vector<int>& owner,
               const std::vector<std::uint8_t>& ghost, int width);

  /// Sends pack(entity, out) of each entity a peer reads, then unpack(entity, in) of each ghost.
  template <class Pack, class Unpack>
  void exchange(Pack&& pack, Unpack&& unpack) {
    if (comm_.size() == 1) return;
    for (std::size_t k = 0; k < peers_.size(); ++k) {
      double* out = send_buffer_[k].data();
      for (const Index e : send_[k]) {
        pack(e, out);
        out += width_;
      }
    }
    comm_.exchange(peers_, send_buffer_, receive_buffer_);
    for (std::size_t k = 0; k < peers_.size(); ++k) {
      const double* in = receive_buffer_[k].data();
      for (const Index e : receive_[k]) {
        unpack(e, in);
        in += width_;
      }
    }
  }

  [[nodiscard]] Index ghosts() const { return ghosts_; }  ///< entities received per exchange
  [[nodiscard]] Index sent() const { return sent_; }      ///< entities sent (over all peers)
  [[nodiscard]] Index peers() const { return static_cast<Index>(peers_.size()); }
  [[nodiscard]] std::size_t received_bytes() const {
    return static_cast<std::size_t>(ghosts_) * static_cast<std::size_t>(width_) * sizeof(double);
  }

 private:
  core::Communicator comm_;
  int width_ = 0;
  std::vector<int> peers_;
  std::vector<std::vector<Index>> send_, receive_;  ///< per peer, ascending entity indices
  std::vector<std::vector<double>> send_buffer_, receive_buffer_;
  Index ghosts_ = 0, sent_ = 0;
};

}  // namespace mcdyna::solver::parallel
