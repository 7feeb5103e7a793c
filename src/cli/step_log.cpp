#include "cli/step_log.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/contact/contact.hpp"
#include "solver/element_ref.hpp"
#include "solver/energy.hpp"
#include "solver/spg/spg_parts.hpp"

namespace mcdyna::cli {

namespace {

constexpr long kRowsPerWrite = 4096;

struct ParticleFacts {
  double nearest_now = 0.0, nearest_initial = 0.0;  ///< over the row / over the bonds
  double row_mass_factor = 1.0;                     ///< smallest (m-hat / physical) of the row
  bool in_contact = false;
};

ParticleFacts facts(const solver::State& s, const solver::spg::Domain& d, solver::Index j) {
  ParticleFacts f;
  const auto jj = static_cast<std::size_t>(j);
  const Eigen::Vector3d x = s.nodes.position.col(d.particles.nodes[jj]);
  double now = std::numeric_limits<double>::infinity();
  double factor = std::numeric_limits<double>::infinity();
  for (solver::Index p = d.kernel.list.offsets[jj]; p < d.kernel.list.offsets[jj + 1]; ++p) {
    const auto k = static_cast<std::size_t>(d.kernel.list.neighbours[static_cast<std::size_t>(p)]);
    factor =
        std::min(factor, d.particles.mass[k] / (d.particles.mass[k] - d.particles.added_mass[k]));
    if (k != jj) now = std::min(now, (s.nodes.position.col(d.particles.nodes[k]) - x).norm());
  }
  double initial = std::numeric_limits<double>::infinity();
  for (solver::Index b = d.kernel.bonds.offsets[jj]; b < d.kernel.bonds.offsets[jj + 1]; ++b)
    initial = std::min(initial, d.kernel.bonds.length[static_cast<std::size_t>(b)]);
  f.nearest_now = std::isfinite(now) ? now : 0.0;
  f.nearest_initial = std::isfinite(initial) ? initial : 0.0;
  f.row_mass_factor = std::isfinite(factor) ? factor : 1.0;
  for (const solver::contact::Interface* c : solver::contact::interfaces_of(s))
    for (const auto& a : c->applied)
      if (a.node == d.particles.nodes[jj]) f.in_contact = true;
  return f;
}

}  // namespace

StepLog::StepLog(const std::filesystem::path& path) : file_(io::RecordFile::create(path)) {
  file_.pending() =
      "cycle,time,step,estimate,controlling,controlling_id,physical_step,physical_node,"
      "nearest_now,nearest_initial,row_mass_factor,mobility,in_contact,added_mass,"
      "particle_critical\n";
}

void StepLog::add(const solver::State& s) {
  std::string kind = "none";
  long id = 0;
  if (s.controlling_element >= 0) {
    const solver::ElementRef r = solver::element_ref(s, s.controlling_element);
    kind = r.kind;
    id = static_cast<long>(r.id);
  } else if (s.controlling_particle >= 0) {
    kind = "particle";
    const auto& d = solver::spg::domain_of(s, s.controlling_domain);
    id = s.nodes.ids[static_cast<std::size_t>(
        d.particles.nodes[static_cast<std::size_t>(s.controlling_particle)])];
  }
  // The particle with the smallest step at its physical mass, over all SPG parts.
  const solver::spg::Domain* worst = nullptr;
  for (const solver::spg::Domain* d : solver::spg::domains_of(s))
    if (d->kernel.step_bound.physical_particle >= 0 &&
        (!worst || d->kernel.step_bound.physical < worst->kernel.step_bound.physical))
      worst = d;
  const double added = solver::total_added_mass(s);
  std::string& out = file_.pending();
  fmt::format_to(std::back_inserter(out), "{},{:.9e},{:.6e},{:.6e},{},{},", s.cycle, s.time, s.step,
                 s.critical_step, kind, id);
  if (worst) {
    const solver::Index j = worst->kernel.step_bound.physical_particle;
    const ParticleFacts f = facts(s, *worst, j);
    fmt::format_to(
        std::back_inserter(out), "{:.6e},{},{:.6e},{:.6e},{:.4f},{:.4f},{},{:.6e}\n",
        worst->kernel.step_bound.physical,
        s.nodes.ids[static_cast<std::size_t>(worst->particles.nodes[static_cast<std::size_t>(j)])],
        f.nearest_now, f.nearest_initial, f.row_mass_factor,
        worst->kernel.mobility[static_cast<std::size_t>(j)], f.in_contact ? 1 : 0, added);
    out.pop_back();  // the newline: the power iteration's critical step follows
    fmt::format_to(std::back_inserter(out), ",{:.6e}\n", worst->kernel.step_bound.critical);
  } else {
    fmt::format_to(std::back_inserter(out), "0,0,0,0,1,1,0,{:.6e},0\n", added);
  }
  if (++rows_ % kRowsPerWrite == 0) flush();
}

void StepLog::flush() {
  file_.commit();
}

}  // namespace mcdyna::cli
