// The deformable solids (*ELEMENT_SOLID of parts with a solid section, not rigid, not SPG): one
// block per part, their materials, volumes, masses (given to the nodes) and integration points.
#include <algorithm>
#include <utility>

#include "solver/compile.hpp"
#include "solver/solids/hex_geometry.hpp"
#include "solver/solids/solids.hpp"

namespace mcdyna::solver::detail {

namespace {

// Number of distinct nodes of a connectivity: 8 for a hexahedron, 6 for a pentahedron (wedge)
// and 4 for a tetrahedron written as degenerate hexahedra with repeated nodes.
int distinct_nodes(const std::array<Index, 8>& conn) {
  std::array<Index, 8> sorted = conn;
  std::sort(sorted.begin(), sorted.end());
  return static_cast<int>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
}

void allocate_solid_state(Solids& so, Index points, bool back_stress) {
  const auto n = static_cast<std::size_t>(so.count());
  so.volume = so.initial_volume;
  so.internal_energy.assign(n, 0.0);
  so.hourglass_energy.assign(n, 0.0);
  so.hourglass_force.assign(12 * n, 0.0);
  so.viscosity.assign(n, 0.0);
  so.time_step.assign(n, 0.0);
  so.added_mass.assign(n, 0.0);
  so.eroded.assign(n, 0);
  so.corner_force.assign(24 * n, 0.0);
  so.pressure.assign(n, 0.0);
  so.points.deviator.setZero(6, points);
  if (back_stress) so.points.back_stress.setZero(6, points);
  so.points.plastic_strain.assign(static_cast<std::size_t>(points), 0.0);
  so.points.damage.assign(static_cast<std::size_t>(points), 0.0);
}

}  // namespace

void compile_solids(const model::ModelDatabase& m, State& s, const CompiledBlocks& /*before*/,
                    Blocks& own, core::Diagnostics& d) {
  Nodes& nd = s.nodes;
  // Solids grouped per deformable part (parts in deck order) into blocks.
  std::vector<std::vector<std::size_t>> by_part(m.parts.size());
  for (std::size_t e = 0; e < m.solids.size(); ++e) {
    const auto p = m.index.parts.find(m.solids[e].part);
    if (p != model::IdIndex::kNone) by_part[static_cast<std::size_t>(p)].push_back(e);
  }
  Solids so;
  Index points = 0;
  bool back = false;
  for (std::size_t p = 0; p < m.parts.size(); ++p) {
    const model::Part& part = m.parts[p];
    const model::Material* mat = m.material(part.material);
    const model::Section* sec = m.section(part.section);
    const bool rigid = mat != nullptr && mat->kind == model::MaterialKind::rigid;
    // SPG parts become particles (compile_spg.cpp), not elements.
    if (!rigid && !by_part[p].empty() && sec != nullptr &&
        sec->kind != model::SectionKind::solid_spg) {
      SolidBlock b;
      b.part = static_cast<Index>(p);
      b.formulation = sec->element_formulation == 2 ? SolidFormulation::selective_reduced
                                                    : SolidFormulation::one_point;
      b.points_per_element = b.formulation == SolidFormulation::one_point ? 1 : 8;
      b.hourglass = hourglass_of(m, part, b.bulk_viscosity);
      b.objective = objective_update(m, part);
      b.material = static_cast<Index>(s.materials.size());
      s.materials.push_back(compile_material(m, part, d));
      s.parts[p].material = b.material;
      b.begin = so.count();
      b.point_begin = points;
      const Material& cm = s.materials.back();
      std::array<int, 3> degenerate{};  // tetrahedra, pentahedra, other
      for (const std::size_t e : by_part[p]) {
        const model::SolidElement& el = m.solids[e];
        std::array<Index, 8> conn{};
        hex::Corners x{};
        for (int c = 0; c < 8; ++c) {
          conn[static_cast<std::size_t>(c)] =
              static_cast<Index>(m.index.nodes.find(el.nodes[static_cast<std::size_t>(c)]));
          for (int k = 0; k < 3; ++k)
            x[static_cast<std::size_t>(c)][static_cast<std::size_t>(k)] =
                nd.initial(k, conn[static_cast<std::size_t>(c)]);
        }
        // The volume the formulation measures (so the relative volume starts at exactly 1);
        // the mass from the exact volume: for a distorted or degenerate element the one-point
        // volume differs from it (a tetrahedron's by ~40 %), and mass must not.
        const double exact = hex::exact_volume(x);
        const double v0 =
            b.formulation == SolidFormulation::one_point ? hex::centre_volume(x) : exact;
        const double mass = cm.density * exact;
        const int distinct = distinct_nodes(conn);
        if (distinct < 8) ++degenerate[distinct == 4 ? 0 : (distinct == 6 ? 1 : 2)];
        if (!(v0 > 0.0)) {
          d.error(el.loc,
                  "solid element {} of part {} has non-positive volume {:.4g} "
                  "(node order inverted or element collapsed)",
                  el.id, part.id, v0);
        }
        so.ids.push_back(el.id);
        so.nodes.push_back(conn);
        so.part.push_back(static_cast<Index>(p));
        so.initial_volume.push_back(v0);
        so.mass.push_back(mass);
        so.eos_energy.push_back(cm.eos.initial_energy);
        so.temperature.push_back(cm.initial_temperature());
        for (const Index v : conn)
          nd.mass[static_cast<std::size_t>(v)] += mass / 8.0;
      }
      if (degenerate[0] + degenerate[1] + degenerate[2] > 0) {
        d.warning(part.loc,
                  "part {}: degenerate hexahedra (repeated nodes): {} tetrahedra, {} pentahedra, "
                  "{} other; they run as ELFORM {} hexahedra with their exact mass, stiffer and "
                  "less accurate than true tetrahedron/pentahedron elements",
                  part.id, degenerate[0], degenerate[1], degenerate[2],
                  sec->element_formulation == 2 ? 2 : 1);
      }
      b.end = so.count();
      points += (b.end - b.begin) * b.points_per_element;
      back = back || cm.has_back_stress();
      so.blocks.push_back(b);
    }
  }
  if (so.count() == 0) return;
  allocate_solid_state(so, points, back);
  build_node_corners(
      nd.count(), so.nodes, [](std::size_t) { return 8; }, so.corner_offsets, so.node_corners);
  own.push_back(make_hexahedra_block(std::move(so)));
}
}  // namespace mcdyna::solver::detail
