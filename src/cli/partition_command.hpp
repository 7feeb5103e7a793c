#pragma once
/// `mcdyna partition DECK --ranks N[,N...]`: the decomposition a run over N processes would use
/// (solver/run/decomposition.hpp), computed without running the physics: per rank the
/// nodes it owns and reads, the elements and SPG rows it computes and how many of them other
/// ranks compute too, and the balance of the estimated cost.
#include <filesystem>
#include <iosfwd>
#include <vector>

namespace mcdyna::cli {

struct PartitionOptions {
  std::filesystem::path deck;
  std::vector<int> ranks;
  std::size_t max_messages = 50;
};

/// Exit code: 0 fine, 1 deck errors, 2 usage (no deck, a rank count below 1).
int run_partition(const PartitionOptions& options, std::ostream& out, std::ostream& err);

}  // namespace mcdyna::cli
