// The deformable shells as one block of the time loop: the element pass and the gather of the
// corner forces and moments into the nodes.
#include <memory>
#include <utility>

#include "solver/block.hpp"
#include "solver/fe/added_mass.hpp"
#include "solver/fe/element_energies.hpp"
#include "solver/shells/shell_elements.hpp"
#include "solver/shells/shell_result.hpp"
#include "solver/shells/shells.hpp"
#include "solver/shells/shells_dump.hpp"

namespace mcdyna::solver {

namespace {

class ShellsBlock final : public DumpedBlock<ShellsBlock> {
 public:
  [[nodiscard]] std::string dump_name() const override { return "shells"; }
  [[nodiscard]] std::string dump_layout() const override {
    return core::sizes_text(kShellsDumpedSizes);
  }
  template <class Ar>
  void dumped(Ar& ar, State& /*s*/) {
    ar(shells_);
  }
  explicit ShellsBlock(Shells shells) : shells_(std::move(shells)) {}
  [[nodiscard]] const Shells& shells() const { return shells_; }
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::elements; }
  [[nodiscard]] long elements() const override { return shells_.count(); }
  [[nodiscard]] Index numbered_elements() const override { return shells_.count(); }
  [[nodiscard]] ElementRef element(const State& s, Index k) const override {
    const auto i = static_cast<std::size_t>(k);
    return {"shell", shells_.ids[i], s.parts[static_cast<std::size_t>(shells_.part[i])].id};
  }

  // Every process computes the shells whole (and so moves their nodes itself): the same bits
  // for any process count, without a share of the work.
  void mark_replicated(const State& /*s*/, std::vector<std::uint8_t>& nodes) const override {
    for (const auto& conn : shells_.nodes)
      for (const Index n : conn)
        nodes[static_cast<std::size_t>(n)] = 1;
  }

  void add_energies(const State& /*s*/, const Eigen::Matrix3Xd& /*previous*/,
                    EnergySummary& e) const override {
    fe::add_element_energies(shells_, e);
  }

  // Kinetic energy and momentum from each element's lumped mass and corner inertia, so shared
  // nodes split between parts.
  void add_part_energies(const State& s, const Eigen::Matrix3Xd& previous,
                         std::vector<PartSummary>& parts) const override {
    const Shells& sh = shells_;
    for (std::size_t e = 0; e < sh.ids.size(); ++e) {
      PartSummary& ps = parts[static_cast<std::size_t>(sh.part[e])];
      (sh.eroded[e] ? ps.eroded_internal : ps.internal) += sh.internal_energy[e];
      ps.hourglass += sh.hourglass_energy[e];
      ps.added_mass += sh.added_mass[e];
      const bool triangle = sh.nodes[e][3] == sh.nodes[e][2];
      const double m = sh.mass[e] / (triangle ? 3.0 : 4.0);
      for (int c = 0; c < (triangle ? 3 : 4); ++c)
        fe::add_corner_motion(ps, s.nodes, previous, sh.nodes[e][static_cast<std::size_t>(c)], m,
                              sh.corner_inertia[e]);
    }
  }

  // Each element's DT2MS mass, 1/4 (a triangle's 1/3) to each corner, in the order of the
  // corner-force gather.
  void spread_added_mass(const State& s, std::vector<double>& nodal) const override {
    const Nodes& nd = s.nodes;
#pragma omp parallel for schedule(static)
    for (Index n = 0; n < nd.count(); ++n) {
      const auto nn = static_cast<std::size_t>(n);
      for (Index k = shells_.corner_offsets[nn]; k < shells_.corner_offsets[nn + 1]; ++k) {
        const auto e =
            static_cast<std::size_t>(shells_.node_corners[static_cast<std::size_t>(k)] / 4);
        const bool triangle = shells_.nodes[e][3] == shells_.nodes[e][2];
        nodal[nn] += shells_.added_mass[e] / (triangle ? 3.0 : 4.0);
      }
    }
  }

  void forces(State& s, NodalForces& f, ForceReport& r) override {
    const ElementPassResult e = shell_element_pass(
        s, shells_, ShellPassInput{s.step, s.time_control.scale_factor, s.mass_scaling_dt});
    gather_shell_forces(s, shells_, f);
    if (e.mass_changed) refresh_added_mass(s);
    // Elements are numbered block by block (block.hpp): the hexahedra's before the shells'.
    const Index offset = first_element(s, *this);
    if (e.critical_step < r.critical_step) {
      r.critical_step = e.critical_step;
      r.controlling_element = offset + e.controlling;
      r.controlling_particle = -1;
    }
    if (e.inverted >= 0)
      r.fail("zero or negative area in " + element_name(s, offset + e.inverted), true);
    else if (e.non_finite >= 0)
      r.fail("non-finite stress or step in " + element_name(s, offset + e.non_finite), false);
    else if (e.runaway >= 0)
      r.fail(runaway_message(s, offset + e.runaway, "area"), false);
  }

 private:
  Shells shells_;

  // The shells (quadrilaterals, triangles): the mean of the layers, and of their own the stress
  // of the top, middle and bottom layers (global axes), their plastic strain, the thickness and
  // the internal energy per volume (the layers and words of LS-DYNA's d3plot at MAXINT 3).
  void write_state(const State& s, StateSink& sink) const override {
    sink.declare("stress_top", {"XX", "YY", "ZZ", "XY", "YZ", "XZ"});
    sink.declare("stress_bottom", {"XX", "YY", "ZZ", "XY", "YZ", "XZ"});
    sink.declare("thickness", {});
    sink.declare("stress_middle", {"XX", "YY", "ZZ", "XY", "YZ", "XZ"});
    sink.declare("layer_plastic_strain", {"bottom", "middle", "top"});
    sink.declare("internal_energy_density", {});
    const Shells& sh = shells_;
    for (const ShellBlock& block : sh.blocks) {
      const model::Id part = s.parts[static_cast<std::size_t>(block.part)].id;
      for (Index e = block.begin; e < block.end; ++e) {
        const auto i = static_cast<std::size_t>(e);
        const auto& q = sh.nodes[i];
        const ElementResult mid = shell_result(s.nodes, sh, block, e, ShellSurface::all);
        CellValues v{mid, pressure_of(mid), sh.temperature[i], part};
        v.id = sh.ids[i];
        v.deleted = sh.eroded[i] != 0;
        sink.cell(q[3] == q[2] ? CellShape::triangle : CellShape::quadrilateral, q.data(), v);
        const ElementResult top = shell_result(s.nodes, sh, block, e, ShellSurface::top);
        const ElementResult bottom = shell_result(s.nodes, sh, block, e, ShellSurface::bottom);
        const ElementResult middle = shell_result(s.nodes, sh, block, e, ShellSurface::middle);
        sink.value("stress_top", top.stress.data());
        sink.value("stress_bottom", bottom.stress.data());
        sink.value("thickness", &sh.thickness[i]);
        sink.value("stress_middle", middle.stress.data());
        const double layer_strain[3] = {bottom.plastic_strain, middle.plastic_strain,
                                        top.plastic_strain};
        sink.value("layer_plastic_strain", layer_strain);
        // The area from the diagonals (a triangle's repeated fourth corner gives its half).
        const Vec3 d1 = s.nodes.position.col(q[2]) - s.nodes.position.col(q[0]);
        const Vec3 d2 = s.nodes.position.col(q[3]) - s.nodes.position.col(q[1]);
        const double volume = 0.5 * d1.cross(d2).norm() * sh.thickness[i];
        const double density = volume > 0.0 ? sh.internal_energy[i] / volume : 0.0;
        sink.value("internal_energy_density", &density);
      }
    }
  }
};

}  // namespace

std::unique_ptr<Block> make_shell_block(Shells shells) {
  return std::make_unique<ShellsBlock>(std::move(shells));
}

const Shells& shells_of(const State& s) {
  return owned_by(s, &ShellsBlock::shells);
}

const Shells& shells_of(const CompiledBlocks& before) {
  return owned_by(before, &ShellsBlock::shells);
}

}  // namespace mcdyna::solver
