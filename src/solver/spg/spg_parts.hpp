#pragma once
/// The SPG parts' domains, each owned by its part's block (spg_block.cpp). Domain k is the k-th
/// SPG block in the loop's order: the index of its share over several processes
/// (parallel::Ownership::particles) and of State::controlling_domain.
#include <cstddef>
#include <memory>
#include <vector>

#include "model/entities.hpp"
#include "solver/spg/domain.hpp"

namespace mcdyna::solver {

class Block;           // block.hpp
class CompiledBlocks;  // block.hpp
struct State;          // state.hpp

namespace spg {

/// The block of SPG part `part` (user ID) (compile_spg.cpp).
std::unique_ptr<Block> make_part_block(Domain domain, model::Id part);

/// The domains in order: at run time from the state's blocks, during compile from the blocks
/// compiled before (the contact sides).
std::vector<const Domain*> domains_of(const State& s);
std::vector<const Domain*> domains_of(const CompiledBlocks& before);
std::vector<Domain*> domains_of(State& s);
/// Domain k (k below domains_of(s).size()).
const Domain& domain_of(const State& s, std::size_t k);
Domain& domain_of(State& s, std::size_t k);

}  // namespace spg
}  // namespace mcdyna::solver
