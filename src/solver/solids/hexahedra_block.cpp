// The deformable 8-node solids as one block of the time loop: the element pass (strain rate,
// stress, forces per corner, step and mass scaling, erosion) and the gather of the corner forces
// into the nodes in the fixed order of Nodes::corners.
#include <fmt/format.h>

#include <memory>
#include <utility>

#include "solver/block.hpp"
#include "solver/fe/added_mass.hpp"
#include "solver/fe/element_energies.hpp"
#include "solver/results.hpp"
#include "solver/solids/solid_elements.hpp"
#include "solver/solids/solids.hpp"
#include "solver/solids/solids_dump.hpp"

namespace mcdyna::solver {

namespace {

// Result of element `e` of `block`: the mean of its points' stress and plastic strain, the
// largest damage.
ElementResult element_result(const Solids& so, const SolidBlock& block, Index e) {
  ElementResult r;
  const int np = block.points_per_element;
  const Index first = block.point_begin + np * (e - block.begin);
  const auto& pts = so.points;
  std::array<double, 6> dev{};
  for (Index p = first; p < first + np; ++p) {
    for (int k = 0; k < 6; ++k)
      dev[static_cast<std::size_t>(k)] += pts.deviator(k, p) / np;
    r.plastic_strain += pts.plastic_strain[static_cast<std::size_t>(p)] / np;
    r.damage = std::max(r.damage, pts.damage[static_cast<std::size_t>(p)]);
  }
  set_stress(r, dev, so.pressure[static_cast<std::size_t>(e)]);
  return r;
}

class HexahedraBlock final : public DumpedBlock<HexahedraBlock> {
 public:
  explicit HexahedraBlock(Solids solids) : solids_(std::move(solids)) {}
  [[nodiscard]] const Solids& solids() const { return solids_; }
  [[nodiscard]] Solids& solids() { return solids_; }
  [[nodiscard]] std::string dump_name() const override { return "hexahedra"; }
  [[nodiscard]] std::string dump_layout() const override {
    return core::sizes_text(kSolidsDumpedSizes);
  }
  template <class Ar>
  void dumped(Ar& ar, State& /*s*/) {
    ar(solids_);
  }
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::elements; }
  [[nodiscard]] long elements() const override { return solids_.count(); }
  [[nodiscard]] Index numbered_elements() const override { return solids_.count(); }
  [[nodiscard]] ElementRef element(const State& s, Index k) const override {
    const auto i = static_cast<std::size_t>(k);
    return {"solid", solids_.ids[i], s.parts[static_cast<std::size_t>(solids_.part[i])].id};
  }

  void add_energies(const State& /*s*/, const Eigen::Matrix3Xd& /*previous*/,
                    EnergySummary& e) const override {
    fe::add_element_energies(solids_, e);
  }

  // Kinetic energy and momentum from each element's lumped mass (1/8 per corner), so shared
  // nodes split between parts.
  void add_part_energies(const State& s, const Eigen::Matrix3Xd& previous,
                         std::vector<PartSummary>& parts) const override {
    const Solids& so = solids_;
    for (std::size_t e = 0; e < so.ids.size(); ++e) {
      PartSummary& ps = parts[static_cast<std::size_t>(so.part[e])];
      (so.eroded[e] ? ps.eroded_internal : ps.internal) += so.internal_energy[e];
      ps.hourglass += so.hourglass_energy[e];
      ps.added_mass += so.added_mass[e];
      const double m = so.mass[e] / 8.0;
      for (const Index n : so.nodes[e])
        fe::add_corner_motion(ps, s.nodes, previous, n, m);
    }
  }

  // Each element's DT2MS mass, 1/8 to each corner, in the order of the corner-force gather.
  void spread_added_mass(const State& s, std::vector<double>& nodal) const override {
    const Nodes& nd = s.nodes;
#pragma omp parallel for schedule(static)
    for (Index n = 0; n < nd.count(); ++n) {
      const auto nn = static_cast<std::size_t>(n);
      double sum = 0.0;
      for (Index k = solids_.corner_offsets[nn]; k < solids_.corner_offsets[nn + 1]; ++k)
        sum += solids_.added_mass[static_cast<std::size_t>(
            solids_.node_corners[static_cast<std::size_t>(k)] / 8)];
      nodal[nn] += sum / 8.0;
    }
  }

  void forces(State& s, NodalForces& f, ForceReport& r) override {
    const ElementPassResult e = solid_element_pass(
        s, solids_, ElementPassInput{s.step, s.time_control.scale_factor, s.mass_scaling_dt});
    gather_solid_forces(s, solids_, f);
    if (e.mass_changed) refresh_added_mass(s);
    if (e.critical_step < r.critical_step) {
      r.critical_step = e.critical_step;
      r.controlling_element = e.controlling;
    }
    if (e.inverted >= 0)
      r.fail("negative volume in " + element_name(s, e.inverted), true);
    else if (e.non_finite >= 0)
      r.fail("non-finite stress or wave speed in " + element_name(s, e.non_finite), false);
    else if (e.runaway >= 0)
      r.fail(runaway_message(s, e.runaway, "volume"), false);
  }

  // The solids with their mean stress, pressure and temperature.
  void write_state(const State& s, StateSink& sink) const override {
    const Solids& so = solids_;
    for (const SolidBlock& block : so.blocks) {
      const model::Id part = s.parts[static_cast<std::size_t>(block.part)].id;
      for (Index e = block.begin; e < block.end; ++e) {
        const auto i = static_cast<std::size_t>(e);
        CellValues v{element_result(so, block, e), so.pressure[i], so.temperature[i], part};
        v.id = so.ids[i];
        v.deleted = so.eroded[i] != 0;
        sink.cell(CellShape::hexahedron, so.nodes[i].data(), v);
      }
    }
  }

 private:
  Solids solids_;
};

}  // namespace

std::unique_ptr<Block> make_hexahedra_block(Solids solids) {
  return std::make_unique<HexahedraBlock>(std::move(solids));
}

const Solids& solids_of(const State& s) {
  return owned_by(s, &HexahedraBlock::solids);
}

const Solids& solids_of(const CompiledBlocks& before) {
  return owned_by(before, &HexahedraBlock::solids);
}

Solids* solids_in(State& s) {
  for (const std::unique_ptr<Block>& b : s.blocks)
    if (auto* found = dynamic_cast<HexahedraBlock*>(b.get())) return &found->solids();
  return nullptr;
}

}  // namespace mcdyna::solver
