// An SPG part as one block of the time loop (spg_solver.hpp): its particle pass in the force
// phase, its velocity update (MC-SPG scatter and gather, Eqs. 13, 25-30) after the nodes' own,
// and the take-up of what constraints and walls changed.
#include <fmt/format.h>

#include "solver/block.hpp"
#include "solver/results.hpp"
#include "solver/spg/distribution.hpp"
#include "solver/spg/domain_dump.hpp"
#include "solver/spg/spg_solver.hpp"

namespace mcdyna::solver {

std::string particle_name(const State& s, std::size_t domain, Index particle) {
  const spg::Domain& d = s.spg[domain];
  return fmt::format(
      "SPG particle at node {} (part {})",
      s.nodes.ids[static_cast<std::size_t>(d.particles.nodes[static_cast<std::size_t>(particle)])],
      s.parts[static_cast<std::size_t>(d.part)].id);
}

namespace {

class SpgBlock final : public DumpedBlock<SpgBlock> {
 public:
  SpgBlock(std::size_t domain, long count, model::Id part)
      : domain_(domain), count_(count), part_(part) {}
  [[nodiscard]] std::string dump_name() const override { return fmt::format("SPG part {}", part_); }
  [[nodiscard]] std::string dump_layout() const override {
    return sizes_text(spg::kDomainDumpedSizes);
  }
  template <class Ar>
  void dumped(Ar& ar, State& s) const {
    ar(s.spg[domain_]);
  }
  // Charged to "elements" as a whole; split_times moves its finer phases out at the end.
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::elements; }
  [[nodiscard]] long particles() const override { return count_; }

  void initialise(State& s) override {
    spg::Domain& d = s.spg[domain_];
    if (d.diagnostics.renewals == 0) spg::initialise(s, d);
  }

  // MC-SPG particles count with their unsmoothed velocity and mass (Eq. 13).
  void add_energies(const State& s, const Eigen::Matrix3Xd& /*previous*/,
                    EnergySummary& e) const override {
    const spg::Domain& d = s.spg[domain_];
    for (std::size_t i = 0; i < d.fields.internal_energy.size(); ++i)
      e.internal += d.fields.internal_energy[i];
    e.damping += d.fields.damping_energy;
    for (const double w : d.fields.mode_energy)
      e.hourglass += w;
    const spg::SmoothedKinetic k = spg::smoothed_kinetic(s, d);
    e.kinetic += k.kinetic;
    e.momentum += k.momentum;
    e.mass += k.mass;
  }

  void add_part_energies(const State& s, const Eigen::Matrix3Xd& previous,
                         std::vector<PartSummary>& parts) const override {
    const spg::Domain& d = s.spg[domain_];
    const Eigen::Matrix3Xd& velocity = s.nodes.velocity;
    PartSummary& ps = parts[static_cast<std::size_t>(d.part)];
    for (Index i = 0; i < d.count(); ++i) {
      const auto ii = static_cast<std::size_t>(i);
      ps.internal += d.fields.internal_energy[ii];
      ps.added_mass += d.particles.added_mass[ii];
      const Index n = d.particles.nodes[ii];
      const bool mc = s.nodes.smoothed[static_cast<std::size_t>(n)] == 1;
      const Vec3 before = mc ? Vec3(d.fields.unsmoothed_previous.col(i)) : Vec3(previous.col(n));
      const Vec3 after = mc ? Vec3(d.fields.unsmoothed.col(i)) : Vec3(velocity.col(n));
      ps.kinetic += 0.5 * d.particles.mass[ii] * before.dot(after);
      ps.momentum += 0.5 * d.particles.mass[ii] * (before + after);
    }
    ps.internal += d.fields.damping_energy;
    for (const double w : d.fields.mode_energy)
      ps.hourglass += w;
  }

  void add_added_mass(const State& s, double& added) const override {
    for (const double a : s.spg[domain_].particles.added_mass)
      added += a;
  }

  void forces(State& s, NodalForces& f, ForceReport& r) override {
    const spg::ParticlePassResult p = spg::particle_pass(s, s.spg[domain_], s.step, f.force);
    if (p.critical_step < r.critical_step) {
      r.critical_step = p.critical_step;
      r.controlling_element = -1;
      r.controlling_domain = domain_;
      r.controlling_particle = p.controlling;
    }
    if (p.inverted >= 0)
      r.fail("non-positive Jacobian or volume at " + particle_name(s, domain_, p.inverted), true);
    else if (p.non_finite >= 0)
      r.fail("non-finite stress or wave speed at " + particle_name(s, domain_, p.non_finite),
             false);
  }

  Index advance_velocities(State& s, const NodalForces& f, const StepTimes& t) override {
    return spg::advance_velocities(s, s.spg[domain_], f.force, t.mean);
  }

  void after_constraints(State& s) override { spg::absorb_constraints(s, s.spg[domain_]); }

  // A part with options that read the whole part every cycle (distribution.hpp splittable) is
  // computed whole on every process.
  void mark_replicated(const State& s, std::vector<std::uint8_t>& nodes) const override {
    if (spg::splittable(s.spg[domain_])) return;
    for (const Index n : s.spg[domain_].particles.nodes)
      nodes[static_cast<std::size_t>(n)] = 1;
  }

  void distribute(State& s) override {
    if (!spg::splittable(s.spg[domain_])) return;
    spg::share_particles(s, domain_);
    spg::keep_read_rows(s, s.spg[domain_]);
  }

  void synchronise(State& s, Gather what) override {
    spg::synchronise(s, domain_,
                     what == Gather::dump    ? spg::Scope::everything
                     : what == Gather::state ? spg::Scope::to_root
                                             : spg::Scope::histories);
  }

  void split_times(const State& s, PhaseTimes& phases) const override {
    const spg::SpgTimes& t = s.spg[domain_].times;
    constexpr int kSplit = PhaseTimes::spg_step_estimate - PhaseTimes::spg_neighbours + 1;
    const double split[kSplit] = {t.neighbours,    t.shape_functions, t.smoothing, t.stress,
                                  t.stabilization, t.force,           t.bonds,     t.step_estimate};
    for (int k = 0; k < kSplit; ++k) {
      phases.seconds[PhaseTimes::spg_neighbours + k] += split[k];
      phases.seconds[PhaseTimes::elements] -= split[k];
    }
    if (const parallel::ParticleShare* share = s.ownership.split_part(domain_)) {
      phases.seconds[PhaseTimes::exchange] += share->exchange_seconds;
      phases.seconds[PhaseTimes::elements] -= share->exchange_seconds;
    }
  }

  // The particles, a vertex each, with the fields of their integration point, the share of
  // their bonds broken, how they are integrated now and their stable step.
  void write_state(const State& s, StateSink& sink) const override {
    const spg::Domain& d = s.spg[domain_];
    const model::Id part = s.parts[static_cast<std::size_t>(d.part)].id;
    for (Index i = 0; i < d.count(); ++i) {
      const auto ii = static_cast<std::size_t>(i);
      const int state = d.fields.debris[ii]     ? 3
                        : d.kernel.isolated[ii] ? 2
                        : d.kernel.pinned[ii]   ? 1
                                                : 0;
      sink.cell(CellShape::vertex, &d.particles.nodes[ii],
                {particle_result(d, i), d.fields.pressure[ii], d.fields.temperature[ii], part,
                 d.kernel.bonds.damage(i), state, d.fields.step[ii]});
    }
  }

 private:
  std::size_t domain_;
  long count_;
  model::Id part_;
};

}  // namespace

void add_spg_blocks(State& s, Blocks& blocks) {
  for (std::size_t k = 0; k < s.spg.size(); ++k)
    blocks.push_back(std::make_unique<SpgBlock>(
        k, s.spg[k].count(), s.parts[static_cast<std::size_t>(s.spg[k].part)].id));
}

}  // namespace mcdyna::solver
