// An SPG part as one block of the time loop (spg_solver.hpp): its particle pass in the force
// phase, its velocity update (MC-SPG scatter and gather, Eqs. 13, 25-30) after the nodes' own,
// and the take-up of what constraints and walls changed.
#include <fmt/format.h>

#include <memory>
#include <utility>
#include <vector>

#include "solver/block.hpp"
#include "solver/results.hpp"
#include "solver/spg/distribution.hpp"
#include "solver/spg/domain_dump.hpp"
#include "solver/spg/spg_parts.hpp"
#include "solver/spg/spg_solver.hpp"

namespace mcdyna::solver {

std::string particle_name(const State& s, std::size_t domain, Index particle) {
  const spg::Domain& d = spg::domain_of(s, domain);
  return fmt::format(
      "SPG particle at node {} (part {})",
      s.nodes.ids[static_cast<std::size_t>(d.particles.nodes[static_cast<std::size_t>(particle)])],
      s.parts[static_cast<std::size_t>(d.part)].id);
}

namespace {

// Result of particle `i` of an SPG domain (its one integration point).
ElementResult particle_result(const spg::Domain& d, Index i) {
  ElementResult r;
  const auto ii = static_cast<std::size_t>(i);
  std::array<double, 6> dev{};
  for (int k = 0; k < 6; ++k)
    dev[static_cast<std::size_t>(k)] = d.fields.points.deviator(k, i);
  set_stress(r, dev, d.fields.pressure[ii]);
  r.plastic_strain = d.fields.points.plastic_strain[ii];
  r.damage = d.fields.points.damage[ii];
  return r;
}

class SpgBlock final : public DumpedBlock<SpgBlock> {
 public:
  SpgBlock(spg::Domain domain, model::Id part) : domain_(std::move(domain)), part_(part) {}
  [[nodiscard]] const spg::Domain& domain() const { return domain_; }
  [[nodiscard]] spg::Domain& domain() { return domain_; }
  [[nodiscard]] std::string dump_name() const override { return fmt::format("SPG part {}", part_); }
  [[nodiscard]] std::string dump_layout() const override {
    return core::sizes_text(spg::kDomainDumpedSizes);
  }
  template <class Ar>
  void dumped(Ar& ar, State& /*s*/) {
    ar(domain_);
  }
  // Charged to "elements" as a whole; split_times moves its finer phases out at the end.
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::elements; }
  [[nodiscard]] long particles() const override { return domain_.count(); }

  void initialise(State& s) override {
    if (domain_.diagnostics.renewals == 0) spg::initialise(s, domain_);
  }

  // MC-SPG particles count with their unsmoothed velocity and mass (Eq. 13).
  void add_energies(const State& s, const Eigen::Matrix3Xd& /*previous*/,
                    EnergySummary& e) const override {
    const spg::Domain& d = domain_;
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
    const spg::Domain& d = domain_;
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
      ps.mass += d.particles.mass[ii];
    }
    ps.internal += d.fields.damping_energy;
    for (const double w : d.fields.mode_energy)
      ps.hourglass += w;
  }

  void add_added_mass(const State& /*s*/, double& added) const override {
    for (const double a : domain_.particles.added_mass)
      added += a;
  }

  void forces(State& s, NodalForces& f, ForceReport& r) override {
    const spg::ParticlePassResult p = spg::particle_pass(s, domain_, s.step, f.force);
    if (p.critical_step < r.critical_step) {
      r.critical_step = p.critical_step;
      r.controlling_element = -1;
      r.controlling_domain = domain_.index;
      r.controlling_particle = p.controlling;
    }
    if (p.inverted >= 0)
      r.fail("non-positive Jacobian or volume at " + particle_name(s, domain_.index, p.inverted),
             true);
    else if (p.non_finite >= 0)
      r.fail("non-finite stress or wave speed at " + particle_name(s, domain_.index, p.non_finite),
             false);
  }

  Index advance_velocities(State& s, const NodalForces& f, const StepTimes& t) override {
    return spg::advance_velocities(s, domain_, f.force, t.mean);
  }

  void after_constraints(State& s) override { spg::absorb_constraints(s, domain_); }

  // A part with options that read the whole part every cycle (distribution.hpp splittable) is
  // computed whole on every process.
  void mark_replicated(const State& /*s*/, std::vector<std::uint8_t>& nodes) const override {
    if (spg::splittable(domain_)) return;
    for (const Index n : domain_.particles.nodes)
      nodes[static_cast<std::size_t>(n)] = 1;
  }

  void distribute(State& s) override {
    if (!spg::splittable(domain_)) return;
    spg::share_particles(s, domain_.index);
    spg::keep_read_rows(s, domain_);
  }

  void synchronise(State& s, Gather what) override {
    spg::synchronise(s, domain_.index,
                     what == Gather::dump    ? spg::Scope::everything
                     : what == Gather::state ? spg::Scope::to_root
                                             : spg::Scope::histories);
  }

  void split_times(const State& s, PhaseTimes& phases) const override {
    const spg::SpgTimes& t = domain_.times;
    constexpr int kSplit = PhaseTimes::spg_step_estimate - PhaseTimes::spg_neighbours + 1;
    const double split[kSplit] = {t.neighbours,    t.shape_functions, t.smoothing, t.stress,
                                  t.stabilization, t.force,           t.bonds,     t.step_estimate};
    for (int k = 0; k < kSplit; ++k) {
      phases.seconds[PhaseTimes::spg_neighbours + k] += split[k];
      phases.seconds[PhaseTimes::elements] -= split[k];
    }
    if (const parallel::ParticleShare* share = s.ownership.split_part(domain_.index)) {
      phases.seconds[PhaseTimes::exchange] += share->exchange_seconds;
      phases.seconds[PhaseTimes::elements] -= share->exchange_seconds;
    }
  }

  // The particles, a vertex each, with the fields of their integration point, the share of
  // their bonds broken, how they are integrated now and their stable step.
  void write_state(const State& s, StateSink& sink) const override {
    const spg::Domain& d = domain_;
    const model::Id part = s.parts[static_cast<std::size_t>(d.part)].id;
    for (Index i = 0; i < d.count(); ++i) {
      const auto ii = static_cast<std::size_t>(i);
      const int state = d.fields.debris[ii]     ? 3
                        : d.kernel.isolated[ii] ? 2
                        : d.kernel.pinned[ii]   ? 1
                                                : 0;
      CellValues v{particle_result(d, i),    d.fields.pressure[ii],
                   d.fields.temperature[ii], part,
                   d.kernel.bonds.damage(i), state,
                   d.fields.step[ii]};
      v.id = s.nodes.ids[static_cast<std::size_t>(d.particles.nodes[ii])];
      sink.cell(CellShape::vertex, &d.particles.nodes[ii], v);
    }
  }

 private:
  spg::Domain domain_;
  model::Id part_;
};

}  // namespace

namespace spg {

std::unique_ptr<Block> make_part_block(Domain domain, model::Id part) {
  return std::make_unique<SpgBlock>(std::move(domain), part);
}

std::vector<const Domain*> domains_of(const State& s) {
  std::vector<const Domain*> out;
  for (const std::unique_ptr<Block>& b : s.blocks)
    if (const auto* part = dynamic_cast<const SpgBlock*>(b.get())) out.push_back(&part->domain());
  return out;
}

std::vector<const Domain*> domains_of(const CompiledBlocks& before) {
  std::vector<const Domain*> out;
  for (const SpgBlock* part : before.find_all<SpgBlock>())
    out.push_back(&part->domain());
  return out;
}

std::vector<Domain*> domains_of(State& s) {
  std::vector<Domain*> out;
  for (const std::unique_ptr<Block>& b : s.blocks)
    if (auto* part = dynamic_cast<SpgBlock*>(b.get())) out.push_back(&part->domain());
  return out;
}

const Domain& domain_of(const State& s, std::size_t k) {
  return *domains_of(s).at(k);
}

Domain& domain_of(State& s, std::size_t k) {
  return *domains_of(s).at(k);
}

}  // namespace spg

}  // namespace mcdyna::solver
