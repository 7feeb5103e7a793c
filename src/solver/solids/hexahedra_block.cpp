// The deformable 8-node solids as one block of the time loop: the element pass (strain rate,
// stress, forces per corner, step and mass scaling, erosion) and the gather of the corner forces
// into the nodes in the fixed order of Nodes::corners.
#include <fmt/format.h>

#include "solver/block.hpp"
#include "solver/fe/added_mass.hpp"
#include "solver/fe/element_energies.hpp"
#include "solver/results.hpp"
#include "solver/solids/solid_elements.hpp"
#include "solver/solids/solids_dump.hpp"

namespace mcdyna::solver {

namespace {

class HexahedraBlock final : public DumpedBlock<HexahedraBlock> {
 public:
  explicit HexahedraBlock(long count) : count_(count) {}
  [[nodiscard]] std::string dump_name() const override { return "hexahedra"; }
  [[nodiscard]] std::string dump_layout() const override { return sizes_text(kSolidsDumpedSizes); }
  template <class Ar>
  void dumped(Ar& ar, State& s) const {
    ar(s.solids);
  }
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::elements; }
  [[nodiscard]] long elements() const override { return count_; }
  [[nodiscard]] Index numbered_elements() const override { return static_cast<Index>(count_); }
  [[nodiscard]] ElementRef element(const State& s, Index k) const override {
    const auto i = static_cast<std::size_t>(k);
    return {"solid", s.solids.ids[i], s.parts[static_cast<std::size_t>(s.solids.part[i])].id};
  }

  void add_energies(const State& s, const Eigen::Matrix3Xd& /*previous*/,
                    EnergySummary& e) const override {
    fe::add_element_energies(s.solids, e);
  }

  // Kinetic energy and momentum from each element's lumped mass (1/8 per corner), so shared
  // nodes split between parts.
  void add_part_energies(const State& s, const Eigen::Matrix3Xd& previous,
                         std::vector<PartSummary>& parts) const override {
    const Solids& so = s.solids;
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
      for (Index k = nd.corner_offsets[nn]; k < nd.corner_offsets[nn + 1]; ++k)
        sum +=
            s.solids
                .added_mass[static_cast<std::size_t>(nd.corners[static_cast<std::size_t>(k)] / 8)];
      nodal[nn] += sum / 8.0;
    }
  }

  void forces(State& s, NodalForces& f, ForceReport& r) override {
    const ElementPassResult e = solid_element_pass(
        s, ElementPassInput{s.step, s.time_control.scale_factor, s.mass_scaling_dt});
    gather_solid_forces(s, f);
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

  // The solids not eroded, with their mean stress, pressure and temperature.
  void write_state(const State& s, StateSink& sink) const override {
    const Solids& so = s.solids;
    for (const SolidBlock& block : so.blocks) {
      const model::Id part = s.parts[static_cast<std::size_t>(block.part)].id;
      for (Index e = block.begin; e < block.end; ++e) {
        const auto i = static_cast<std::size_t>(e);
        if (so.eroded[i]) continue;
        sink.cell(CellShape::hexahedron, so.nodes[i].data(),
                  {element_result(s, block, e), so.pressure[i], so.temperature[i], part});
      }
    }
  }

 private:
  long count_;
};

}  // namespace

void add_hexahedra_blocks(State& s, Blocks& blocks) {
  if (s.solids.count() > 0) blocks.push_back(std::make_unique<HexahedraBlock>(s.solids.count()));
}

}  // namespace mcdyna::solver
