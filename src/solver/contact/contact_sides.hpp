#pragma once
/// The sides of a contact, as compile_contact.cpp builds them from *CONTACT cards: the segments
/// every part offers (free faces of its hexahedra, its shells) with LS-DYNA's standard penalty
/// stiffness (keywords.md §2.15, §2.25: a solid's free face K A^2 / V, a shell K A / longest
/// diagonal), each node's own penalty, and a side's nodes and segments by its SURFA/SURFB type.
#include <array>
#include <map>
#include <utility>
#include <vector>

#include "solver/compile.hpp"
#include "solver/contact/interface.hpp"
#include "solver/shells/shells.hpp"
#include "solver/solids/solids.hpp"
#include "solver/spg/spg_parts.hpp"

namespace mcdyna::solver::detail {

using contact::Surface;
using Face = std::array<Index, 4>;

// The segments a part offers a contact side, and its particles.
struct PartSurface {
  Surface surface;  ///< free faces of its hexahedra, then its shells (stiffness before scaling)
  std::vector<double> shell_thickness;  ///< per segment, 0 for solid faces
  std::vector<Index> particles;
  std::vector<Index> solid_nodes;  ///< every node of its deformable hexahedra
};

/// The surfaces of every part (empty for parts that offer none): the free faces of the
/// hexahedra and the shells compiled before (`before`), and of the rigid parts' elements.
std::vector<PartSurface> part_surfaces(const model::ModelDatabase& m, const State& s,
                                       const CompiledBlocks& before);

/// Penalty of a slave node: the stiffest segment (free face K A^2 / V, shell K A / diagonal)
/// holding it, or K V^(1/3) of a particle's volume (K A^2 / V of a cube of that volume). A node
/// inside a solid part (given in a node set) takes K V^(1/3) of its stiffest element; a node on
/// no element is left at 0 and contact then uses the segment's stiffness (contact_forces.cpp).
std::vector<double> node_stiffness(const State& s, const CompiledBlocks& before,
                                   const std::vector<PartSurface>& parts);

/// A face's nodes in ascending order: the key that finds a segment set's face among the parts'.
Face sorted(Face f);

/// Part and segment index of every part's segment, by its sorted nodes (for segment sets).
using FaceOwners = std::map<Face, std::pair<std::size_t, std::size_t>>;
FaceOwners face_owners(const std::vector<PartSurface>& parts);

/// One side of a contact.
struct Side {
  std::vector<Index> nodes;  ///< the nodes of its segments and its particles
  /// As slave nodes of a nodes-to-surface contact a part gives every node of its hexahedra:
  /// the interior ones meet the master surface once the elements around them erode.
  std::vector<Index> slave_nodes;
  Surface surface;
  std::vector<double> shell_thickness;
  bool has_particles = false;
};

/// The nodes and segments of one side of contact c, numbered `number` (SURFA/SURFB by its type
/// code); reports what is undefined or unsupported at the contact's card and clears `ok`.
Side resolve_side(const model::ModelDatabase& m, const std::vector<PartSurface>& parts,
                  const FaceOwners& face_owner, core::Diagnostics& d, const model::Contact& c,
                  model::Id number, const model::ContactSide& side, const char* name, bool& ok);

/// Every node of a side, its segments' and its slave nodes, ascending (the nodes a force
/// transducer watches and a tie holds).
std::vector<Index> all_nodes(const Side& side);

}  // namespace mcdyna::solver::detail
