#include "cli/partition_command.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <chrono>
#include <ostream>
#include <sstream>

#include "cli/load.hpp"
#include "deck/deck.hpp"
#include "solver/run/compile.hpp"
#include "solver/run/decomposition.hpp"
#include "solver/solids/solids.hpp"
#include "solver/spg/spg_solver.hpp"

namespace mcdyna::cli {

namespace {

using solver::parallel::RankLoad;

void print_rank(std::ostream& out, const std::string& label, const RankLoad& l) {
  fmt::print(out, "  {:>6} {:>9} {:>9} {:>6} {:>9} {:>9} {:>9} {:>9} {:>9} {:>12.1f}\n", label,
             l.owned_nodes, l.ghost_nodes, l.peers, l.elements, l.ghost_elements, l.particles,
             l.rows, l.ghost_rows, 1e6 * l.cost);
}

void print_decomposition(std::ostream& out, const solver::State& s, int ranks) {
  const auto start = std::chrono::steady_clock::now();
  const solver::parallel::Decomposition d = solver::parallel::decompose(s, ranks);
  const std::vector<RankLoad> loads = solver::parallel::rank_loads(s, d);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  fmt::print(out,
             "\n{} rank{} (recursive coordinate bisection; the SPG particles and the solids "
             "each spread over all ranks)\n",
             ranks, ranks == 1 ? "" : "s");
  fmt::print(out, "  {:>6} {:>9} {:>9} {:>6} {:>9} {:>9} {:>9} {:>9} {:>9} {:>12}\n", "rank",
             "nodes", "ghosts", "peers", "elements", "ghost el", "particles", "rows", "ghost rows",
             "cost us/cyc");
  RankLoad lowest = loads.front(), highest = loads.front(), total;
  for (const RankLoad& l : loads) {
    auto each = [&](auto member) {
      lowest.*member = std::min(lowest.*member, l.*member);
      highest.*member = std::max(highest.*member, l.*member);
      total.*member += l.*member;
    };
    each(&RankLoad::owned_nodes);
    each(&RankLoad::ghost_nodes);
    each(&RankLoad::peers);
    each(&RankLoad::elements);
    each(&RankLoad::ghost_elements);
    each(&RankLoad::particles);
    each(&RankLoad::rows);
    each(&RankLoad::ghost_rows);
    each(&RankLoad::cost);
  }
  if (ranks <= 16) {
    for (std::size_t r = 0; r < loads.size(); ++r)
      print_rank(out, std::to_string(r), loads[r]);
  } else {
    print_rank(out, "least", lowest);
    print_rank(out, "most", highest);
  }
  print_rank(out, "total", total);
  const double mean = total.cost / ranks;
  fmt::print(out,
             "  balance: largest cost / mean {:.3f}; ghost nodes {} ({:.1f} % of the {} nodes); "
             "{} element and {} row computations repeated on another rank; decomposed in {:.0f} "
             "ms\n",
             mean > 0.0 ? highest.cost / mean : 1.0, total.ghost_nodes,
             100.0 * total.ghost_nodes / std::max<solver::Index>(s.nodes.count(), 1),
             s.nodes.count(), total.elements - solver::solids_of(s).count(), total.ghost_rows, ms);
}

}  // namespace

int run_partition(const PartitionOptions& options, std::ostream& out, std::ostream& err) {
  if (const std::string problem = deck::file_problem(options.deck); !problem.empty()) {
    fmt::print(err, "mcdyna: error: deck {}: {}\n", options.deck.string(), problem);
    return 2;
  }
  for (const int r : options.ranks)
    if (r < 1) {
      fmt::print(err, "mcdyna: error: --ranks {}: a rank count is at least 1\n", r);
      return 2;
    }
  std::ostringstream report;
  LoadedDeck d = load_deck(options.deck, report);
  core::print_diagnostics(err, d.diags, d.deck.files, options.max_messages);
  if (d.diags.has_errors()) return 1;
  core::Diagnostics compile_diags;
  std::unique_ptr<solver::State> state = solver::compile(d.built.model, compile_diags);
  core::print_diagnostics(err, compile_diags, d.deck.files, options.max_messages);
  if (!state) return 1;
  // The SPG rows are those of the first kernel, as a run starts with.
  for (solver::spg::Domain* dom : solver::spg::domains_of(*state))
    solver::spg::initialise(*state, *dom);
  fmt::print(out, "{}: {} nodes, {} deformable solids, {} SPG particles\n", options.deck.string(),
             state->nodes.count(), solver::solids_of(*state).count(), [&] {
               solver::Index n = 0;
               for (const solver::spg::Domain* dom : solver::spg::domains_of(*state))
                 n += dom->count();
               return n;
             }());
  for (const int r : options.ranks)
    print_decomposition(out, *state, r);
  return 0;
}

}  // namespace mcdyna::cli
