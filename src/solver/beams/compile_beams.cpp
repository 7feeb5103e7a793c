// Deformable beam parts -> beam blocks: connectivity, local s axis, cross section (properties and
// Hughes-Liu points), mass and rotary inertia, the flexural stable step, and the node -> end
// lists of the gather.
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

#include "solver/beams/beams.hpp"
#include "solver/block.hpp"
#include "solver/compile.hpp"

namespace mcdyna::solver::detail {

namespace {

// Points and weights on [-1, 1] of the section rules of *SECTION_BEAM QR 1-5 for rectangles:
// 1 point, 2 and 3 Gauss, 3 Lobatto, 4 Gauss.
struct LineRule {
  int n;
  double z[4], w[4];
};

LineRule rectangle_rule(int qr) {
  const double g2 = 1.0 / std::sqrt(3.0), g3 = std::sqrt(0.6);
  const double a = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(1.2));
  const double b = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(1.2));
  const double wa = (18.0 + std::sqrt(30.0)) / 36.0, wb = (18.0 - std::sqrt(30.0)) / 36.0;
  switch (qr) {
    case 1:
      return {1, {0.0}, {2.0}};
    case 3:
      return {3, {-g3, 0.0, g3}, {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};
    case 4:
      return {3, {-1.0, 0.0, 1.0}, {1.0 / 3.0, 4.0 / 3.0, 1.0 / 3.0}};
    case 5:
      return {4, {-b, -a, a, b}, {wb, wa, wa, wb}};
    default:
      return {2, {-g2, g2}, {1.0, 1.0}};
  }
}

// The Hughes-Liu points of a section: rectangles QR x QR (positions as fractions of the widths,
// in [-1/2, 1/2]); tubes and rods N points evenly spaced on the ring of radius
// sqrt((ro^2 + ri^2) / 2) (N = 1, 4, 9, 9, 16 for QR 1-5), which integrates A, I and J exactly;
// the widths are then the ring's diameter, the positions cos, sin / 2.
void section_points(const model::BeamSettings& set, BeamBlock& b) {
  const int qr = static_cast<int>(set.quadrature);
  if (set.cross_section == 1) {
    constexpr int kRing[6] = {0, 1, 4, 9, 9, 16};
    b.points = kRing[std::clamp(qr, 1, 5)];
    for (int k = 0; k < b.points; ++k) {
      const double angle = 2.0 * M_PI * k / b.points;
      const auto i = static_cast<std::size_t>(k);
      b.point_s[i] = b.points == 1 ? 0.0 : 0.5 * std::cos(angle);
      b.point_t[i] = b.points == 1 ? 0.0 : 0.5 * std::sin(angle);
      b.point_weight[i] = 1.0 / b.points;
    }
    return;
  }
  const LineRule r = rectangle_rule(qr);
  b.points = r.n * r.n;
  for (int i = 0; i < r.n; ++i)
    for (int j = 0; j < r.n; ++j) {
      const auto k = static_cast<std::size_t>(i * r.n + j);
      b.point_s[k] = 0.5 * r.z[i];
      b.point_t[k] = 0.5 * r.z[j];
      b.point_weight[k] = 0.25 * r.w[i] * r.w[j];
    }
}

// An element's section: the element's _THICKNESS values where given, else the section's; a zero
// value at node 2 takes node 1's, and a tapered beam runs with the mean.
struct SectionProperties {
  double area = 0.0, inertia_s = 0.0, inertia_t = 0.0, torsion = 0.0, shear_area = 0.0;
  double width_s = 0.0, width_t = 0.0;
};

SectionProperties section_of(const model::BeamElement& el, const model::Section& sec) {
  const model::BeamSettings& set = sec.beam;
  auto value = [&](std::size_t k, double section_value) {
    return el.parameters[k] > 0.0 ? el.parameters[k] : section_value;
  };
  SectionProperties p;
  if (sec.element_formulation == 2) {
    p.area = value(0, set.area);
    p.inertia_s = value(1, set.iss);
    p.inertia_t = value(2, set.itt);
    p.torsion = value(3, set.torsion);
    if (!(p.torsion > 0.0)) p.torsion = p.inertia_s + p.inertia_t;
    p.shear_area = value(4, set.shear_area);
    if (!(p.shear_area > 0.0)) p.shear_area = p.area;
    return p;
  }
  std::array<double, 4> t{};
  for (std::size_t k = 0; k < 4; ++k)
    t[k] = value(k, set.thickness[k]);
  const double s = 0.5 * (t[0] + (t[1] > 0.0 ? t[1] : t[0]));
  const double tt = 0.5 * (t[2] + (t[3] > 0.0 ? t[3] : t[2]));
  if (set.cross_section == 1) {  // tube: outer and inner diameters
    const double ro = 0.5 * s, ri = 0.5 * tt;
    p.area = M_PI * (ro * ro - ri * ri);
    const double ring2 = 0.5 * (ro * ro + ri * ri);
    p.inertia_s = p.inertia_t = 0.5 * p.area * ring2;
    p.torsion = p.area * ring2;
    p.width_s = p.width_t = 2.0 * std::sqrt(ring2);
  } else {
    p.area = s * tt;
    p.inertia_s = s * tt * tt * tt / 12.0;  // about s: the t extent bends
    p.inertia_t = tt * s * s * s / 12.0;
    p.torsion = p.inertia_s + p.inertia_t;  // the fibres' polar moment (no warping)
    p.width_s = s;
    p.width_t = tt;
  }
  p.shear_area = p.area;
  return p;
}

// The initial s axis: from N1 toward N3 or along the orientation vector, made normal to the
// beam; without either, the global axis least aligned with the beam. Zero if N3 or the vector
// lies along the beam.
Vec3 initial_s_axis(const model::ModelDatabase& m, const Nodes& nd, const model::BeamElement& el,
                    const Vec3& x1, const Vec3& r) {
  Vec3 v = Vec3::Zero();
  if (el.orientation_node != 0) {
    v = nd.initial.col(static_cast<Index>(m.index.nodes.find(el.orientation_node))) - x1;
  } else if (el.orientation != model::Vec3{}) {
    v = Vec3(el.orientation[0], el.orientation[1], el.orientation[2]);
  } else {
    Eigen::Index least = 0;
    r.cwiseAbs().minCoeff(&least);
    v = Vec3::Unit(least);
  }
  const Vec3 s = v - v.dot(r) * r;
  return s.norm() > 1e-8 * v.norm() ? Vec3(s.normalized()) : Vec3(Vec3::Zero());
}

// The largest frequency of the element's bending (both planes) and torsion modes with its lumped
// masses and end inertias: K = L (kappa G A b_g b_g^T + E I b_k b_k^T) for the one-point
// Hughes-Liu beam, the Timoshenko stiffness for the resultant beam.
double flexural_frequency(bool resultant, double e, double g, double kappa,
                          const SectionProperties& p, double length, double half_mass,
                          double inertia) {
  Eigen::Matrix4d mass = Eigen::Vector4d(half_mass, inertia, half_mass, inertia).asDiagonal();
  double highest = 0.0;
  for (const double i : {p.inertia_s, p.inertia_t}) {
    Eigen::Matrix4d k;
    const double l = length;
    if (resultant) {
      const double phi = 12.0 * e * i / (g * p.shear_area * l * l);
      const double c = e * i / (l * l * l * (1.0 + phi));
      k << 12, 6 * l, -12, 6 * l, 6 * l, (4 + phi) * l * l, -6 * l, (2 - phi) * l * l, -12, -6 * l,
          12, -6 * l, 6 * l, (2 - phi) * l * l, -6 * l, (4 + phi) * l * l;
      k *= c;
    } else {
      const Eigen::Vector4d bg(-1.0 / l, -0.5, 1.0 / l, -0.5), bk(0.0, -1.0 / l, 0.0, 1.0 / l);
      k = l * (kappa * g * p.shear_area * bg * bg.transpose() + e * i * bk * bk.transpose());
    }
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix4d> eig(k, mass, Eigen::EigenvaluesOnly);
    highest = std::max(highest, eig.eigenvalues().maxCoeff());
  }
  highest = std::max(highest, 2.0 * g * p.torsion / (length * inertia));
  return std::sqrt(std::max(highest, 0.0));
}

// The end's rotary inertia (one number for the three axes, as for every node): the least that
// keeps the bending and torsion modes below the axial mode 2 c / L, so that the axial wave sets
// the step, and no less than the physical inertia about the weaker axis, half the mass times
// min(ISS, ITT) / A. More than that stiffens nothing but slows the rotations: a 10 x 1 mm strip
// needs 0.4 of its polar radius of gyration squared for torsion, +0.09 % on its first bending
// period (the shells' max(t^2 / 12, A / 8) does the same, +0.08 %). Elements so short that
// their bending outruns the axial mode at any inertia keep 1.01 times their translational limit.
double end_inertia(bool resultant, double e, double g, double density, double kappa,
                   const SectionProperties& p, double length, double half_mass) {
  const double physical = half_mass * std::min(p.inertia_s, p.inertia_t) / p.area;
  auto omega = [&](double inertia) {
    return flexural_frequency(resultant, e, g, kappa, p, length, half_mass, inertia);
  };
  const double axial = 2.0 * std::sqrt(e / density) / length;
  const double target = std::max(axial, 1.01 * omega(1e12 * half_mass * length * length));
  if (omega(physical) <= target) return physical;
  double lo = physical, hi = physical;
  while (omega(hi) > target)
    hi *= 2.0;
  for (int it = 0; it < 60 && hi - lo > 1e-6 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (omega(mid) > target ? lo : hi) = mid;
  }
  return hi;
}

}  // namespace

void compile_beams(const model::ModelDatabase& m, State& s, const CompiledBlocks& /*before*/,
                   Blocks& own, core::Diagnostics& d) {
  Nodes& nd = s.nodes;
  Beams bm;
  const std::vector<std::vector<std::size_t>> by_part = elements_by_part(m, m.beams);
  std::vector<double> rotary(static_cast<std::size_t>(nd.count()), 0.0);
  std::vector<Vec3> axes;
  Index points = 0;
  bool back = false;
  for (std::size_t p = 0; p < m.parts.size(); ++p) {
    const model::Part& part = m.parts[p];
    const model::Material* mat = m.material(part.material);
    const model::Section* sec = m.section(part.section);
    if (by_part[p].empty() || mat == nullptr || sec == nullptr ||
        mat->kind == model::MaterialKind::rigid || sec->kind != model::SectionKind::beam)
      continue;
    const model::BeamSettings& set = sec->beam;
    BeamBlock b;
    b.part = static_cast<Index>(p);
    const bool resultant = sec->element_formulation == 2;
    b.formulation = resultant ? BeamFormulation::belytschko_schwer : BeamFormulation::hughes_liu;
    if (!resultant) section_points(set, b);
    if (!resultant && b.points == 1) {
      d.warning(set.quadrature_loc,
                "part {}: QR 1 puts one point on the section of its Hughes-Liu beams: they carry "
                "axial and shear forces but no bending or torsion",
                part.id);
    }
    b.shear_factor = set.shear_factor > 0.0 ? set.shear_factor : 1.0;
    b.material = static_cast<Index>(s.materials.size());
    s.materials.push_back(compile_material(m, part, d));
    s.parts[p].material = b.material;
    const Material& mm = s.materials.back();
    const double young =
        9.0 * mm.bulk_modulus * mm.shear_modulus / (3.0 * mm.bulk_modulus + mm.shear_modulus);
    b.begin = bm.count();
    b.point_begin = points;
    for (const std::size_t e : by_part[p]) {
      const model::BeamElement& el = m.beams[e];
      std::array<Index, 2> conn{};
      for (std::size_t c = 0; c < 2; ++c)
        conn[c] = static_cast<Index>(m.index.nodes.find(el.nodes[c]));
      const Vec3 x1 = nd.initial.col(conn[0]), x2 = nd.initial.col(conn[1]);
      const double length = (x2 - x1).norm();
      const SectionProperties sp = section_of(el, *sec);
      if (!(length > 0.0)) {
        d.error(el.loc, "beam element {} of part {} has zero length (N1 and N2 coincide)", el.id,
                part.id);
        continue;
      }
      const Vec3 axis_s = initial_s_axis(m, nd, el, x1, (x2 - x1) / length);
      if (axis_s.isZero()) {
        d.error(el.loc,
                "beam element {} of part {}: its orientation ({}) lies along the beam; the s "
                "axis is undefined",
                el.id, part.id,
                el.orientation_node != 0 ? fmt::format("node {}", el.orientation_node)
                                         : std::string("vector"));
      }
      if (!(sp.area > 0.0) || !(sp.inertia_s > 0.0) || !(sp.inertia_t > 0.0)) {
        d.error(el.loc,
                "beam element {} of part {} has no cross section (A = {:g}, ISS = {:g}, ITT = "
                "{:g} from section {}{})",
                el.id, part.id, sp.area, sp.inertia_s, sp.inertia_t, sec->id,
                resultant ? ": A, ISS, ITT" : ": TS1, TT1");
        continue;
      }
      const double mass = (mm.density * sp.area + set.nonstructural_mass) * length;
      const double inertia = end_inertia(resultant, young, mm.shear_modulus, mm.density,
                                         b.shear_factor, sp, length, 0.5 * mass);
      const double omega = flexural_frequency(resultant, young, mm.shear_modulus, b.shear_factor,
                                              sp, length, 0.5 * mass, inertia);
      for (const Index n : conn) {
        nd.mass[static_cast<std::size_t>(n)] += 0.5 * mass;
        rotary[static_cast<std::size_t>(n)] += inertia;
      }
      bm.ids.push_back(el.id);
      bm.nodes.push_back(conn);
      bm.part.push_back(static_cast<Index>(p));
      axes.push_back(axis_s);
      bm.initial_length.push_back(length);
      bm.mass.push_back(mass);
      bm.area.push_back(sp.area);
      bm.inertia_s.push_back(sp.inertia_s);
      bm.inertia_t.push_back(sp.inertia_t);
      bm.torsion.push_back(sp.torsion);
      bm.shear_area.push_back(sp.shear_area);
      bm.width_s.push_back(sp.width_s);
      bm.width_t.push_back(sp.width_t);
      bm.end_inertia.push_back(inertia);
      bm.flexural_step.push_back(omega > 0.0 ? 2.0 / omega : 1e30);
      bm.temperature.push_back(mm.initial_temperature());
    }
    b.end = bm.count();
    points += (b.end - b.begin) * b.points;
    back = back || mm.has_back_stress();
    bm.blocks.push_back(b);
  }
  const auto n = static_cast<std::size_t>(bm.count());
  bm.s_axis.resize(3, static_cast<Eigen::Index>(n));
  for (std::size_t e = 0; e < n; ++e)
    bm.s_axis.col(static_cast<Eigen::Index>(e)) = axes[e];
  bm.resultants.assign(6 * n, 0.0);
  bm.internal_energy.assign(n, 0.0);
  bm.time_step.assign(n, 0.0);
  bm.added_mass.assign(n, 0.0);
  bm.eroded.assign(n, 0);
  bm.corner_force.assign(12 * n, 0.0);
  bm.points.stress.setZero(6, points);
  if (back) bm.points.back_stress.setZero(6, points);
  bm.points.plastic_strain.assign(static_cast<std::size_t>(points), 0.0);
  bm.points.damage.assign(static_cast<std::size_t>(points), 0.0);
  if (n == 0) return;
  add_rotary_inertia(nd, rotary);
  build_node_corners(
      nd.count(), bm.nodes, [](std::size_t) { return 2; }, bm.end_offsets, bm.ends);
  own.push_back(make_beams_block(std::move(bm)));
}

void add_rotary_inertia(Nodes& nd, const std::vector<double>& inertia) {
  if (nd.rotary_inertia.empty()) {
    nd.rotary_inertia.assign(static_cast<std::size_t>(nd.count()), 0.0);
    nd.angular_velocity.setZero(3, nd.count());
    nd.previous_angular_velocity.setZero(3, nd.count());
  }
  for (std::size_t i = 0; i < inertia.size(); ++i)
    nd.rotary_inertia[i] += inertia[i];
}

}  // namespace mcdyna::solver::detail
