// *CONTACT_... -> contact::Interface: the passes of the penalty contacts (node-on-segment, their
// stiffness scaled by SLSFAC and SFS / SFM) and the force transducers, from the sides
// contact_sides.hpp resolves. Runs after the SPG parts (their particles are slave nodes) and
// the ties (compile_ties.cpp: the tied nodes are moved onto their surfaces first).
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "solver/block.hpp"
#include "solver/compile.hpp"
#include "solver/contact/contact.hpp"
#include "solver/contact/contact_sides.hpp"

namespace mcdyna::solver::detail {

namespace {

using contact::Interface;
using contact::Pass;

// Slave nodes that start inside the master surface, said at the contact keyword: moved onto it
// (IGNORE 0) or kept as tracked offsets (IGNORE 1/2, SPG particles, rigid nodes).
void report_initial_penetrations(State& s, Interface& in, const std::vector<std::uint8_t>& particle,
                                 const model::Contact& c, int ignore, core::Diagnostics& d) {
  const contact::InitialPenetrations r = contact::resolve_initial_penetrations(s, in, particle);
  if (r.count == 0) return;
  const long kept = r.count - r.moved;
  std::string what;
  if (r.moved > 0) what = fmt::format("{} moved onto the surface", r.moved);
  if (kept > 0)
    what += fmt::format("{}{} kept as an initial offset that contact pushes only beyond{}",
                        what.empty() ? "" : ", ", kept,
                        ignore == 0 ? " (SPG particles and rigid-body nodes are not moved)"
                                    : fmt::format(" (IGNORE {})", ignore));
  d.warning(c.loc,
            "contact {}: {} slave node(s) start inside the master surface, deepest {:.4g} at "
            "node {}; {}",
            in.id, r.count, r.deepest, s.nodes.ids[static_cast<std::size_t>(r.node)], what);
}

// *CONTACT_FORCE_TRANSDUCER_PENALTY: the nodes of its sides (every node a side's parts or sets
// give, as a slave side has them), no passes.
void compile_transducer(const model::ModelDatabase& m, const std::vector<PartSurface>& parts,
                        const FaceOwners& face_owner, core::Diagnostics& d, const model::Contact& c,
                        model::Id number, std::vector<Interface>& out) {
  bool ok = true;
  auto nodes_of = [&](const model::ContactSide& side, const char* name) {
    return all_nodes(resolve_side(m, parts, face_owner, d, c, number, side, name, ok));
  };
  contact::Transducer sensor;
  sensor.active = true;
  sensor.nodes_a = nodes_of(c.a, "A (slave)");
  if (c.b.id != 0 || c.b.type == 5) sensor.nodes_b = nodes_of(c.b, "B (master)");
  if (!ok) return;
  Interface in;
  in.id = number;
  in.heading = c.heading;
  in.birth = c.birth;
  in.death = c.death > 0.0 ? c.death : 1.0e20;
  in.sensor = std::move(sensor);
  out.push_back(std::move(in));
}

// What every interface's passes read of the model's surfaces: the parts' outer faces, each
// node's penalty stiffness and the half thickness of the thickest shell on it (for
// single-surface contacts capped as capped_thickness says), the faces' owners (segment sets).
struct ContactSurfaces {
  std::vector<PartSurface> parts;
  std::vector<double> node_k;
  std::vector<double> shell_half, shell_half_single;
  FaceOwners face_owner;
  std::vector<std::uint8_t> particle;  ///< per node: an SPG particle's
  bool cap_single = true;              ///< SSTHK 0
  double slsfac = 0.1;
};

// Single-surface contacts touch a shell at min(t, 0.4 x its shortest edge) unless SSTHK = 1
// (LS-DYNA's default: a fold's crest then never touches the segments next to it).
double capped_thickness(const State& s, const std::array<Index, 4>& seg, double t) {
  double shortest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < 4; ++k) {
    const double edge =
        (s.nodes.position.col(seg[(k + 1) % 4]) - s.nodes.position.col(seg[k])).norm();
    if (edge > 0.0) shortest = std::min(shortest, edge);
  }
  return std::min(t, 0.4 * shortest);
}

ContactSurfaces contact_surfaces(const model::ModelDatabase& m, const State& s,
                                 const CompiledBlocks& before,
                                 const model::ContactControl& control) {
  ContactSurfaces cs;
  cs.parts = part_surfaces(m, s, before);
  cs.node_k = node_stiffness(s, before, cs.parts);
  cs.cap_single = control.single_surface_thickness == 0;
  // Half the thickest shell (rigid or deformable) on each node, and the same capped for
  // single-surface contacts.
  const auto node_count = static_cast<std::size_t>(s.nodes.count());
  cs.shell_half.assign(node_count, 0.0);
  cs.shell_half_single.assign(node_count, 0.0);
  cs.particle.assign(node_count, 0);
  for (const PartSurface& ps : cs.parts)
    for (const Index n : ps.particles)
      cs.particle[static_cast<std::size_t>(n)] = 1;
  for (const PartSurface& ps : cs.parts)
    for (std::size_t j = 0; j < ps.surface.segments.size(); ++j) {
      const double t = ps.shell_thickness[j];
      const double t_single = cs.cap_single ? capped_thickness(s, ps.surface.segments[j], t) : t;
      for (const Index n : ps.surface.segments[j]) {
        const auto nn = static_cast<std::size_t>(n);
        cs.shell_half[nn] = std::max(cs.shell_half[nn], 0.5 * t);
        cs.shell_half_single[nn] = std::max(cs.shell_half_single[nn], 0.5 * t_single);
      }
    }
  cs.face_owner = face_owners(cs.parts);
  cs.slsfac = control.penalty_scale > 0.0 ? control.penalty_scale : 0.1;
  return cs;
}

// The contact's kind as its passes need it: single surface (the nodes of side A against its
// own segments; SURFA 0 is every part), automatic (shells touched on both faces), both ways.
struct ContactKind {
  bool single = false, automatic = false, two_way = false;
};

ContactKind contact_kind(const model::Contact& c) {
  ContactKind k;
  k.single = c.kind == model::ContactKind::automatic_single_surface;
  k.automatic = k.single || c.kind == model::ContactKind::automatic_nodes_to_surface ||
                c.kind == model::ContactKind::automatic_surface_to_surface;
  k.two_way = c.kind == model::ContactKind::automatic_surface_to_surface ||
              c.kind == model::ContactKind::surface_to_surface || (c.soft == 2 && !k.single);
  return k;
}

// IGNORE: the contact's own, else *CONTROL_CONTACT's.
int ignore_option(const model::Contact& c, const model::ContactControl& control) {
  return c.ignore_penetration != 0 ? c.ignore_penetration : control.ignore_penetration;
}

// The interface's settings from its keyword and *CONTROL_CONTACT (no passes yet).
Interface interface_settings(const model::Contact& c, const model::ContactControl& control,
                             model::Id number, const ContactKind& kind, double slsfac,
                             core::Diagnostics& d) {
  Interface in;
  in.id = number;
  in.heading = c.heading;
  in.static_friction = c.static_friction * c.friction_scale;
  in.dynamic_friction = c.dynamic_friction * c.friction_scale;
  in.decay = c.decay;
  in.viscous_friction = c.viscous_friction * c.viscous_friction_scale;
  in.damping = c.viscous_damping / 100.0;
  in.birth = c.birth;
  in.death = c.death > 0.0 ? c.death : 1.0e20;
  in.soft_constraint = c.soft == 1;
  in.segment_based = c.soft == 2;
  in.soft_scale = c.soft_scale > 0.0 ? c.soft_scale : 0.1;
  in.sort_interval = control.bucket_interval > 0 ? control.bucket_interval : 10;
  // SOFT 2 keeps an initial penetration as the baseline contact pushes beyond (LS-DYNA's
  // segment-based contact does not move nodes out).
  in.initial_penetration = ignore_option(c, control) == 0 && !in.segment_based
                               ? contact::InitialPenetration::move
                               : contact::InitialPenetration::keep_offset;
  switch (control.penalty_option) {
    case 2:
      in.penalty_scale = contact::PenaltyScale::segment;
      break;
    case 3:
      in.penalty_scale = contact::PenaltyScale::node;
      break;
    case 1:
      in.penalty_scale = contact::PenaltyScale::smaller;
      break;
    default:
      d.warning(control.loc,
                "*CONTROL_CONTACT: PENOPT = {} runs as 1 (the smaller of the node's and the "
                "segment's stiffness); 2 and 3 are also available",
                control.penalty_option);
      in.penalty_scale = contact::PenaltyScale::smaller;
  }
  // SOFT 4 and 6 are refused by the reader (forming contacts are not there); other values
  // above 2 are not LS-DYNA's and run as 1.
  if (c.soft > 2) {
    in.soft_constraint = true;
    d.warning(c.loc, "contact {}: SOFT = {} runs as SOFT = 1 (the soft-constraint stiffness)",
              number, c.soft);
  }
  // SOFT 2 (segment-based): its stiffness and its baseline rule for initial penetrations,
  // with the penetrations found node on segment both ways (two passes whatever the keyword:
  // the segments of either side can be the ones penetrated). Edge-to-edge crossings with
  // no node through a segment are not found.
  in.segment_based_scale = {0.5 * slsfac * (kind.single ? c.penalty_scale_a : c.penalty_scale_b),
                            0.5 * slsfac * c.penalty_scale_a};
  if (in.segment_based && c.depth >= 3) {
    d.note(c.loc,
           "contact {}: SOFT 2 DEPTH = {}: edge-to-edge checks are not done (penetrations are "
           "found node on segment, both ways)",
           number, static_cast<int>(c.depth));
  }
  return in;
}

// One direction of a contact: the nodes of one side on the segments of the other (`nodes`
// with their scale factor and SST, 0: the shells'; `segments` with theirs).
struct PassSide {
  const Side& side;
  double scale = 1.0, thickness = 0.0;
};

Pass make_pass(const State& s, const ContactSurfaces& cs, const ContactKind& kind,
               const PassSide& nodes, const PassSide& segments, bool nodes_on_a) {
  Pass p;
  p.nodes = kind.two_way ? nodes.side.nodes : nodes.side.slave_nodes;
  p.nodes_on_side_a = nodes_on_a;
  p.stiffness.resize(p.nodes.size());
  p.node_half_thickness.assign(p.nodes.size(), 0.0);
  for (std::size_t i = 0; i < p.nodes.size(); ++i) {
    const auto n = static_cast<std::size_t>(p.nodes[i]);
    p.stiffness[i] = cs.slsfac * nodes.scale * cs.node_k[n];
    // Automatic contact: a shell node touches at half its shell's thickness (or SST).
    if (kind.automatic && cs.shell_half[n] > 0.0)
      p.node_half_thickness[i] = nodes.thickness > 0.0 ? 0.5 * nodes.thickness
                                 : kind.single         ? cs.shell_half_single[n]
                                                       : cs.shell_half[n];
  }
  p.surface = segments.side.surface;
  for (std::size_t j = 0; j < p.surface.segments.size(); ++j) {
    p.surface.stiffness[j] *= cs.slsfac * segments.scale;
    const double shell = segments.side.shell_thickness[j];
    const double t = segments.thickness > 0.0 ? segments.thickness
                     : kind.single && cs.cap_single && shell > 0.0
                         ? capped_thickness(s, p.surface.segments[j], shell)
                         : shell;
    // Automatic contact touches shells on both faces at half their thickness.
    if (segments.side.shell_thickness[j] > 0.0 || segments.thickness > 0.0) {
      p.surface.two_sided[j] = kind.automatic ? 1 : 0;
      p.surface.half_thickness[j] = kind.automatic ? 0.5 * t : 0.0;
    }
    if (!std::isinf(p.surface.smallest_node_mass[j])) {
      double lightest = std::numeric_limits<double>::infinity();
      for (const Index n : p.surface.segments[j])
        lightest = std::min(lightest, s.nodes.mass[static_cast<std::size_t>(n)]);
      p.surface.smallest_node_mass[j] = lightest;
    }
  }
  p.friction.setZero(3, static_cast<Eigen::Index>(p.nodes.size()));
  p.side.setZero(3, static_cast<Eigen::Index>(p.nodes.size()));
  return p;
}

// Search margin: half the largest segment plus the largest contact thickness; nodes tracked for
// an early re-sort are those of both sides.
void set_search_margin(Interface& in, const Side& a, const Side& b, bool two_way) {
  double largest = 0.0, thickest = 0.0, thickest_node = 0.0;
  for (const Pass& p : in.passes) {
    for (std::size_t j = 0; j < p.surface.segments.size(); ++j) {
      largest = std::max(largest, std::sqrt(p.surface.area[j]));
      thickest = std::max(thickest, p.surface.half_thickness[j]);
    }
    for (const double h : p.node_half_thickness)
      thickest_node = std::max(thickest_node, h);
  }
  in.capture = 0.5 * largest + thickest + thickest_node;
  in.tracked = two_way ? a.nodes : a.slave_nodes;
  in.tracked.insert(in.tracked.end(), b.nodes.begin(), b.nodes.end());
  std::sort(in.tracked.begin(), in.tracked.end());
  in.tracked.erase(std::unique(in.tracked.begin(), in.tracked.end()), in.tracked.end());
}

// A penalty contact (node on segment, one or both ways).
void compile_penalty_contact(const model::ModelDatabase& m, const ContactSurfaces& cs,
                             const model::ContactControl& control, const model::Contact& c,
                             model::Id number, State& s, std::vector<Interface>& out,
                             core::Diagnostics& d) {
  const ContactKind kind = contact_kind(c);
  bool ok = true;
  model::ContactSide side_a = c.a;
  if (kind.single && side_a.id == 0) side_a.type = 5;
  const Side a = resolve_side(m, cs.parts, cs.face_owner, d, c, number, side_a, "A (slave)", ok);
  const Side b =
      kind.single ? a
                  : resolve_side(m, cs.parts, cs.face_owner, d, c, number, c.b, "B (master)", ok);
  if (!ok) return;
  if (b.surface.segments.empty()) {
    d.error(c.loc,
            "contact {}: side B (master) has no segments (an SPG part or a node set cannot be "
            "the master surface: make it side A)",
            number);
    return;
  }
  Interface in = interface_settings(c, control, number, kind, cs.slsfac, d);
  // Single surface: side A's scale factors and thickness on both ends.
  in.passes.push_back(make_pass(s, cs, kind, PassSide{a, c.penalty_scale_a, c.thickness_a},
                                PassSide{b, kind.single ? c.penalty_scale_a : c.penalty_scale_b,
                                         kind.single ? c.thickness_a : c.thickness_b},
                                true));
  if (kind.two_way) {
    if (a.surface.segments.empty()) {
      d.note(c.loc,
             "contact {}: side A has no segments ({}): surface-to-surface runs one way, A "
             "nodes on B segments",
             number, a.has_particles ? "SPG particles" : "a node set");
    } else {
      in.passes.push_back(make_pass(s, cs, kind, PassSide{b, c.penalty_scale_b, c.thickness_b},
                                    PassSide{a, c.penalty_scale_a, c.thickness_a}, false));
    }
  }
  set_search_margin(in, a, b, kind.two_way);
  report_initial_penetrations(s, in, cs.particle, c, ignore_option(c, control), d);
  out.push_back(std::move(in));
}

}  // namespace

void compile_contacts(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                      Blocks& own, core::Diagnostics& d) {
  if (m.contacts.empty()) return;
  std::vector<Interface> interfaces;  // rcforc's order: the deck's, ties left out
  const model::ContactControl control = m.controls.contact.value_or(model::ContactControl{});
  const ContactSurfaces cs = contact_surfaces(m, s, before, control);
  for (std::size_t order = 0; order < m.contacts.size(); ++order) {
    const model::Contact& c = m.contacts[order];
    // Contacts without an ID are numbered in deck order, as LS-DYNA numbers them in rcforc.
    const model::Id number = c.id > 0 ? c.id : static_cast<model::Id>(order + 1);
    if (c.kind == model::ContactKind::force_transducer)
      compile_transducer(m, cs.parts, cs.face_owner, d, c, number, interfaces);
    else if (c.kind != model::ContactKind::tied)  // the ties' own pass (compile_ties.cpp)
      compile_penalty_contact(m, cs, control, c, number, s, interfaces, d);
  }
  contact::add_interface_blocks(std::move(interfaces), own);
}

}  // namespace mcdyna::solver::detail
