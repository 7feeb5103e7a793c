// The deformable beams as one block of the time loop: the element pass and the gather of the
// end forces and moments. The block owns the beams' data (beams.hpp).
#include "solver/beams/beam_elements.hpp"
#include "solver/beams/beam_results.hpp"
#include "solver/beams/beams_dump.hpp"
#include "solver/block.hpp"
#include "solver/fe/added_mass.hpp"
#include "solver/fe/element_energies.hpp"

namespace mcdyna::solver {

namespace {

class BeamsBlock final : public DumpedBlock<BeamsBlock> {
 public:
  [[nodiscard]] std::string dump_name() const override { return "beams"; }
  [[nodiscard]] std::string dump_layout() const override {
    return core::sizes_text(kBeamsDumpedSizes);
  }
  template <class Ar>
  void dumped(Ar& ar, State& /*s*/) {
    ar(bm_);
  }
  explicit BeamsBlock(Beams beams) : bm_(std::move(beams)) {}
  [[nodiscard]] const Beams& beams() const { return bm_; }
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::elements; }
  [[nodiscard]] long elements() const override { return bm_.count(); }
  [[nodiscard]] Index numbered_elements() const override { return bm_.count(); }
  [[nodiscard]] ElementRef element(const State& s, Index k) const override {
    const auto i = static_cast<std::size_t>(k);
    return {"beam", bm_.ids[i], s.parts[static_cast<std::size_t>(bm_.part[i])].id};
  }

  // Every process computes the beams whole, as the shells (shell_block.cpp).
  void mark_replicated(const State& /*s*/, std::vector<std::uint8_t>& nodes) const override {
    for (const auto& conn : bm_.nodes)
      for (const Index n : conn)
        nodes[static_cast<std::size_t>(n)] = 1;
  }

  void add_energies(const State& /*s*/, const Eigen::Matrix3Xd& /*previous*/,
                    EnergySummary& e) const override {
    const Beams& bm = bm_;
    for (std::size_t i = 0; i < bm.ids.size(); ++i)
      (bm.eroded[i] ? e.eroded_internal : e.internal) += bm.internal_energy[i];
  }

  // Kinetic energy and momentum from each element's lumped mass and end inertia.
  void add_part_energies(const State& s, const Eigen::Matrix3Xd& previous,
                         std::vector<PartSummary>& parts) const override {
    const Beams& bm = bm_;
    for (std::size_t e = 0; e < bm.ids.size(); ++e) {
      PartSummary& ps = parts[static_cast<std::size_t>(bm.part[e])];
      (bm.eroded[e] ? ps.eroded_internal : ps.internal) += bm.internal_energy[e];
      ps.added_mass += bm.added_mass[e];
      for (const Index n : bm.nodes[e])
        fe::add_corner_motion(ps, s.nodes, previous, n, 0.5 * bm.mass[e], bm.end_inertia[e]);
    }
  }

  void forces(State& s, NodalForces& f, ForceReport& r) override {
    const ElementPassResult e = beam_element_pass(
        s, bm_, BeamPassInput{s.step, s.time_control.scale_factor, s.mass_scaling_dt, s.time});
    gather_beam_forces(s, bm_, f);
    if (e.mass_changed) refresh_added_mass(s);
    const Index offset = first_element(s, *this);
    if (e.critical_step < r.critical_step) {
      r.critical_step = e.critical_step;
      r.controlling_element = offset + e.controlling;
      r.controlling_particle = -1;
    }
    if (e.inverted >= 0)
      r.fail("zero length in " + element_name(s, offset + e.inverted), true);
    else if (e.non_finite >= 0)
      r.fail("non-finite stress or step in " + element_name(s, offset + e.non_finite), false);
  }

  // The beams (lines): the mean of the fibres, and of their own the resultants in the
  // local axes r s t (LS-DYNA's elout order: axial force, shear s, shear t, torsion, moment s,
  // moment t).
  void write_state(const State& s, StateSink& sink) const override {
    sink.declare("beam_resultants", {"N", "Vs", "Vt", "T", "Ms", "Mt"});
    const Beams& bm = bm_;
    for (const BeamBlock& block : bm.blocks) {
      const model::Id part = s.parts[static_cast<std::size_t>(block.part)].id;
      for (Index e = block.begin; e < block.end; ++e) {
        const auto i = static_cast<std::size_t>(e);
        const ElementResult r = beam_result(s, bm, block, e);
        CellValues v{r, pressure_of(r), bm.temperature[i], part};
        v.id = bm.ids[i];
        v.deleted = bm.eroded[i] != 0;
        sink.cell(CellShape::line, bm.nodes[i].data(), v);
        sink.value("beam_resultants", beam_resultants(s, bm, block, e).data());
      }
    }
  }

  // The share of each end's DT2MS mass at its node, in the order of the end-force gather.
  void spread_added_mass(const State& /*s*/, std::vector<double>& nodal) const override {
    const auto count = static_cast<Index>(nodal.size());
#pragma omp parallel for schedule(static)
    for (Index n = 0; n < count; ++n) {
      const auto nn = static_cast<std::size_t>(n);
      for (Index k = bm_.end_offsets[nn]; k < bm_.end_offsets[nn + 1]; ++k)
        nodal[nn] +=
            0.5 *
            bm_.added_mass[static_cast<std::size_t>(bm_.ends[static_cast<std::size_t>(k)] / 2)];
    }
  }

 private:
  Beams bm_;
};

}  // namespace

std::unique_ptr<Block> make_beams_block(Beams beams) {
  return std::make_unique<BeamsBlock>(std::move(beams));
}

const Beams* beams_of(const State& s) {
  const BeamsBlock* b = find_block<BeamsBlock>(s);
  return b ? &b->beams() : nullptr;
}

}  // namespace mcdyna::solver
