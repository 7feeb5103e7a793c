// The ceilings of the roofline (tools/bench/roofline.py, fds_speed.sh): what this machine moves
// and computes per second on 1 and 2 threads, with the compiler flags the solver is built with.
//   triad    a[i] = b[i] + s c[i] over arrays of a given size (STREAM's triad, 24 bytes per
//            element moved, write-allocate not counted, as STREAM counts): the streaming
//            bandwidth of the level the arrays fit in (2 MiB: L2, 48 MiB: the last-level cache
//            share an SPG part at h 0.15 uses, 1 GiB: memory)
//   gather   sum_p w[p] v[col[p]] over a CSR-like list with 3-double columns, the access
//            pattern of every SPG pass (Eqs. 13, 30, 33 and the force gather): 12 bytes of
//            pair data streamed and one 24-byte column read per pair, the columns either in
//            order along the list (neighbours close in memory) or scattered at random
//   flops    independent multiply-adds in registers: the compute ceiling of scalar and
//            two-wide double code as GCC emits it without -march
//   clock    a chain of dependent integer additions, one per clock cycle: the core's clock,
//            for instructions per cycle from callgrind's instruction counts (the VM exposes
//            no hardware counters)
//   issue    eight independent integer additions per loop step: how many simple instructions
//            the core retires per cycle at most (the instruction ceiling)
// Each figure is the best of several repetitions (the machine's quietest moment).
// Build: g++ -O3 -fopenmp tools/bench/bandwidth.cpp -o bandwidth  (fds_speed.sh does it)
// Usage: bandwidth [THREADS...]      prints one line per kernel, size and thread count
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <random>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a) {
  return std::chrono::duration<double>(Clock::now() - a).count();
}

// Best time over `repeats` of `body`, after one warm-up call.
template <class Body>
double best_of(int repeats, Body&& body) {
  body();
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto start = Clock::now();
    body();
    best = std::min(best, seconds(start));
  }
  return best;
}

double triad(std::size_t bytes, int threads) {
  const std::size_t n = bytes / (3 * sizeof(double));
  std::vector<double> a(n), b(n), c(n);
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    a[i] = 0.0;
    b[i] = 1.0;
    c[i] = 2.0;
  }
  const double s = 3.0;
  const int sweeps = static_cast<int>(std::max<std::size_t>(1, (std::size_t{1} << 30) / bytes));
  const double t = best_of(5, [&] {
    for (int k = 0; k < sweeps; ++k) {
#pragma omp parallel for num_threads(threads) schedule(static)
      for (std::size_t i = 0; i < n; ++i)
        a[i] = b[i] + s * c[i];
    }
  });
  if (a[n / 2] != 7.0) std::abort();  // keeps the loop
  return 24.0 * static_cast<double>(n) * sweeps / t;
}

// Rows of `per_row` pairs over `rows` rows; the column of pair p is its row's neighbour.
struct Gather {
  std::vector<std::int32_t> offsets, column;
  std::vector<double> weight;
  std::vector<double> field;  // 3 x rows
};

Gather make_gather(std::size_t rows, int per_row, bool scattered) {
  Gather g;
  g.offsets.resize(rows + 1);
  std::mt19937 random(7);
  std::vector<std::int32_t> order(rows);
  std::iota(order.begin(), order.end(), 0);
  if (scattered) std::shuffle(order.begin(), order.end(), random);
  for (std::size_t i = 0; i < rows; ++i) {
    g.offsets[i + 1] = static_cast<std::int32_t>((i + 1) * static_cast<std::size_t>(per_row));
    for (int k = 0; k < per_row; ++k) {
      // Neighbours within a window of +-per_row rows (a particle's cell neighbourhood in a
      // well-ordered set), mapped through `order` when scattered.
      const auto near = static_cast<std::int64_t>(i) + k - per_row / 2;
      const auto j = static_cast<std::size_t>(
          std::clamp<std::int64_t>(near, 0, static_cast<std::int64_t>(rows) - 1));
      g.column.push_back(order[j]);
      g.weight.push_back(1.0 / per_row);
    }
  }
  g.field.assign(3 * rows, 1.0);
  return g;
}

// Pairs per second of the gather; `out` keeps the result alive.
double gather_rate(const Gather& g, int threads, std::vector<double>& out) {
  const auto rows = static_cast<std::int64_t>(g.offsets.size() - 1);
  out.assign(3 * static_cast<std::size_t>(rows), 0.0);
  const double t = best_of(5, [&] {
    for (int sweep = 0; sweep < 10; ++sweep) {
#pragma omp parallel for num_threads(threads) schedule(static, 256)
      for (std::int64_t i = 0; i < rows; ++i) {
        double x = 0.0, y = 0.0, z = 0.0;
        for (std::int32_t p = g.offsets[static_cast<std::size_t>(i)];
             p < g.offsets[static_cast<std::size_t>(i) + 1]; ++p) {
          const double w = g.weight[static_cast<std::size_t>(p)];
          const double* v =
              &g.field[3 * static_cast<std::size_t>(g.column[static_cast<std::size_t>(p)])];
          x += w * v[0];
          y += w * v[1];
          z += w * v[2];
        }
        out[3 * static_cast<std::size_t>(i)] = x;
        out[3 * static_cast<std::size_t>(i) + 1] = y;
        out[3 * static_cast<std::size_t>(i) + 2] = z;
      }
    }
  });
  return 10.0 * static_cast<double>(g.column.size()) / t;
}

// Multiply-adds per second: 8 independent chains of two-wide registers per thread (16
// doubles), kept in registers; the ceiling of SSE2 double code, which is what GCC emits for
// the solver's loops without -march.
double flop_rate(int threads) {
  using Pair = double __attribute__((vector_size(16)));
  const long steps = 100'000'000;
  std::vector<double> sink(static_cast<std::size_t>(threads), 0.0);
  const double t = best_of(3, [&] {
#pragma omp parallel num_threads(threads)
    {
      Pair a0 = {1.0, 1.1}, a1 = {1.2, 1.3}, a2 = {1.4, 1.5}, a3 = {1.6, 1.7};
      Pair a4 = {1.8, 1.9}, a5 = {2.0, 2.1}, a6 = {2.2, 2.3}, a7 = {2.4, 2.5};
      const Pair m = {0.999999999, 0.999999999}, c = {1e-9, 1e-9};
      for (long s = 0; s < steps; ++s) {
        a0 = a0 * m + c, a1 = a1 * m + c, a2 = a2 * m + c, a3 = a3 * m + c;
        a4 = a4 * m + c, a5 = a5 * m + c, a6 = a6 * m + c, a7 = a7 * m + c;
        // The barrier keeps the compiler from folding the steps; the chains stay in registers.
        asm volatile(""
                     : "+x"(a0), "+x"(a1), "+x"(a2), "+x"(a3), "+x"(a4), "+x"(a5), "+x"(a6),
                       "+x"(a7));
      }
      const Pair sum = a0 + a1 + a2 + a3 + a4 + a5 + a6 + a7;
      sink[static_cast<std::size_t>(omp_get_thread_num())] = sum[0] + sum[1];
    }
  });
  if (!(sink[0] > 0.0)) std::abort();
  return 2.0 * 16.0 * static_cast<double>(steps) * threads / t;  // multiply + add per double
}

// Clock cycles per second: a chain of dependent additions (one cycle each) that the compiler
// cannot fold (the asm hides the value).
// The guest's core is at times taken away (steal time): the best of many short runs.
double clock_rate() {
  const long steps = 200'000'000;
  std::uint64_t x = 0;
  const double t = best_of(9, [&] {
    for (long s = 0; s < steps; ++s) {
#if defined(__x86_64__)
      asm volatile("add $1, %0" : "+r"(x));
#else
      asm volatile("add %0, %0, #1" : "+r"(x));  // arm64
#endif
    }
  });
  if (x == 0) std::abort();
  return static_cast<double>(steps) / t;
}

// Instructions per cycle at most: eight independent additions and the loop's two per step.
double issue_rate(double clock) {
#if defined(__x86_64__)
  const long steps = 200'000'000;
  std::uint64_t sink = 0;
  const double t = best_of(9, [&] {
    // Locals, so that the eight stay in registers (a captured array is reloaded around the asm).
    std::uint64_t r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0, r6 = 0, r7 = 0;
    for (long s = 0; s < steps; ++s)
      asm volatile(
          "add $1, %0\n\tadd $1, %1\n\tadd $1, %2\n\tadd $1, %3\n\t"
          "add $1, %4\n\tadd $1, %5\n\tadd $1, %6\n\tadd $1, %7"
          : "+r"(r0), "+r"(r1), "+r"(r2), "+r"(r3), "+r"(r4), "+r"(r5), "+r"(r6), "+r"(r7));
    sink += r0 + r1 + r2 + r3 + r4 + r5 + r6 + r7;
  });
  if (sink == 0) std::abort();
  return 10.0 * static_cast<double>(steps) / t / clock;
#else
  (void)clock;
  return 0.0;
#endif
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> thread_counts;
  for (int k = 1; k < argc; ++k)
    thread_counts.push_back(std::atoi(argv[k]));
  if (thread_counts.empty()) thread_counts = {1, 2};
  const double clock = clock_rate();
  std::printf("clock: %.2f GHz (dependent additions, one per cycle)\n", clock / 1e9);
  std::printf("issue: %.2f instructions per cycle (independent additions)\n", issue_rate(clock));
  for (const int threads : thread_counts) {
    for (const std::size_t mib : {2, 48, 1024})
      std::printf("triad %5zu MiB threads %d: %7.2f GB/s\n", mib, threads,
                  triad(mib << 20, threads) / 1e9);
    std::vector<double> out;
    // 500,000 rows of 25 pairs: the h 0.15 plate's 19,547 rows x 25 scaled to past the L2.
    for (const bool scattered : {false, true}) {
      const Gather g = make_gather(500'000, 25, scattered);
      const double rate = gather_rate(g, threads, out);
      std::printf("gather %s threads %d: %7.1f M pairs/s (%.2f GB/s of pair data and columns)\n",
                  scattered ? "scattered" : "ordered  ", threads, rate / 1e6, rate * 36.0 / 1e9);
    }
    std::printf("flops threads %d: %7.2f GFLOP/s (multiply + add, double)\n", threads,
                flop_rate(threads) / 1e9);
  }
  return 0;
}
