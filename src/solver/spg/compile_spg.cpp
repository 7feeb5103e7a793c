// SPG parts (*SECTION_SOLID_SPG, ELFORM 47): their hexahedra become particles (paper §2, §4.3).
// Runs after the FE solids, constraints and motions are compiled, because a particle whose node
// is shared with them is pinned (spg/spg_solver.hpp).
#include <algorithm>
#include <array>
#include <map>

#include "solver/block.hpp"
#include "solver/compile.hpp"
#include "solver/solids/hex_geometry.hpp"
#include "solver/solids/solids.hpp"
#include "solver/spg/particles.hpp"
#include "solver/spg/spg_parts.hpp"

namespace mcdyna::solver::detail {

namespace {

// Particles on the boundary of the generating mesh: corners of faces that belong to one element.
std::vector<std::uint8_t> surface_flags(const std::vector<std::array<Index, 8>>& elements,
                                        const std::vector<Index>& particle_nodes) {
  static constexpr int kFaces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                       {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::map<std::array<Index, 4>, int> faces;
  for (const auto& e : elements)
    for (const auto& f : kFaces) {
      std::array<Index, 4> key{e[static_cast<std::size_t>(f[0])], e[static_cast<std::size_t>(f[1])],
                               e[static_cast<std::size_t>(f[2])],
                               e[static_cast<std::size_t>(f[3])]};
      std::sort(key.begin(), key.end());
      if (key[0] == key[3]) continue;  // collapsed face of a degenerate element
      ++faces[key];
    }
  std::vector<std::uint8_t> flags(particle_nodes.size(), 0);
  for (const auto& [key, count] : faces) {
    if (count != 1) continue;
    for (const Index node : key) {
      const auto it = std::lower_bound(particle_nodes.begin(), particle_nodes.end(), node);
      flags[static_cast<std::size_t>(it - particle_nodes.begin())] = 1;
    }
  }
  return flags;
}

spg::SpgSettings settings_of(const model::Section& sec, const Material& mat,
                             const BulkViscosityParams& q) {
  const model::SpgSettings& in = sec.spg;
  spg::SpgSettings st;
  st.shape = static_cast<spg::KernelShape>(in.kernel_function);
  // KERNEL 2 runs as 0 (the model check notes it).
  st.kernel_update =
      in.kernel_update == 1 ? spg::KernelUpdate::eulerian : spg::KernelUpdate::updated_lagrangian;
  st.renewal_interval = std::max(in.smoothing_interval, 1);
  // FS on MAT_003 / MAT_024 overrides the section's FS (keywords.md §2.6).
  st.failure_strain = mat.failure_strain > 0.0 ? mat.failure_strain : in.failure_strain;
  st.failure_stretch = in.failure_stretch;
  st.bond_failure = in.damage_criterion == 1 && st.failure_strain < 1.0e10;
  st.damping = std::abs(in.particle_damping);
  st.surface_factor = in.surface_quadrature_factor > 0.0 ? in.surface_quadrature_factor : 1.0;
  st.mode_control = in.smoothing_scheme == 1.0 ? spg::kModeControl : 0.0;
  // ITB 1 (and 2, which the model check notes) is the original SPG; 3 is MC-SPG.
  st.stabilization = in.stabilization == 3 ? spg::Stabilization::momentum_consistent
                                           : spg::Stabilization::strain_gradient;
  st.step_estimate = spg::default_step_estimate(st.stabilization);
  st.bulk_viscosity = q;
  return st;
}

}  // namespace

void compile_spg_parts(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                       Blocks& own, core::Diagnostics& d) {
  std::vector<spg::Domain> domains;
  Nodes& nd = s.nodes;
  nd.smoothed.assign(static_cast<std::size_t>(nd.count()), 0);
  // Nodes a particle shares with something else that moves them: FE solids, SPC, motions.
  std::vector<std::uint8_t> shared(static_cast<std::size_t>(nd.count()), 0);
  for (const std::array<Index, 8>& corners : solids_of(before).nodes)
    for (const Index n : corners)
      shared[static_cast<std::size_t>(n)] = 1;
  const std::vector<std::uint8_t> held = before.held_nodes(nd.count());
  for (Index n = 0; n < nd.count(); ++n)
    if (held[static_cast<std::size_t>(n)] != 0) shared[static_cast<std::size_t>(n)] = 1;
  std::vector<std::uint8_t> in_spg(static_cast<std::size_t>(nd.count()), 0);

  for (std::size_t p = 0; p < m.parts.size(); ++p) {
    const model::Part& part = m.parts[p];
    const model::Section* sec = m.section(part.section);
    if (sec == nullptr || sec->kind != model::SectionKind::solid_spg) continue;
    const model::Material* mm = m.material(part.material);
    if (mm == nullptr || mm->kind == model::MaterialKind::rigid) continue;  // model check reports
    std::vector<std::array<Index, 8>> elements;
    std::vector<double> volumes;
    for (const model::SolidElement& el : m.solids) {
      if (el.part != part.id) continue;
      std::array<Index, 8> conn{};
      hex::Corners x{};
      for (std::size_t c = 0; c < 8; ++c) {
        conn[c] = static_cast<Index>(m.index.nodes.find(el.nodes[c]));
        for (std::size_t k = 0; k < 3; ++k)
          x[c][k] = nd.initial(static_cast<Eigen::Index>(k), conn[c]);
      }
      const double v = hex::exact_volume(x);
      if (!(v > 0.0)) {
        d.error(el.loc, "solid element {} of SPG part {} has non-positive volume {:.4g}", el.id,
                part.id, v);
      }
      elements.push_back(conn);
      volumes.push_back(v);
    }
    if (elements.empty()) continue;
    const BulkViscosityParams q = control_bulk_viscosity(m);
    const spg::GeneratedParticles gen =
        spg::particles_from_hexahedra(nd.initial, elements, volumes);
    spg::Domain dom;
    dom.part = static_cast<Index>(p);
    dom.material = static_cast<Index>(s.materials.size());
    s.materials.push_back(compile_material(m, part, d));
    s.parts[p].material = dom.material;
    const Material& mat = s.materials.back();
    dom.settings = settings_of(*sec, mat, q);
    dom.settings.objective = objective_update(m, part);
    if (dom.settings.bond_failure && dom.settings.failure_stretch >= 1.0e10) {
      d.warning(sec->loc,
                "section {}: bond failure at FS = {:g} also needs the bond stretch to exceed "
                "STRETCH (Eq. 36), which is not given (1e10): no bond will break",
                sec->id, dom.settings.failure_strain);
    }
    if (sec->spg.smoothing_scheme == 1.0) {
      d.note(sec->loc,
             "section {}: MSC = 1 (control of low-energy modes): MC-SPG with mcdyna's stiffness "
             "on the particle positions the neighbours do not reproduce, coefficient {:g} "
             "(LS-DYNA's MSC 1 scheme is not published)",
             sec->id, spg::kModeControl);
    } else if (sec->spg.smoothing_scheme != 0.0) {
      d.warning(sec->loc,
                "section {}: MSC = {:g} is neither 0 (regular MC-SPG) nor 1 (low-energy-mode "
                "control); runs as 0",
                sec->id, sec->spg.smoothing_scheme);
    }
    dom.particles.nodes = gen.nodes;
    const auto n = dom.particles.nodes.size();
    dom.particles.initial_volume = gen.volume;
    dom.fields.volume = gen.volume;
    dom.particles.initial_support = spg::support_matrices(
        gen, Vec3(sec->spg.support_scale[0], sec->spg.support_scale[1], sec->spg.support_scale[2]));
    dom.particles.surface = surface_flags(elements, dom.particles.nodes);
    dom.particles.initial_position.resize(3, static_cast<Eigen::Index>(n));
    dom.particles.mass.resize(n);
    dom.particles.shared.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto node = static_cast<std::size_t>(dom.particles.nodes[i]);
      dom.particles.initial_position.col(static_cast<Eigen::Index>(i)) =
          nd.initial.col(dom.particles.nodes[i]);
      dom.particles.mass[i] = mat.density * gen.volume[i];
      nd.mass[node] += dom.particles.mass[i];
      dom.particles.shared[i] = shared[node] || in_spg[node];
      in_spg[node] = 1;
    }
    dom.fields.pressure.assign(n, 0.0);
    dom.fields.eos_energy.assign(n, mat.eos.initial_energy);
    dom.fields.temperature.assign(n, mat.initial_temperature());
    dom.fields.viscosity.assign(n, 0.0);
    dom.fields.internal_energy.assign(n, 0.0);
    dom.fields.failed.assign(n, 0);
    dom.fields.points.deviator.setZero(6, static_cast<Eigen::Index>(n));
    if (mat.has_back_stress())
      dom.fields.points.back_stress.setZero(6, static_cast<Eigen::Index>(n));
    dom.fields.points.plastic_strain.assign(n, 0.0);
    dom.fields.points.damage.assign(n, 0.0);
    domains.push_back(std::move(dom));
  }
  // A node shared by two SPG parts is pinned in both (marked in the first only above).
  for (spg::Domain& dom : domains)
    for (std::size_t i = 0; i < dom.particles.nodes.size(); ++i) {
      int owners = 0;
      for (const spg::Domain& other : domains)
        owners += std::binary_search(other.particles.nodes.begin(), other.particles.nodes.end(),
                                     dom.particles.nodes[i]);
      if (owners > 1) dom.particles.shared[i] = 1;
    }
  // Base mass after all parts have added theirs (FE corners, particles of every SPG part).
  for (spg::Domain& dom : domains) {
    dom.particles.base_mass.resize(dom.particles.nodes.size());
    dom.particles.added_mass.assign(dom.particles.nodes.size(), 0.0);
    dom.particles.mass_request.assign(dom.particles.nodes.size(), 0.0);
    for (std::size_t i = 0; i < dom.particles.nodes.size(); ++i)
      dom.particles.base_mass[i] = nd.mass[static_cast<std::size_t>(dom.particles.nodes[i])];
  }
  for (std::size_t k = 0; k < domains.size(); ++k) {
    const model::Id part = s.parts[static_cast<std::size_t>(domains[k].part)].id;
    domains[k].index = k;
    own.push_back(spg::make_part_block(std::move(domains[k]), part));
  }
}

}  // namespace mcdyna::solver::detail
