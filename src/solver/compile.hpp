#pragma once
/// The formulations' compile passes (each in its folder, run in the registry's order by
/// run/compile.cpp's compile()) and the helpers they share. Everything the solver cannot run is
/// reported as an error at the deck location that asks for it; nothing is dropped silently.
#include <memory>

#include "core/diagnostics.hpp"
#include "model/model_database.hpp"
#include "solver/material/compile_material.hpp"
#include "solver/state.hpp"

namespace mcdyna::solver {

/// Solver indices of the nodes of a node set (sorted, unique); empty if the set is unknown.
std::vector<Index> node_set_nodes(const model::ModelDatabase& m, model::Id set);

class CompiledBlocks;  // block.hpp: the blocks of the passes before

namespace detail {
/// Node -> (element * N + corner) lists of a connectivity in element order (CSR: `offsets` per
/// node, then `corners`): the fixed order the force gathers sum in. `corners_of(e)` says how
/// many of element e's first corners count (a triangle's repeated fourth is left out).
template <std::size_t N, class CornersOf>
void build_node_corners(Index nodes, const std::vector<std::array<Index, N>>& conn,
                        CornersOf corners_of, std::vector<Index>& offsets,
                        std::vector<Index>& corners) {
  const auto n = static_cast<std::size_t>(nodes);
  offsets.assign(n + 1, 0);
  for (std::size_t e = 0; e < conn.size(); ++e)
    for (int c = 0; c < corners_of(e); ++c)
      ++offsets[static_cast<std::size_t>(conn[e][static_cast<std::size_t>(c)]) + 1];
  for (std::size_t i = 0; i < n; ++i)
    offsets[i + 1] += offsets[i];
  corners.assign(static_cast<std::size_t>(offsets[n]), 0);
  std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
  for (std::size_t e = 0; e < conn.size(); ++e)
    for (int c = 0; c < corners_of(e); ++c) {
      const auto v = static_cast<std::size_t>(conn[e][static_cast<std::size_t>(c)]);
      corners[static_cast<std::size_t>(fill[v]++)] = static_cast<Index>(N * e) + c;
    }
}

/// The indices of `elements` by the position of their part in m.parts (elements of undefined
/// parts left out), in element order.
template <class Element>
std::vector<std::vector<std::size_t>> elements_by_part(const model::ModelDatabase& m,
                                                       const std::vector<Element>& elements) {
  std::vector<std::vector<std::size_t>> by_part(m.parts.size());
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const auto p = m.index.parts.find(elements[e].part);
    if (p != model::IdIndex::kNone) by_part[static_cast<std::size_t>(p)].push_back(e);
  }
  return by_part;
}

// The formulations' compile passes (compile_*.cpp in their folders; formulations.cpp orders
// them).
void compile_solids(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                    Blocks& own, core::Diagnostics& d);
void compile_shells(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                    Blocks& own, core::Diagnostics& d);
void compile_beams(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                   Blocks& own, core::Diagnostics& d);
void compile_discrete(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                      Blocks& own, core::Diagnostics& d);
/// Adds `inertia` (per node) to the nodes' rotary inertia, giving the nodes rotations (angular
/// velocity, moment) the first time.
void add_rotary_inertia(Nodes& nd, const std::vector<double>& inertia);
void compile_rigid_bodies(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                          Blocks& own, core::Diagnostics& d);
/// *CONSTRAINED_JOINT_* and *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED: after the rigid bodies (a
/// joint node's mass may be a body's).
void compile_joints(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                    Blocks& own, core::Diagnostics& d);
/// The rigid body of part `id` (merged parts share their lead's) or of the nodal rigid body
/// `id`; -1 for neither.
Index rigid_body_of(const model::ModelDatabase& m, const State& s, model::Id id);
void compile_constraints(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                         Blocks& own, core::Diagnostics& d);
void compile_motions(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                     Blocks& own, core::Diagnostics& d);
void compile_body_loads(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                        Blocks& own, core::Diagnostics& d);
/// *LOAD_NODE, *LOAD_RIGID_BODY, *LOAD_SEGMENT (after the rigid bodies and shells).
void compile_applied_loads(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                           Blocks& own, core::Diagnostics& d);
void compile_global_damping(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                            Blocks& own, core::Diagnostics& d);
void compile_initial_velocities(const model::ModelDatabase& m, State& s,
                                const CompiledBlocks& before, core::Diagnostics& d);
void compile_planar_walls(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                          Blocks& own,
                          core::Diagnostics& d);  // walls/planar_walls.cpp
/// The nodes a rigid wall tracks: its node set (0: every node), less the exempted set, inside
/// its box, with mass and not of a rigid body; for NSID 0 within OFFSET of the plane (point,
/// normal) when OFFSET > 0.
std::vector<Index> wall_nodes(const model::ModelDatabase& m, const State& s,
                              const model::RigidWall& w, const Vec3& point, const Vec3& normal);
/// The unit direction of *DEFINE_VECTOR `id`, reported at `loc` when it is missing or zero.
Vec3 vector_direction(const model::ModelDatabase& m, model::Id id, const core::SourceLoc& loc,
                      core::Diagnostics& d);
void compile_geometric_walls(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                             Blocks& own, core::Diagnostics& d);
void compile_spg_parts(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                       Blocks& own, core::Diagnostics& d);
/// *CONTACT_TIED_...: the tied nodes moved onto their surfaces (contact/compile_ties.cpp).
void compile_ties(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                  Blocks& own, core::Diagnostics& d);
void compile_contacts(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                      Blocks& own, core::Diagnostics& d);
void compile_sensors(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                     Blocks& own,
                     core::Diagnostics& d);  // sensors/sensor_block.cpp
Index curve_index(const model::ModelDatabase& m, model::Id id);
/// Thickness of a shell element: the mean of its corners' (*ELEMENT_SHELL_THICKNESS, else the
/// section's T1..T4, a zero T2..T4 taking T1).
double shell_thickness(const model::ShellElement& el, const model::Section* sec);
/// Q1, Q2 of *CONTROL_BULK_VISCOSITY (defaults without it).
BulkViscosityParams control_bulk_viscosity(const model::ModelDatabase& m);
/// Whether the part takes the second-order objective stress update of *CONTROL_ACCURACY:
/// OSU 1, or membership of the PIDOSU part set when one is given (OSU then ignored).
bool objective_update(const model::ModelDatabase& m, const model::Part& part);
/// *CONTROL_ACCURACY's fields that do nothing here, as notes; a PIDOSU set that is not defined
/// is an error.
void check_accuracy_control(const model::ModelDatabase& m, core::Diagnostics& d);
}  // namespace detail

}  // namespace mcdyna::solver
