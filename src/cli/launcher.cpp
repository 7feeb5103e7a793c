#include "cli/launcher.hpp"

#include <cstdlib>
#include <string>

namespace mcdyna::cli {

namespace {

// The first of the variables that is set and a positive integer (rank: non-negative).
int read_count(const char* const* names, int fallback, int minimum) {
  for (const char* const* n = names; *n != nullptr; ++n) {
    const char* value = std::getenv(*n);
    if (value == nullptr) continue;
    try {
      std::size_t used = 0;
      const int v = std::stoi(value, &used);
      if (used == std::string(value).size() && v >= minimum) return v;
    } catch (const std::exception&) {
    }
  }
  return fallback;
}

}  // namespace

LaunchedProcesses launched_processes() {
  static const char* const kSize[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", nullptr};
  static const char* const kRank[] = {"OMPI_COMM_WORLD_RANK", "PMI_RANK", nullptr};
  return {read_count(kSize, 1, 1), read_count(kRank, 0, 0)};
}

}  // namespace mcdyna::cli
