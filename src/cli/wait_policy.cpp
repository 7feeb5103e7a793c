#include "cli/wait_policy.hpp"

#include <unistd.h>

#include <cstdlib>
#include <string>

namespace mcdyna::cli {

void adopt_passive_wait(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
  if (setenv("OMP_WAIT_POLICY", "PASSIVE", 1) != 0) return;
  // The binary's own path, not /proc/self/exe: the kernel names a process after the file it
  // executed, and `ps`, `top` and `pkill mcdyna` should see "mcdyna", not "exe".
  char path[4096];
  const ssize_t n = readlink("/proc/self/exe", path, sizeof(path) - 1);
  if (n > 0) {
    path[n] = '\0';
    execv(path, argv);  // fails for a binary deleted since it started: /proc/self/exe still runs it
  }
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
