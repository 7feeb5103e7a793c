// The decomposition of a model over processes and what each rank computes
// (solver/run/decomposition.hpp).
#include "solver/run/decomposition.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "solver/spg/spg_solver.hpp"
#include "solver_support.hpp"
#include "test_support.hpp"

namespace mcdyna::test {

namespace {

using solver::Index;
namespace parallel = solver::parallel;

// An FE block 8 x 4 x 4 (edge 1) beside an SPG block 6 x 4 x 4 (KERNEL 0, DX 1.5), not joined.
std::string fe_and_spg_deck() {
  return "*KEYWORD\n*CONTROL_TERMINATION\n1.0\n"
         "*PART\nfe\n1,1,1\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,1.0,100.0,0.3\n"
         "*PART\nspg\n2,2,1\n*SECTION_SOLID_SPG\n2,47\n1.5,1.5,1.5,0,0,,15,0.0\n"
         "1,1.0E+11,1.0E+10,3,1.0,0,0,0\n" +
         box_mesh(8, 4, 4, 1.0) + box_mesh(6, 4, 4, 1.0, 1001, 1001, 2, 10.0) + "*END\n";
}

}  // namespace

TEST_CASE("Decomposition: every node owned once, SPG and FE each spread over all ranks") {
  TempDir dir;
  Simulation sim = prepare(dir, fe_and_spg_deck());
  solver::State& s = *sim.state;
  for (solver::spg::Domain* d : solver::spg::domains_of(s))
    solver::spg::initialise(s, *d);
  const Index elements = solver::solids_of(s).count();
  const Index particles = solver::spg::domain_of(s, 0).count();
  REQUIRE(elements == 128);
  REQUIRE(particles == 7 * 5 * 5);
  {
    const parallel::Decomposition one = parallel::decompose(s, 1);
    const std::vector<parallel::RankLoad> l = parallel::rank_loads(s, one);
    CHECK(l[0].owned_nodes == s.nodes.count());
    CHECK(l[0].ghost_nodes == 0);
    CHECK(l[0].peers == 0);
    CHECK(l[0].elements == elements);
    CHECK(l[0].ghost_elements == 0);
    CHECK(l[0].rows == particles);
    CHECK(l[0].ghost_rows == 0);
  }
  for (const int ranks : {2, 3, 4}) {
    const parallel::Decomposition d = parallel::decompose(s, ranks);
    const std::vector<parallel::RankLoad> loads = parallel::rank_loads(s, d);
    Index owned = 0, owned_particles = 0, computed = 0, ghost = 0;
    for (const parallel::RankLoad& l : loads) {
      owned += l.owned_nodes;
      owned_particles += l.particles;
      computed += l.elements;
      ghost += l.ghost_elements;
      // Every rank has a share of both kinds of work (PARTS_DISTRIBUTE).
      CHECK(l.elements > 0);
      CHECK(l.particles > 0);
      CHECK(l.ghost_nodes > 0);
      CHECK(l.peers >= 1);
      CHECK(l.peers < ranks);
      CHECK(l.ghost_rows > 0);
      CHECK(l.rows >= l.particles);
    }
    CHECK(owned == s.nodes.count());
    CHECK(owned_particles == particles);
    // An element computed by k ranks counts k times: the redundant ones are the ghosts.
    CHECK(computed - elements <= ghost);
    CHECK(computed > elements);
    // The particles of each rank within 15 % of the mean (RCB on 175 particles).
    for (const parallel::RankLoad& l : loads)
      CHECK(std::abs(l.particles - static_cast<double>(particles) / ranks) <=
            0.15 * particles / ranks);
    MESSAGE(ranks, " ranks: rank 0 owns ", loads[0].owned_nodes, " nodes, reads ",
            loads[0].ghost_nodes, " ghosts, computes ", loads[0].elements, " elements (",
            loads[0].ghost_elements, " ghost) and ", loads[0].rows, " rows (", loads[0].ghost_rows,
            " ghost)");
  }
}

}  // namespace mcdyna::test

namespace mcdyna::test {

TEST_CASE("mcdyna partition: the decomposition of the FDS deck per rank, without the physics") {
  const std::string deck = std::string(MCDYNA_SOURCE_DIR) + "/decks/fds/fds_h0.3.k";
  const Run r = run_mcdyna("partition " + deck + " --ranks 1,4");
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(r.output.find("15512 nodes, 1920 deformable solids, 2742 SPG particles") !=
        std::string::npos);
  CHECK(r.output.find("4 ranks (recursive coordinate bisection") != std::string::npos);
  // One rank reads no ghosts; four ranks own all the nodes between them.
  CHECK(r.output.find("ghost nodes 0 (0.0 % of the 15512 nodes)") != std::string::npos);
  CHECK(r.output.find("   total     15512") != std::string::npos);
  const Run bad = run_mcdyna("partition " + deck + " --ranks 0");
  CHECK(bad.exit_code == 2);
  CHECK(bad.output.find("a rank count is at least 1") != std::string::npos);
}

}  // namespace mcdyna::test
