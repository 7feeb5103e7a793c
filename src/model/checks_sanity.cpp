// Physical and geometric sanity, and whether mcdyna can run what the deck asks for.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "model/checks.hpp"

namespace mcdyna::model::detail {

namespace {

struct PartUse {
  std::size_t solids = 0, shells = 0, beams = 0, discretes = 0;
};

// Output intervals far below ENDTIM ask for more outputs than any run can use; they are written
// at most once per cycle (io::Outputs), so the deck runs, but the user hears of it.
constexpr double kMostStates = 1e5, kMostHistoryRows = 1e6;

void check_output_intervals(const ModelDatabase& m, double end_time, core::Diagnostics& diags) {
  auto warn = [&](core::SourceLoc loc, const std::string& what, double dt, double most) {
    if (dt > 0.0 && end_time / dt > most)
      diags.warning(loc,
                    "{} DT = {:g} asks for {:.3g} outputs over ENDTIM = {:g}: they are written at "
                    "most once per cycle",
                    what, dt, end_time / dt, end_time);
  };
  if (m.outputs.d3plot && m.outputs.d3plot->interval_curve == 0)
    warn(m.outputs.d3plot->loc, "*DATABASE_BINARY_D3PLOT", m.outputs.d3plot->interval, kMostStates);
  for (const AsciiRequest& r : m.outputs.ascii)
    if (r.interval_curve == 0)
      warn(r.loc, fmt::format("*DATABASE_{}", ascii_database_name(r.database)), r.interval,
           kMostHistoryRows);
}

// DT2MS is the step mass scaling holds the run to (|DT2MS| x TSSFAC): one that is not shorter
// than the end time makes the whole run a single step with the mass scaled to match.
void check_mass_scaling(const ModelDatabase& m, double end_time, core::Diagnostics& diags) {
  if (!m.controls.time_step || !(end_time > 0.0)) return;
  const TimeStepControl& ts = *m.controls.time_step;
  const double dt2ms = std::fabs(ts.mass_scaling_step);
  if (dt2ms >= end_time) {
    diags.error(ts.loc,
                "*CONTROL_TIMESTEP DT2MS = {:g} is not shorter than ENDTIM = {:g}: the run would "
                "be a single step with its mass scaled up to match",
                ts.mass_scaling_step, end_time);
  } else if (dt2ms * std::fabs(ts.scale_factor) * 100.0 > end_time) {
    diags.warning(ts.loc,
                  "*CONTROL_TIMESTEP DT2MS = {:g} (x TSSFAC {:g}) leaves fewer than 100 steps to "
                  "ENDTIM = {:g}",
                  ts.mass_scaling_step, ts.scale_factor, end_time);
  }
}

void check_controls(const ModelDatabase& m, core::Diagnostics& diags, bool has_elements) {
  if (!has_elements) {
    // Nodes alone have no mass (elements and their materials give it), so nothing would move.
    if (m.nodes.empty())
      diags.error(core::SourceLoc{}, "the deck defines no nodes and no elements: nothing to run");
    else
      diags.error(m.nodes.front().loc,
                  "the deck defines {} node(s) but no elements: nothing to run (elements and "
                  "their materials give the nodes their mass)",
                  m.nodes.size());
    return;
  }
  if (!m.controls.termination) {
    diags.error(core::SourceLoc{},
                "the deck has no *CONTROL_TERMINATION: the end time is not "
                "defined");
    return;
  }
  const Termination& t = *m.controls.termination;
  if (t.end_time <= 0.0 && t.end_cycle <= 0) {
    diags.error(t.loc, "*CONTROL_TERMINATION: ENDTIM = {} and no ENDCYC; the run would not advance",
                t.end_time);
  }
  check_mass_scaling(m, t.end_time, diags);
  if (t.end_cycle <= 0) check_output_intervals(m, t.end_time, diags);  // ENDCYC may end it early
}

// A deformable shell part: the formulations and integration rules mcdyna has.
void check_deformable_shell(const Part& p, const Section& s, core::Diagnostics& diags) {
  const ShellSettings& sh = s.shell;
  const int f = s.element_formulation;
  if (f != 2 && f != 0 && f != 16 && f != 4) {
    diags.error(sh.formulation_loc,
                "part {}: shell ELFORM {} of section {} is not supported for deformable shells "
                "(2 Belytschko-Tsay, 4 C0 triangle, 16 fully integrated)",
                p.id, s.element_formulation, s.id);
  }
  if (sh.integration_points > 10) {
    diags.error(sh.points_loc, "part {}: NIP = {} through the thickness (at most 10)", p.id,
                sh.integration_points);
  }
  if (sh.quadrature != 0.0 && sh.quadrature != 1.0) {
    diags.error(sh.quadrature_loc,
                "part {}: QR/IRID = {:g} of section {} is not supported (0 Gauss, 1 trapezoidal; "
                "user integration rules *INTEGRATION_SHELL are not)",
                p.id, sh.quadrature, s.id);
  }
  if (sh.quadrature == 1.0 && sh.integration_points == 1) {
    diags.error(sh.points_loc, "part {}: the trapezoidal rule (QR 1) needs NIP >= 2", p.id);
  }
  if (sh.composite != 0) {
    diags.error(sh.composite_loc,
                "part {}: composite shells (ICOMP 1, integration-point angles) are not supported",
                p.id);
  }
}

// A deformable beam part: Hughes-Liu with a rectangular or tubular section, or the elastic
// Belytschko-Schwer resultant beam.
void check_deformable_beam(const Part& p, const Section& s, const Material& mat,
                           core::Diagnostics& diags) {
  const BeamSettings& b = s.beam;
  const int f = s.element_formulation;
  if (f != 1 && f != 2 && f != 9) {
    diags.error(b.formulation_loc,
                "part {}: beam ELFORM {} of section {} is not supported (1 Hughes-Liu, 2 "
                "Belytschko-Schwer resultant, 9 spot weld)",
                p.id, f, s.id);
    return;
  }
  // The spot-weld beam and its material go together.
  if ((f == 9) != (mat.kind == MaterialKind::spotweld)) {
    diags.error(f == 9 ? p.material_loc : b.formulation_loc, "part {}: {}", p.id,
                f == 9 ? "the spot-weld beam (ELFORM 9) needs *MAT_SPOTWELD"
                       : "*MAT_SPOTWELD runs on spot-weld beams (ELFORM 9) only");
  }
  if (f == 2 && mat.kind != MaterialKind::elastic) {
    diags.error(p.material_loc,
                "part {}: the Belytschko-Schwer resultant beam (ELFORM 2) runs elastic "
                "materials only (*MAT_ELASTIC); material {} needs the integrated ELFORM 1",
                p.id, mat.id);
  }
  if (f == 1 && mat.kind == MaterialKind::johnson_cook) {
    diags.error(p.material_loc,
                "part {}: *MAT_JOHNSON_COOK is not available on beams (it needs an EOS); use "
                "*MAT_PLASTIC_KINEMATIC or *MAT_PIECEWISE_LINEAR_PLASTICITY",
                p.id);
  }
  if (f != 2 && b.cross_section == 2) {
    diags.error(b.cross_section_loc,
                "part {}: CST 2 (user integration rule, *INTEGRATION_BEAM) of section {} is not "
                "supported (0 rectangular, 1 tubular)",
                p.id, s.id);
  }
  if (f != 2 &&
      (b.quadrature < 1.0 || b.quadrature > 5.0 || b.quadrature != std::floor(b.quadrature))) {
    diags.error(b.quadrature_loc,
                "part {}: QR/IRID = {:g} of section {} is not supported (1-5; user rules "
                "*INTEGRATION_BEAM are not)",
                p.id, b.quadrature, s.id);
  }
  if (f == 1 && b.nonstructural_mass < 0.0)
    diags.error(b.formulation_loc, "part {}: NSM < 0 in section {}", p.id, s.id);
}

bool is_discrete_material(MaterialKind k) {
  return k == MaterialKind::spring_elastic || k == MaterialKind::damper_viscous ||
         k == MaterialKind::spring_nonlinear_elastic;
}

// Discrete elements take a discrete section and a spring or damper material, and nothing else
// does. Returns false when the part is a discrete one (the other checks are not for it).
bool check_discrete_part(const Part& p, const PartUse& use, const Section& s, const Material& mat,
                         core::Diagnostics& diags) {
  const bool section = s.kind == SectionKind::discrete, material = is_discrete_material(mat.kind);
  const std::size_t others = use.solids + use.shells + use.beams;
  if (use.discretes > 0 && !section)
    diags.error(p.section_loc,
                "part {} has discrete elements but section {} is not a *SECTION_DISCRETE", p.id,
                s.id);
  if (others > 0 && section)
    diags.error(p.section_loc,
                "part {} has solid, shell or beam elements but section {} is a *SECTION_DISCRETE",
                p.id, s.id);
  if (use.discretes > 0 && !material)
    diags.error(p.material_loc,
                "part {} has discrete elements: its material {} must be a spring or damper "
                "(*MAT_SPRING_ELASTIC, *MAT_DAMPER_VISCOUS, *MAT_SPRING_NONLINEAR_ELASTIC)",
                p.id, mat.id);
  if (others > 0 && material)
    diags.error(p.material_loc,
                "part {}: material {} is for discrete elements (springs and dampers) only", p.id,
                mat.id);
  return !(section || material || use.discretes > 0);
}

void check_part(const ModelDatabase& m, const Part& p, const PartUse& use,
                core::Diagnostics& diags) {
  const Section* s = m.section(p.section);
  const Material* mat = m.material(p.material);
  if (use.solids == 0 && use.shells == 0 && use.beams == 0 && use.discretes == 0) {
    diags.warning(p.loc, "part {} has no elements", p.id);
  }
  if (s == nullptr || mat == nullptr) return;  // reported as dangling references
  if (!check_discrete_part(p, use, *s, *mat, diags)) return;
  const bool rigid = mat->kind == MaterialKind::rigid;
  if (p.inertia && !rigid) {
    diags.error(p.inertia->loc,
                "*PART_INERTIA {}: the mass and inertia it gives are for rigid parts; material "
                "{} is not *MAT_RIGID",
                p.id, mat->id);
  }
  if (p.inertia) {
    const auto& t = p.inertia->tensor;
    // Positive definite: the leading minors of [[xx xy xz] [xy yy yz] [xz yz zz]].
    const double m2 = t[0] * t[3] - t[1] * t[1];
    const double m3 = t[0] * (t[3] * t[5] - t[4] * t[4]) - t[1] * (t[1] * t[5] - t[4] * t[2]) +
                      t[2] * (t[1] * t[4] - t[3] * t[2]);
    if (!(t[0] > 0.0 && m2 > 0.0 && m3 > 0.0)) {
      diags.error(p.inertia->loc,
                  "*PART_INERTIA {}: the inertia tensor (IXX {:g} IXY {:g} IXZ {:g} IYY {:g} IYZ "
                  "{:g} IZZ {:g}) is not positive definite",
                  p.id, t[0], t[1], t[2], t[3], t[4], t[5]);
    }
    if (p.inertia->node != 0 && !m.index.nodes.contains(p.inertia->node)) {
      diags.error(p.inertia->loc, "*PART_INERTIA {}: NODEID {} is not a defined node", p.id,
                  p.inertia->node);
    }
  }
  if (use.solids > 0 && s->kind == SectionKind::shell) {
    diags.error(p.section_loc, "part {} has solid elements but section {} is a shell section", p.id,
                s->id);
  }
  if (use.shells > 0 && (s->kind == SectionKind::solid || s->kind == SectionKind::solid_spg)) {
    diags.error(p.section_loc, "part {} has shell elements but section {} is a solid section", p.id,
                s->id);
  }
  if (use.shells > 0 && !rigid && s->kind == SectionKind::shell)
    check_deformable_shell(p, *s, diags);
  if ((use.beams > 0) != (s->kind == SectionKind::beam) &&
      use.solids + use.shells + use.beams > 0) {
    // Solids or shells on a beam section, or beams on another section.
    diags.error(p.section_loc, "part {} has {} elements but section {} is a {} section", p.id,
                use.beams > 0 ? "beam" : (use.shells > 0 ? "shell" : "solid"), s->id,
                s->kind == SectionKind::beam ? "beam" : "solid or shell");
  }
  if (use.beams > 0 && s->kind == SectionKind::beam) {
    if (rigid)
      diags.error(p.material_loc,
                  "part {}: beams of rigid parts are not supported (deformable beams only)", p.id);
    else
      check_deformable_beam(p, *s, *mat, diags);
  }
  if (s->kind == SectionKind::solid && !rigid && s->element_formulation != 1 &&
      s->element_formulation != 2) {
    diags.error(p.section_loc,
                "part {}: solid ELFORM {} of section {} is not supported (1 "
                "one-point hexahedron, 2 selectively reduced, 47 SPG)",
                p.id, s->element_formulation, s->id);
  }
  if (s->kind == SectionKind::solid_spg && rigid) {
    diags.error(p.material_loc, "part {}: an SPG section cannot be rigid", p.id);
  }
  const bool solid = s->kind == SectionKind::solid || s->kind == SectionKind::solid_spg;
  if (mat->kind == MaterialKind::null_material && !solid && use.shells + use.beams > 0) {
    diags.error(p.material_loc,
                "part {}: *MAT_NULL shells and beams (contact-only surfaces) are not supported; "
                "*MAT_NULL runs on solids with an equation of state",
                p.id);
  }
  if (mat->kind == MaterialKind::null_material && solid && p.eos == 0) {
    diags.error(p.eos_loc,
                "part {}: *MAT_NULL solids need an equation of state (EOSID): it gives all of "
                "their stress",
                p.id);
  }
  if (mat->kind == MaterialKind::spotweld && use.beams == 0 && use.solids + use.shells > 0) {
    diags.error(
        p.material_loc,
        "part {}: *MAT_SPOTWELD runs on spot-weld beams (ELFORM 9) only; solid (hexahedron) "
        "welds are not supported",
        p.id);
  }
  if (mat->kind == MaterialKind::null_material && s->kind == SectionKind::solid_spg) {
    diags.error(p.section_loc, "part {}: *MAT_NULL is not available on SPG sections", p.id);
  }
  if (mat->kind == MaterialKind::johnson_cook && solid && p.eos == 0) {
    diags.error(p.eos_loc,
                "part {}: *MAT_JOHNSON_COOK solids need an equation of state (EOSID), "
                "as in LS-DYNA",
                p.id);
  }
  if (p.eos != 0 && (rigid || mat->kind == MaterialKind::elastic)) {
    diags.warning(p.eos_loc, "part {}: EOSID {} is not used by material type of material {}", p.id,
                  p.eos, mat->id);
  }
  if (p.hourglass != 0 && solid && !rigid) {
    const Hourglass* h = ModelDatabase::lookup(m.hourglasses, m.index.hourglasses, p.hourglass);
    if (h != nullptr && h->type > 5) {
      diags.error(p.hourglass_loc, "part {}: hourglass type IHQ = {} is not supported (1-5)", p.id,
                  h->type);
    }
  }
}

void check_spg_section(const Section& s, core::Diagnostics& diags) {
  const SpgSettings& spg = s.spg;
  if (spg.stabilization == 2) {
    diags.note(s.loc,
               "section {}: ITB = 2 (simplified fluid-particle approximation) runs as ITB = 1, the "
               "original SPG stabilisation: the public SPG references define no simplified "
               "variant (manual/migration.md)",
               s.id);
  }
  // MC-SPG alone leans on the kernel to couple alternate particle layers; at DX 1.5 the cubic
  // box kernel gives the next layer 7 % of a particle's own weight and the layers pair up
  // (verification.md "MSC 0 alone": coarse 6061 Taylor bar 1.6 % short of FE at DX 1.5, 0.5 %
  // at R15's default 1.6, 0.4 % long at 1.8).
  const double smallest_support =
      *std::min_element(spg.support_scale.begin(), spg.support_scale.end());
  if (spg.stabilization == 3 && spg.smoothing_scheme == 0.0 && smallest_support < 1.6) {
    diags.note(s.loc,
               "section {}: MC-SPG with MSC = 0 and a support of DX = {:g}, below LS-DYNA R15's "
               "default 1.6: alternate particle layers barely see each other and can pair up "
               "under impact (a 6061 Taylor bar ends 1.6 % short at DX 1.5, 0.5 % at 1.6); "
               "DX 1.6-1.8 or MSC = 1 avoids it. Slow forming is less sensitive: the FDS decks "
               "keep the paper's 1.5, where 1.6 moves the screw force by under 5 % RMS and the "
               "thread by 0.01 mm (manual/migration.md, verification.md)",
               s.id, smallest_support);
  }
  if (spg.kernel_update == 2) {
    diags.note(s.loc,
               "section {}: KERNEL = 2 (pseudo-Lagrangian) runs as KERNEL = 0 (updated "
               "Lagrangian)",
               s.id);
  }
  const bool failure = spg.failure_strain < 1.0e10;
  if (failure && spg.damage_criterion != 1) {
    diags.error(s.loc,
                "section {}: bond failure IDAM = {} is not supported (IDAM = 1: effective "
                "plastic strain with STRETCH)",
                s.id, spg.damage_criterion);
  }
}

// Determinant of the (unscaled) centre Jacobian, 64 x the volume of a parallelepiped; <= 0 means an
// inverted or collapsed element. Degenerate tets and pentas keep a positive centre Jacobian.
double centre_jacobian(const ModelDatabase& m, const SolidElement& e, bool& ok) {
  constexpr int xi[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
  constexpr int eta[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
  constexpr int zeta[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
  double j[3][3] = {};
  for (int a = 0; a < 8; ++a) {
    const auto i = m.index.nodes.find(e.nodes[a]);
    if (i == IdIndex::kNone) {
      ok = false;
      return 0.0;
    }
    const Vec3& x = m.nodes[static_cast<std::size_t>(i)].position;
    for (int d = 0; d < 3; ++d) {
      j[0][d] += xi[a] * x[d];
      j[1][d] += eta[a] * x[d];
      j[2][d] += zeta[a] * x[d];
    }
  }
  ok = true;
  return j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
         j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
         j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
}

void check_solid_geometry(const ModelDatabase& m, core::Diagnostics& diags) {
  std::size_t bad = 0;
  core::SourceLoc first;
  for (const SolidElement& e : m.solids) {
    bool ok = false;
    const double det = centre_jacobian(m, e, ok);
    if (!ok || det > 0.0) continue;
    if (bad == 0) first = e.loc;
    if (bad++ < 20) {
      diags.error(e.loc,
                  "solid element {} is {} (centre-Jacobian volume {:.3g}); check its node order",
                  e.id, det < 0.0 ? "inverted" : "collapsed to zero volume", det / 64.0);
    }
  }
  if (bad > 20) diags.error(first, "{} inverted or collapsed solid elements in all", bad);
}

}  // namespace

void check_sanity(const ModelDatabase& m, core::Diagnostics& diags) {
  check_controls(m, diags, !m.solids.empty() || !m.shells.empty() || !m.beams.empty());
  std::vector<PartUse> use(m.parts.size());
  for (const SolidElement& e : m.solids) {
    const auto i = m.index.parts.find(e.part);
    if (i != IdIndex::kNone) ++use[static_cast<std::size_t>(i)].solids;
  }
  for (const ShellElement& e : m.shells) {
    const auto i = m.index.parts.find(e.part);
    if (i != IdIndex::kNone) ++use[static_cast<std::size_t>(i)].shells;
  }
  for (const BeamElement& e : m.beams) {
    const auto i = m.index.parts.find(e.part);
    if (i != IdIndex::kNone) ++use[static_cast<std::size_t>(i)].beams;
  }
  for (const DiscreteElement& e : m.discretes) {
    const auto i = m.index.parts.find(e.part);
    if (i != IdIndex::kNone) ++use[static_cast<std::size_t>(i)].discretes;
  }
  for (std::size_t i = 0; i < m.parts.size(); ++i)
    check_part(m, m.parts[i], use[i], diags);
  for (const Section& s : m.sections) {
    if (s.kind == SectionKind::solid_spg) check_spg_section(s, diags);
  }
  // SIDR: LS-DYNA runs a dynamic-relaxation phase before the transient for curves flagged 1
  // (that phase only) or 2 (both). mcdyna has no such phase.
  for (const Curve& c : m.curves) {
    if (c.dynamic_relaxation == 1) {
      diags.error(c.loc,
                  "*DEFINE_CURVE {}: SIDR 1 applies the curve in a dynamic-relaxation phase only; "
                  "mcdyna has no dynamic relaxation (run the preload as a transient, SIDR 0)",
                  c.id);
    } else if (c.dynamic_relaxation == 2) {
      diags.warning(c.loc,
                    "*DEFINE_CURVE {}: SIDR 2: there is no dynamic-relaxation phase; the curve "
                    "applies in the transient only",
                    c.id);
    }
  }
  check_solid_geometry(m, diags);
}

}  // namespace mcdyna::model::detail
