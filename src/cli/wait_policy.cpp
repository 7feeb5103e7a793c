#include "cli/wait_policy.hpp"

#include <unistd.h>

#include <cstdlib>
#include <string>

namespace mcdyna::cli {

void adopt_passive_wait(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
  if (setenv("OMP_WAIT_POLICY", "PASSIVE", 1) != 0) return;
  execv("/proc/self/exe", argv);
  // Not replaced (no /proc?): run on with the policy libgomp already took.
  unsetenv("OMP_WAIT_POLICY");
}

std::string wait_policy_description() {
  const char* policy = std::getenv("OMP_WAIT_POLICY");
  const char* spin = std::getenv("GOMP_SPINCOUNT");
  std::string out =
      policy ? std::string(policy) : std::string("libgomp's default (spin, then sleep)");
  if (policy) out += " (OMP_WAIT_POLICY)";
  if (spin) out += std::string(", GOMP_SPINCOUNT=") + spin;
  return out;
}

}  // namespace mcdyna::cli
