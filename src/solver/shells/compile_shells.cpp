// Deformable shell parts -> shell blocks: connectivity, thickness, mass and rotary inertia, the
// through-thickness rule, hourglass coefficients, and the node -> corner lists of the gather.
#include <algorithm>
#include <cmath>
#include <utility>

#include "solver/compile.hpp"
#include "solver/shells/shell_c0_triangle.hpp"

namespace mcdyna::solver::detail {

double shell_thickness(const model::ShellElement& el, const model::Section* sec) {
  // Corner thicknesses: *ELEMENT_SHELL_THICKNESS when given, else the section's T1..T4; a zero
  // T2..T4 takes T1 (a section that gives T1 only is a uniform shell).
  auto corner = [](const std::array<double, 4>& t, std::size_t c) {
    return t[c] > 0.0 ? t[c] : t[0];
  };
  const bool own =
      std::any_of(el.thickness.begin(), el.thickness.end(), [](double t) { return t > 0.0; });
  const std::array<double, 4> none{};
  const std::array<double, 4>& t = own ? el.thickness : (sec ? sec->shell.thickness : none);
  const bool triangle = el.nodes[3] == el.nodes[2];
  double sum = 0.0;
  for (std::size_t c = 0; c < (triangle ? 3U : 4U); ++c)
    sum += corner(t, c);
  return sum / (triangle ? 3.0 : 4.0);
}

namespace {

// Gauss-Legendre points and weights on [-1, 1] (Newton on P_n from the Chebyshev guesses).
void gauss_rule(int n, std::array<double, 10>& z, std::array<double, 10>& w) {
  for (int i = 0; i < n; ++i) {
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p0 = 1.0, p1 = x;
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    // Ascending: bottom (z = -1) to top.
    z[static_cast<std::size_t>(n - 1 - i)] = x;
    w[static_cast<std::size_t>(n - 1 - i)] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  if (n == 1) {
    z[0] = 0.0;
    w[0] = 2.0;
  }
}

// Gauss-Lobatto points on [-1, 1], the two surfaces included (*CONTROL_SHELL INTGRD 1): the
// interior points are the roots of P'_{n-1}, found by Newton from the Chebyshev-Gauss-Lobatto
// guesses; weights 2 / (n (n - 1) P_{n-1}(x)^2).
void lobatto_rule(int n, std::array<double, 10>& z, std::array<double, 10>& w) {
  const int m = n - 1;
  for (int i = 0; i < n; ++i) {
    double x = -std::cos(M_PI * i / m);
    double p = 0.0;
    for (int it = 0; it < 100; ++it) {
      // P_m(x), P'_m(x), P''_m(x) by the recurrence and the Legendre equation.
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= m; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      p = p1;
      if (i == 0 || i == m) break;  // the end points are fixed
      const double dp = m * (x * p1 - p0) / (x * x - 1.0);
      const double d2p = (2.0 * x * dp - m * (m + 1.0) * p1) / (1.0 - x * x);
      const double dx = dp / d2p;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    z[static_cast<std::size_t>(i)] = x;
    w[static_cast<std::size_t>(i)] = 2.0 / (n * m * p * p);
  }
}

void trapezoidal_rule(int n, std::array<double, 10>& z, std::array<double, 10>& w) {
  const double h = 2.0 / (n - 1);
  for (int i = 0; i < n; ++i) {
    z[static_cast<std::size_t>(i)] = -1.0 + h * i;
    w[static_cast<std::size_t>(i)] = (i == 0 || i == n - 1) ? 0.5 * h : h;
  }
}

// Area of a 3- or 4-node shell from its diagonals (exact for a flat quadrilateral).
double shell_area(const Nodes& nd, const std::array<Index, 4>& conn) {
  const Vec3 d13 = nd.initial.col(conn[2]) - nd.initial.col(conn[0]);
  const Vec3 d24 = nd.initial.col(conn[3]) - nd.initial.col(conn[1]);
  if (conn[3] == conn[2]) {
    const Vec3 d12 = nd.initial.col(conn[1]) - nd.initial.col(conn[0]);
    return 0.5 * d12.cross(d13).norm();
  }
  return 0.5 * d13.cross(d24).norm();
}

// Plane-stress elastic constants for the shells from the compiled 3D ones; *MAT_JOHNSON_COOK
// gives E and PR for shells on its card (its solids take the bulk modulus from the EOS).
void shell_moduli(const model::Material& mat, Material& out, const model::Part& part,
                  core::Diagnostics& d) {
  if (mat.kind != model::MaterialKind::johnson_cook) return;
  const double e = mat.johnson_cook.youngs_modulus, nu = mat.johnson_cook.poisson_ratio;
  if (!(e > 0.0) || !(nu > -1.0 && nu < 0.5)) {
    d.error(mat.loc,
            "part {}: *MAT_JOHNSON_COOK {} on shells needs E > 0 and 0 <= PR < 0.5 on card 1 "
            "(the shells' elastic constants); got E = {:g}, PR = {:g}",
            part.id, mat.id, e, nu);
    return;
  }
  out.shear_modulus = e / (2.0 * (1.0 + nu));
  out.bulk_modulus = e / (3.0 * (1.0 - 2.0 * nu));
}

// *CONTROL_SHELL: notes for the fields that do nothing here.
void note_shell_control(const model::ShellControl& c, core::Diagnostics& d) {
  if (c.sort_triangles >= 2)
    d.note(c.loc, "*CONTROL_SHELL: ESORT {}: triangles run as C0 triangles (as ESORT 1)",
           c.sort_triangles);
  if (c.warping == 1)
    d.note(c.loc, "*CONTROL_SHELL: BWC 1 (Belytschko-Wong-Chiang warping) runs as BWC 2");
  if (c.plasticity_iterations == 3)
    d.note(c.loc, "*CONTROL_SHELL: MITER 3 (radial return) runs as MITER 2 (full iteration)");
  if (c.thickness_update == 2)
    d.note(c.loc, "*CONTROL_SHELL: ISTUPD 2 changes thick shells only: no effect here");
  if (c.theory != 2)
    d.note(c.loc,
           "*CONTROL_SHELL: THEORY {} has no effect: each *SECTION_SHELL gives its ELFORM "
           "(blank is 2)",
           c.theory);
  if (c.contact_offset != 0)
    d.note(c.loc, "*CONTROL_SHELL: CNTCO {} has no effect: contact surfaces are the mid-surfaces",
           c.contact_offset);
  for (const std::string& f : c.inactive)
    d.note(c.loc, "*CONTROL_SHELL: {} has no effect here", f);
}

// Whether the part's shells change thickness under *CONTROL_SHELL ISTUPD (and PSSTUPD): 1 and 3
// from the membrane thickness strain, 4 from its plastic part.
ThicknessUpdate thickness_update(const model::ModelDatabase& m, const model::Part& part) {
  if (!m.controls.shell) return ThicknessUpdate::none;
  const model::ShellControl& c = *m.controls.shell;
  const ThicknessUpdate mode = c.thickness_update == 1 || c.thickness_update == 3
                                   ? ThicknessUpdate::membrane
                               : c.thickness_update == 4 ? ThicknessUpdate::plastic
                                                         : ThicknessUpdate::none;
  if (mode == ThicknessUpdate::none || c.thickness_parts == 0) return mode;
  const model::PartSet* ps = m.part_set(c.thickness_parts);
  return ps != nullptr && std::find(ps->parts.begin(), ps->parts.end(), part.id) != ps->parts.end()
             ? mode
             : ThicknessUpdate::none;
}

}  // namespace

void compile_shells(const model::ModelDatabase& m, State& s, const CompiledBlocks& /*before*/,
                    Blocks& own, core::Diagnostics& d) {
  const model::ShellControl control = m.controls.shell.value_or(model::ShellControl{});
  if (m.controls.shell) {
    note_shell_control(control, d);
    if (control.thickness_parts != 0 && m.part_set(control.thickness_parts) == nullptr)
      d.error(control.loc, "*CONTROL_SHELL: PSSTUPD part set {} is not defined",
              control.thickness_parts);
  }
  Nodes& nd = s.nodes;
  const std::vector<std::vector<std::size_t>> by_part = elements_by_part(m, m.shells);
  Shells sh;
  std::vector<double> rotary(static_cast<std::size_t>(nd.count()), 0.0);
  Index points = 0;
  bool back = false;
  for (std::size_t p = 0; p < m.parts.size(); ++p) {
    const model::Part& part = m.parts[p];
    const model::Material* mat = m.material(part.material);
    const model::Section* sec = m.section(part.section);
    if (by_part[p].empty() || mat == nullptr || sec == nullptr ||
        mat->kind == model::MaterialKind::rigid || sec->kind != model::SectionKind::shell)
      continue;
    const model::ShellSettings& set = sec->shell;
    ShellBlock b;
    b.part = static_cast<Index>(p);
    const bool full = sec->element_formulation == 16;
    b.formulation = full                            ? ShellFormulation::fully_integrated
                    : sec->element_formulation == 4 ? ShellFormulation::c0_triangle
                                                    : ShellFormulation::belytschko_tsay;
    b.sort_triangles = control.sort_triangles >= 1;
    b.in_plane_points = full ? 4 : 1;
    b.layers = std::clamp(set.integration_points == 0 ? 2 : set.integration_points, 1, 10);
    if (set.quadrature == 1.0 && b.layers > 1)
      trapezoidal_rule(b.layers, b.layer_z, b.layer_weight);
    else if (control.lobatto == 1 && b.layers >= 3)
      lobatto_rule(b.layers, b.layer_z, b.layer_weight);
    else
      gauss_rule(b.layers, b.layer_z, b.layer_weight);
    b.thickness_update = thickness_update(m, part);
    b.plane_stress_iterations = control.plasticity_iterations == 1 ? 3 : 30;
    b.reference_surface = set.reference_surface;
    BulkViscosityParams unused;
    b.hourglass = hourglass_of(m, part, unused);
    b.bending_hourglass = b.warping_hourglass = b.hourglass.coefficient;
    if (const model::Hourglass* h = part_hourglass(m, part)) {
      b.bending_hourglass = h->qb;
      b.warping_hourglass = h->qw;
      if (full) {
        d.note(h->loc,
               "part {}: *HOURGLASS {} (IHQ {}) has no effect on its ELFORM 16 shells: fully "
               "integrated, they have no hourglass modes{}",
               part.id, h->id, h->type,
               h->type == 8 ? " (the warping stiffness of IHQ 8 is not added: warped elements "
                              "are taken flat in their frame)"
                            : "");
      }
    }
    b.shear_factor = set.shear_factor > 0.0 ? set.shear_factor : 1.0;
    b.material = static_cast<Index>(s.materials.size());
    Material cm = compile_material(m, part, d);
    shell_moduli(*mat, cm, part, d);
    s.materials.push_back(std::move(cm));
    s.parts[p].material = b.material;
    const Material& mm = s.materials.back();
    b.begin = sh.count();
    b.point_begin = points;
    for (const std::size_t e : by_part[p]) {
      const model::ShellElement& el = m.shells[e];
      std::array<Index, 4> conn{};
      for (std::size_t c = 0; c < 4; ++c)
        conn[c] = static_cast<Index>(m.index.nodes.find(el.nodes[c]));
      const double t = shell_thickness(el, sec);
      const double area = shell_area(nd, conn);
      if (!(t > 0.0)) {
        d.error(el.loc,
                "shell element {} of part {} has no thickness (T1 of section {} and "
                "*ELEMENT_SHELL_THICKNESS are zero)",
                el.id, part.id, sec->id);
      }
      if (!(area > 0.0)) {
        d.error(el.loc, "shell element {} of part {} has zero area (collapsed or repeated nodes)",
                el.id, part.id);
      }
      const double mass = (mm.density * t + set.nonstructural_mass) * area;
      const bool triangle = conn[3] == conn[2];
      const int corners = triangle ? 3 : 4;
      if (!triangle && b.formulation == ShellFormulation::c0_triangle) {
        d.error(el.loc,
                "shell element {} of part {} has four nodes; section {} is the C0 triangle "
                "(ELFORM 4), for three-node shells (N4 = N3)",
                el.id, part.id, sec->id);
      }
      // Rotary inertia (Belytschko, Lin and Tsay 1984): the lumped translational mass times
      // max(t^2 / 12, A / 8), scaled up so that the rotations never set the step.
      double inertia = control.rotary_scale * std::max(t * t / 12.0, area / 8.0) * mass / corners;
      if (triangle && (b.formulation == ShellFormulation::c0_triangle || b.sort_triangles)) {
        std::array<Vec3, 4> x;
        for (std::size_t c = 0; c < 4; ++c)
          x[c] = nd.initial.col(conn[c]);
        const double step = shell_kernel::shell_step(x.data(), area, true, youngs_modulus(mm),
                                                     poisson_ratio(mm), mm.density);
        inertia = std::max(
            inertia, shell_kernel::c0_triangle_inertia(
                         x.data(), b.shear_factor * mm.shear_modulus * t, mass / corners, step));
      }
      for (int c = 0; c < corners; ++c) {
        nd.mass[static_cast<std::size_t>(conn[static_cast<std::size_t>(c)])] += mass / corners;
        rotary[static_cast<std::size_t>(conn[static_cast<std::size_t>(c)])] += inertia;
      }
      sh.corner_inertia.push_back(inertia);
      sh.ids.push_back(el.id);
      sh.nodes.push_back(conn);
      sh.part.push_back(static_cast<Index>(p));
      sh.initial_thickness.push_back(t);
      sh.initial_area.push_back(area);
      sh.mass.push_back(mass);
      sh.temperature.push_back(mm.initial_temperature());
    }
    b.end = sh.count();
    points += (b.end - b.begin) * b.in_plane_points * b.layers;
    back = back || mm.has_back_stress();
    sh.blocks.push_back(b);
  }
  const auto n = static_cast<std::size_t>(sh.count());
  sh.thickness = sh.initial_thickness;
  sh.internal_energy.assign(n, 0.0);
  sh.hourglass_energy.assign(n, 0.0);
  sh.hourglass_force.assign(5 * n, 0.0);
  sh.time_step.assign(n, 0.0);
  sh.added_mass.assign(n, 0.0);
  sh.eroded.assign(n, 0);
  sh.corner_force.assign(24 * n, 0.0);
  sh.points.stress.setZero(6, points);
  if (back) sh.points.back_stress.setZero(6, points);
  sh.points.plastic_strain.assign(static_cast<std::size_t>(points), 0.0);
  sh.points.damage.assign(static_cast<std::size_t>(points), 0.0);
  if (n == 0) return;
  add_rotary_inertia(nd, rotary);
  build_node_corners(
      nd.count(), sh.nodes, [&](std::size_t e) { return sh.nodes[e][3] == sh.nodes[e][2] ? 3 : 4; },
      sh.corner_offsets, sh.node_corners);
  own.push_back(make_shell_block(std::move(sh)));
}

}  // namespace mcdyna::solver::detail
