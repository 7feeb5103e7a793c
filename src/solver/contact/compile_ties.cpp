// *CONTACT_TIED_NODES_TO_SURFACE / _SURFACE_TO_SURFACE -> the ties' block (ties.hpp): each tied
// contact's slave nodes moved onto its master segments, before the other contacts compile (they
// see the nodes where the ties put them). Runs after the SPG parts and the rigid bodies, whose
// nodes a tie refuses.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "solver/block.hpp"
#include "solver/compile.hpp"
#include "solver/contact/contact_sides.hpp"
#include "solver/contact/ties.hpp"

namespace mcdyna::solver::detail {

namespace {

// *CONTACT_TIED_NODES_TO_SURFACE / _SURFACE_TO_SURFACE: side A's nodes tied to side B's
// segments within max(0.05 sqrt(A), t) of a segment (t its shell thickness, or SBST), moved
// onto them. Refused: rigid or SPG nodes on either side, a node tied twice or tied and a
// master at once (checked over all ties in check_ties).
void compile_tie(const model::ModelDatabase& m, const std::vector<PartSurface>& parts,
                 const FaceOwners& face_owner, core::Diagnostics& d, const model::Contact& c,
                 model::Id number, State& s, std::vector<Tie>& ties) {
  bool ok = true;
  const Side a = resolve_side(m, parts, face_owner, d, c, number, c.a, "A (slave)", ok);
  const Side b = resolve_side(m, parts, face_owner, d, c, number, c.b, "B (master)", ok);
  if (!ok) return;
  if (b.surface.segments.empty()) {
    d.error(c.loc, "contact {}: side B (master) of a tied contact has no segments", number);
    return;
  }
  const std::vector<Index> nodes = all_nodes(a);
  auto refused = [&](Index n) {
    const auto i = static_cast<std::size_t>(n);
    return s.nodes.rigid_body[i] >= 0 || s.nodes.smoothed[i] != 0;
  };
  for (const auto& seg : b.surface.segments)
    for (const Index n : seg)
      if (refused(n)) {
        d.error(c.loc,
                "contact {}: side B of a tied contact has node {} of a rigid body or SPG part; "
                "tie to rigid parts with *CONSTRAINED_EXTRA_NODES",
                number, s.nodes.ids[static_cast<std::size_t>(n)]);
        return;
      }
  for (const Index n : nodes)
    if (refused(n)) {
      d.error(c.loc, "contact {}: side A of a tied contact has node {} of a rigid body or SPG part",
              number, s.nodes.ids[static_cast<std::size_t>(n)]);
      return;
    }
  std::vector<double> tolerance(b.surface.segments.size());
  for (std::size_t j = 0; j < tolerance.size(); ++j) {
    const double t = c.thickness_b > 0.0 ? c.thickness_b : b.shell_thickness[j];
    tolerance[j] = std::max(0.05 * std::sqrt(b.surface.area[j]), t);
  }
  const contact::TieResult r = contact::tie_nodes(s, nodes, b.surface, tolerance);
  if (!r.ties.empty()) {
    d.note(c.loc, "contact {}: {} node(s) tied{}", number, r.ties.size(),
           r.farthest > 0.0
               ? fmt::format(", moved onto the surface by up to {:.4g} (node {})", r.farthest,
                             s.nodes.ids[static_cast<std::size_t>(r.farthest_node)])
               : std::string());
  }
  if (!r.untied.empty()) {
    d.note(c.loc,
           "contact {}: {} node(s) of side A have no segment of side B within the tie "
           "tolerance (max(0.05 sqrt(A), t) or SBST) and are not tied, e.g. node {}",
           number, r.untied.size(), s.nodes.ids[static_cast<std::size_t>(r.untied.front())]);
  }
  ties.insert(ties.end(), r.ties.begin(), r.ties.end());
}

// Ties in slave order; a node tied twice, or tied and carrying another tie, is refused (the
// block passes each force once, one level deep).
void check_ties(const State& s, std::vector<Tie>& ties, core::Diagnostics& d) {
  std::sort(ties.begin(), ties.end(), [](const Tie& a, const Tie& b) { return a.slave < b.slave; });
  std::vector<std::uint8_t> master(static_cast<std::size_t>(s.nodes.count()), 0);
  for (const Tie& t : ties)
    for (std::size_t k = 0; k < 4; ++k)
      if (t.weights[k] != 0.0) master[static_cast<std::size_t>(t.masters[k])] = 1;
  for (std::size_t k = 0; k < ties.size(); ++k) {
    const Index n = ties[k].slave;
    const model::Id id = s.nodes.ids[static_cast<std::size_t>(n)];
    if (k > 0 && ties[k - 1].slave == n)
      d.error(core::SourceLoc{}, "node {} is tied by two tied contacts", id);
    if (master[static_cast<std::size_t>(n)])
      d.error(core::SourceLoc{},
              "node {} is tied to a surface and carries a tied node itself (chained ties are "
              "not supported)",
              id);
  }
}

}  // namespace

void compile_ties(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                  Blocks& own, core::Diagnostics& d) {
  std::vector<Tie> ties;
  std::vector<PartSurface> parts;
  FaceOwners face_owner;
  for (std::size_t order = 0; order < m.contacts.size(); ++order) {
    const model::Contact& c = m.contacts[order];
    if (c.kind != model::ContactKind::tied) continue;
    if (parts.empty()) {
      parts = part_surfaces(m, s, before);
      face_owner = face_owners(parts);
    }
    // Numbered as compile_contacts numbers every contact: its ID, else its place in the deck.
    const model::Id number = c.id > 0 ? c.id : static_cast<model::Id>(order + 1);
    compile_tie(m, parts, face_owner, d, c, number, s, ties);
  }
  if (ties.empty()) return;
  check_ties(s, ties, d);
  own.push_back(contact::make_tie_block(std::move(ties)));
}

}  // namespace mcdyna::solver::detail
