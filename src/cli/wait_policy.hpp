#pragma once
/// The OpenMP wait policy mcdyna runs with. libgomp reads OMP_WAIT_POLICY and GOMP_SPINCOUNT
/// once, when it loads (before main), and by default its threads spin for a while at every
/// barrier. On a machine whose cores are taken by other work a spinning thread holds a core the
/// thread it waits for needs: measured here with two other runs on the two cores, the h 0.3
/// FDS deck (400 cycles) took 3.55 s on 2 threads against 2.00 s on 1; with passive waiting
/// 1.50 s (GOMP_SPINCOUNT 1000: 1.66 s, 100000: 2.87 s).
#include <string>

namespace mcdyna::cli {

/// When neither OMP_WAIT_POLICY nor GOMP_SPINCOUNT is set, sets OMP_WAIT_POLICY=PASSIVE and
/// executes the program again (/proc/self/exe) so that libgomp starts with it; returns (and the
/// run goes on with the default policy) only if that fails. A policy the user set is kept.
void adopt_passive_wait(char** argv);

/// "PASSIVE (OMP_WAIT_POLICY)", "libgomp's default (spin, then sleep), GOMP_SPINCOUNT=1000" and
/// the like, for d3hsp.
std::string wait_policy_description();

}  // namespace mcdyna::cli
