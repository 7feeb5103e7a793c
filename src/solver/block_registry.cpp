// The formulations the time loop runs, one line each, in the loop's order (block.hpp): internal
// forces (hexahedra, SPG parts) before body loads and contact; the SPG parts' velocities before
// the rigid bodies sum their nodes' forces; constraints, then motions, then walls.
#include "solver/block.hpp"

namespace mcdyna::solver {

Blocks make_blocks(State& s) {
  using AddBlocks = void (*)(State&, Blocks&);
  constexpr AddBlocks kFormulations[] = {
      add_hexahedra_blocks,
      add_shell_blocks,
      add_beam_blocks,
      add_spg_blocks,
      add_joint_blocks,
      add_rigid_body_blocks,
      add_nodal_constraint_blocks,
      add_nodal_motion_blocks,
      add_rigid_wall_blocks,
      add_body_load_blocks,
      add_applied_load_blocks,
      add_global_damping_blocks,
      add_contact_blocks,
      add_tie_blocks,  // last: it passes every force on a slave node to its segment
  };
  Blocks blocks;
  for (const AddBlocks add : kFormulations)
    add(s, blocks);
  return blocks;
}

}  // namespace mcdyna::solver
