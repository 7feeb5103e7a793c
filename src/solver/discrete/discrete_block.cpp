// The discrete springs and dampers as one formulation: its compile pass makes its block, which
// owns the elements' data and state (springs.hpp). The force phase adds each element's axial
// force to its two nodes and bounds the step; the elements carry no mass.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/pinned_sizes.hpp"
#include "solver/block.hpp"
#include "solver/compile.hpp"
#include "solver/discrete/springs.hpp"

namespace mcdyna::solver {

namespace {

using discrete::SpringLaw;
using discrete::Springs;

inline constexpr auto kSpringsDumpedSizes = core::sizes_of<Springs>();
static_assert(!core::kSizesPinned || kSpringsDumpedSizes == decltype(kSpringsDumpedSizes){312},
              "discrete::Springs changed: list what changes in a run in dumped() below, or "
              "leave it out as deck data");

// The mass a node answers a force with: its rigid body's, or its own with what mass scaling
// added (0: a massless node, held by a constraint).
double answering_mass(const State& s, Index n) {
  const auto i = static_cast<std::size_t>(n);
  const Index body = s.nodes.rigid_body[i];
  if (body >= 0) return s.rigid_bodies[static_cast<std::size_t>(body)].mass;
  return s.nodes.mass[i] + s.nodes.added_mass[i];
}

// Two masses in series; a massless (held) end counts as an infinitely heavy one.
double reduced_mass(double a, double b) {
  if (a <= 0.0) return b;
  if (b <= 0.0) return a;
  return a * b / (a + b);
}

class SpringsBlock final : public DumpedBlock<SpringsBlock> {
 public:
  explicit SpringsBlock(Springs springs) : sp_(std::move(springs)) {}
  [[nodiscard]] PhaseTimes::Phase phase() const override { return PhaseTimes::elements; }
  [[nodiscard]] long elements() const override { return sp_.count(); }
  [[nodiscard]] Index numbered_elements() const override { return sp_.count(); }
  [[nodiscard]] ElementRef element(const State& /*s*/, Index k) const override {
    const auto i = static_cast<std::size_t>(k);
    return {"discrete", sp_.ids[i], sp_.parts[i]};
  }
  // Every process computes the elements whole (a few numbers each), as the beams.
  void mark_replicated(const State& /*s*/, std::vector<std::uint8_t>& nodes) const override {
    for (const auto& conn : sp_.nodes)
      for (const Index n : conn)
        nodes[static_cast<std::size_t>(n)] = 1;
  }

  // At x^n with v^{n-1/2} (the rate lags half a step, as *DAMPING_GLOBAL's velocities do).
  void forces(State& s, NodalForces& forces, ForceReport& r) override {
    const Nodes& nd = s.nodes;
    const Index first = first_element(s, *this);
    for (Index k = 0; k < sp_.count(); ++k) {
      const auto i = static_cast<std::size_t>(k);
      const auto [a, b] = sp_.nodes[i];
      const Vec3 axis = nd.position.col(b) - nd.position.col(a);
      const double length = axis.norm();
      if (!(length > 0.0) || !std::isfinite(length)) {
        r.fail("zero or non-finite length in " + element_name(s, first + k), true);
        return;
      }
      const Vec3 n = axis / length;
      const double d = length - sp_.initial_length[i] + sp_.offset[i];
      const double rate = n.dot(nd.velocity.col(b) - nd.velocity.col(a));
      const SpringLaw& law = sp_.laws[static_cast<std::size_t>(sp_.law[i])];
      const double f = discrete::axial_force(law, s.curves, sp_.scale[i], d, rate);
      if (!std::isfinite(f)) {
        r.fail("non-finite force in " + element_name(s, first + k), false);
        return;
      }
      sp_.work[i] += 0.5 * (sp_.force[i] + f) * (d - sp_.deflection[i]);
      sp_.force[i] = f;
      sp_.deflection[i] = d;
      sp_.rate[i] = rate;
      forces.force.col(a) += f * n;
      forces.force.col(b) -= f * n;
      const double scale = std::abs(sp_.scale[i]);
      const double step =
          discrete::stable_step(scale * law.step_stiffness, scale * law.damping,
                                reduced_mass(answering_mass(s, a), answering_mass(s, b)));
      if (step < r.critical_step) {
        r.critical_step = step;
        r.controlling_element = first + k;
        r.controlling_particle = -1;
      }
    }
  }

  // The work on springs (stored) and dampers (dissipated) is internal energy, as glstat's
  // internal energy holds LS-DYNA's spring and damper energy.
  void add_energies(const State& /*s*/, const Eigen::Matrix3Xd& /*previous*/,
                    EnergySummary& e) const override {
    for (const double w : sp_.work)
      e.internal += w;
  }
  void add_part_energies(const State& /*s*/, const Eigen::Matrix3Xd& /*previous*/,
                         std::vector<PartSummary>& parts) const override {
    for (std::size_t i = 0; i < sp_.work.size(); ++i)
      parts[static_cast<std::size_t>(sp_.part_index[i])].internal += sp_.work[i];
  }

  // Lines, with the axial force and the deflection.
  void write_state(const State& /*s*/, StateSink& sink) const override {
    sink.declare("discrete_force", {"F", "deflection"});
    for (std::size_t i = 0; i < sp_.ids.size(); ++i) {
      CellValues v;
      v.part = sp_.parts[i];
      sink.cell(CellShape::line, sp_.nodes[i].data(), v);
      const double values[2] = {sp_.force[i], sp_.deflection[i]};
      sink.value("discrete_force", values);
    }
  }

  [[nodiscard]] std::string dump_name() const override { return "discrete elements"; }
  [[nodiscard]] std::string dump_layout() const override {
    return core::sizes_text(kSpringsDumpedSizes);
  }
  template <class Ar>
  void dumped(Ar& ar, State& /*s*/) {
    ar(sp_.force, sp_.deflection, sp_.rate, sp_.work);
  }

 private:
  Springs sp_;
};

// A part's spring or damper material, compiled; false (reported) if it cannot run.
bool compile_law(const model::ModelDatabase& m, const model::Material& mat, SpringLaw& law,
                 core::Diagnostics& d) {
  switch (mat.kind) {
    case model::MaterialKind::spring_elastic:
      law.law = discrete::Law::linear_spring;
      law.stiffness = law.step_stiffness = mat.discrete.stiffness;
      return true;
    case model::MaterialKind::damper_viscous:
      law.law = discrete::Law::viscous_damper;
      law.damping = mat.discrete.damping;
      return true;
    case model::MaterialKind::spring_nonlinear_elastic: {
      law.law = discrete::Law::curve_spring;
      law.force_curve = detail::curve_index(m, mat.discrete.force_curve);
      law.rate_curve =
          mat.discrete.rate_curve != 0 ? detail::curve_index(m, mat.discrete.rate_curve) : -1;
      if (law.force_curve < 0) return false;  // reported by the reference checks
      law.step_stiffness =
          discrete::steepest_slope(m.curves[static_cast<std::size_t>(law.force_curve)]);
      if (law.rate_curve >= 0)
        d.note(mat.discrete.rate_curve_loc,
               "*MAT_SPRING_NONLINEAR_ELASTIC {}: the stable step takes LCD's steepest slope "
               "without LCR's scale (keep LCR near 1 or lower TSSFAC)",
               mat.id);
      return true;
    }
    default:
      return false;  // reported by the part checks
  }
}

}  // namespace

namespace detail {

void compile_discrete(const model::ModelDatabase& m, State& s, const CompiledBlocks& before,
                      Blocks& own, core::Diagnostics& d) {
  if (m.discretes.empty()) return;
  Springs sp;
  // A node that carries a discrete element's force must answer it with a mass, or be held in x,
  // y and z (Block::mark_held).
  const std::vector<std::uint8_t> held = before.held_nodes(s.nodes.count());
  std::vector<Index> law_of_part(m.parts.size(), -2);  // -2 not compiled yet, -1 cannot run
  for (const model::DiscreteElement& e : m.discretes) {
    const auto p = m.index.parts.find(e.part);
    const auto n1 = m.index.nodes.find(e.nodes[0]), n2 = m.index.nodes.find(e.nodes[1]);
    if (p == model::IdIndex::kNone || n1 == model::IdIndex::kNone || n2 == model::IdIndex::kNone)
      continue;  // reported by the reference checks
    Index& law = law_of_part[static_cast<std::size_t>(p)];
    if (law == -2) {
      SpringLaw l;
      const model::Material* mat = m.material(m.parts[static_cast<std::size_t>(p)].material);
      law = mat != nullptr && compile_law(m, *mat, l, d) ? static_cast<Index>(sp.laws.size()) : -1;
      if (law >= 0) sp.laws.push_back(l);
    }
    if (law < 0) continue;
    const std::array<Index, 2> nodes{static_cast<Index>(n1), static_cast<Index>(n2)};
    const double length = (s.nodes.initial.col(nodes[1]) - s.nodes.initial.col(nodes[0])).norm();
    if (!(length > 0.0)) {
      d.error(e.loc,
              "discrete element {}: nodes {} and {} coincide; a translational spring acts along "
              "N1 -> N2 and needs them apart",
              e.id, e.nodes[0], e.nodes[1]);
      continue;
    }
    for (int k = 0; k < 2; ++k)
      if (const Index n = nodes[static_cast<std::size_t>(k)];
          answering_mass(s, n) <= 0.0 && (held[static_cast<std::size_t>(n)] & 7U) != 7U)
        d.error(e.loc,
                "discrete element {}: node {} has no mass and is not held in x, y and z (discrete "
                "elements carry none: attach the node to an element or a rigid body, or fix it)",
                e.id, e.nodes[static_cast<std::size_t>(k)]);
    const auto& laws = sp.laws;
    const double f0 = discrete::axial_force(laws[static_cast<std::size_t>(law)], s.curves, e.scale,
                                            e.offset, 0.0);
    sp.ids.push_back(e.id);
    sp.parts.push_back(e.part);
    sp.part_index.push_back(static_cast<Index>(p));
    sp.nodes.push_back(nodes);
    sp.law.push_back(law);
    sp.scale.push_back(e.scale);
    sp.offset.push_back(e.offset);
    sp.initial_length.push_back(length);
    // An OFFSET starts the element deflected: its force and (trapezoidal) work from there.
    sp.force.push_back(f0);
    sp.deflection.push_back(e.offset);
    sp.rate.push_back(0.0);
    sp.work.push_back(0.5 * f0 * e.offset);
  }
  if (sp.count() > 0) own.push_back(std::make_unique<SpringsBlock>(std::move(sp)));
}

}  // namespace detail

}  // namespace mcdyna::solver
