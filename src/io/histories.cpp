// glstat, matsum, nodout, spcforc, rwforc and bndout in the layouts of LSTC's l2a
// (../shared/reference/keywords.md §3), each with its CSV twin.
#include <fmt/format.h>

#include <stdexcept>

#include "core/exact_sum.hpp"
#include "io/history_file.hpp"
#include "solver/block.hpp"
#include "solver/element_ref.hpp"
#include "solver/energy.hpp"
#include "solver/spg/spg_parts.hpp"

namespace mcdyna::io {

namespace {

using solver::Index;
using solver::State;
using solver::Vec3;

class Glstat final : public HistoryFile {
 public:
  Glstat(const HistoryPlace& place, const State& s)
      : HistoryFile(place, "glstat", s.title,
                    "time,time_step,kinetic_energy,internal_energy,stonewall_energy,"
                    "hourglass_energy,sliding_energy,external_work,eroded_internal_energy,"
                    "eroded_hourglass_energy,total_energy,energy_ratio,x_velocity,y_velocity,"
                    "z_velocity,added_mass,percent_mass_increase,controlling_element,"
                    "controlling_particle_node") {}

  void write(const OutputContext& c) override {
    const State& s = c.state;
    const solver::EnergySummary e = solver::energy_summary(s, c.previous);
    if (!initialised_) {
      initial_ = e.total;
      initialised_ = true;
    }
    const double reference = initial_ + e.external_work;
    const double ratio = reference != 0.0 ? e.total / reference : 1.0;
    const Vec3 v = e.mass > 0.0 ? Vec3(e.momentum / e.mass) : Vec3::Zero();
    const double percent = e.mass > 0.0 ? 100.0 * e.added_mass / e.mass : 0.0;
    // The step is set by a solid element or by an SPG particle (named by its node).
    const Index ce = s.controlling_element;
    const Index cp = s.controlling_particle;
    long long ce_id = 0, cp_node = 0, c_part = 0;
    const char* ce_kind = "solid";
    if (ce >= 0) {
      const solver::ElementRef r = solver::element_ref(s, ce);
      ce_id = r.id;
      c_part = r.part;
      ce_kind = r.kind;
    } else if (cp >= 0 && s.controlling_domain < solver::spg::domains_of(s).size()) {
      const solver::spg::Domain& d = solver::spg::domain_of(s, s.controlling_domain);
      cp_node =
          s.nodes.ids[static_cast<std::size_t>(d.particles.nodes[static_cast<std::size_t>(cp)])];
      c_part = s.parts[static_cast<std::size_t>(d.part)].id;
    }
    if (cp_node != 0)
      ascii("\n\n dt of cycle{:8d} is controlled by spg node {:10d} of part{:10d}\n\n", s.cycle,
            cp_node, c_part);
    else
      ascii("\n\n dt of cycle{:8d} is controlled by {:<9}{:10d} of part{:10d}\n\n", s.cycle,
            ce_kind, ce_id, c_part);
    auto line = [&](const char* label, double value) { ascii(" {:.<31}{:14.5E}\n", label, value); };
    line("time", s.time);
    line("time step", s.step);
    line("kinetic energy", e.kinetic);
    line("internal energy", e.internal);
    const std::vector<solver::WallRecord>& walls = c.records.walls;
    for (std::size_t w = 0; w < walls.size(); ++w)
      ascii(" {:.<31}{:14.5E} wall#{:2d}\n", "stonewall energy", walls[w].energy,
            static_cast<int>(w + 1));
    ascii(" hourglass energy ..............{:14.5E}\n", e.hourglass);
    line("system damping energy", 0.0);
    line("sliding interface energy", e.sliding);
    line("external work", e.external_work);
    line("eroded internal energy", e.eroded_internal);
    line("eroded hourglass energy", e.eroded_hourglass);
    line("total energy", e.total);
    line("total energy / initial energy", ratio);
    line("global x velocity", v[0]);
    line("global y velocity", v[1]);
    line("global z velocity", v[2]);
    ascii(" {:.<31}{:14d}\n", "number of nodes", s.nodes.count());
    ascii(" {:.<31}{:14d}\n", "number of elements", solver::numbered_elements(s));
    ascii(" {:.<31}{:14d}\n", "time per zone cycle.(nanosec)",
          static_cast<long long>(c.nanoseconds_per_zone_cycle));
    if (s.mass_scaling_dt > 0.0) {
      line("added mass", e.added_mass);
      line("percentage increase", percent);
    }
    csv("{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},"
        "{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{},{}\n",
        s.time, s.step, e.kinetic, e.internal, e.stonewall, e.hourglass, e.sliding, e.external_work,
        e.eroded_internal, e.eroded_hourglass, e.total, ratio, v[0], v[1], v[2], e.added_mass,
        percent, ce_id, cp_node);
    flush();
  }
  [[nodiscard]] std::vector<double> saved_values() const override {
    return {initialised_ ? 1.0 : 0.0, initial_};
  }

 private:
  void restore_values(const std::vector<double>& v) override {
    if (v.size() != 2) throw std::runtime_error("glstat: the restart dump's values do not fit");
    initialised_ = v[0] != 0.0;
    initial_ = v[1];
  }
  bool initialised_ = false;
  double initial_ = 0.0;
};

class Matsum final : public HistoryFile {
 public:
  Matsum(const HistoryPlace& place, const State& s)
      : HistoryFile(place, "matsum", s.title,
                    "time,part,internal_energy,kinetic_energy,eroded_internal_energy,x_momentum,"
                    "y_momentum,z_momentum,x_rigid_velocity,y_rigid_velocity,z_rigid_velocity,"
                    "hourglass_energy,added_mass") {
    std::vector<std::pair<long long, std::string>> parts;
    for (const auto& p : s.parts)
      parts.emplace_back(p.id, p.heading);
    legend(parts);
    flush();
  }

  void write(const OutputContext& c) override {
    const auto parts = solver::part_summaries(c.state, c.previous);
    ascii("\n\n time ={:13.4E}\n", c.state.time);
    for (const auto& p : parts) {
      ascii(" mat.#={:5d}             inten={:13.4E}     kinen={:13.4E}     eroded_ie={:13.4E}\n",
            p.part, p.internal, p.kinetic, p.eroded_internal);
      ascii(" x-mom={:13.4E}     y-mom={:13.4E}     z-mom={:13.4E}\n", p.momentum[0], p.momentum[1],
            p.momentum[2]);
      ascii(" x-rbv={:13.4E}     y-rbv={:13.4E}     z-rbv={:13.4E}\n", p.rigid_velocity[0],
            p.rigid_velocity[1], p.rigid_velocity[2]);
      ascii("                         hgeng={:13.4E}     +mass={:13.4E}\n", p.hourglass,
            p.added_mass);
      csv("{:.9e},{},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e}"
          "\n",
          c.state.time, p.part, p.internal, p.kinetic, p.eroded_internal, p.momentum[0],
          p.momentum[1], p.momentum[2], p.rigid_velocity[0], p.rigid_velocity[1],
          p.rigid_velocity[2], p.hourglass, p.added_mass);
    }
    flush();
  }
};

class Nodout final : public HistoryFile {
 public:
  Nodout(const HistoryPlace& place, const State& s, std::vector<Index> nodes)
      : HistoryFile(place, "nodout", s.title,
                    "time,node,x_disp,y_disp,z_disp,x_vel,y_vel,z_vel,x_accl,y_accl,z_accl,"
                    "x_coor,y_coor,z_coor"),
        nodes_(std::move(nodes)) {
    std::vector<std::pair<long long, std::string>> legend_nodes;
    for (const Index n : nodes_)
      legend_nodes.emplace_back(s.nodes.ids[static_cast<std::size_t>(n)], "");
    legend(legend_nodes);
    flush();
  }

  void write(const OutputContext& c) override {
    const State& s = c.state;
    const solver::Nodes& nd = s.nodes;
    ascii(
        "\n\n\n n o d a l   p r i n t   o u t   f o r   t i m e  s t e p{:8d}"
        "                              ( at time{:14.7E} )\n\n",
        s.cycle, s.time);
    ascii(
        " nodal point  x-disp     y-disp      z-disp      x-vel       y-vel       z-vel      "
        "x-accl      y-accl      z-accl      x-coor      y-coor      z-coor\n");
    for (const Index n : nodes_) {
      const Vec3 u = nd.position.col(n) - nd.initial.col(n);
      const Vec3 v = c.velocity.col(n), a = nd.acceleration.col(n), x = nd.position.col(n);
      const long long id = nd.ids[static_cast<std::size_t>(n)];
      ascii(
          "{:9d}{:13.4E}{:12.4E}{:12.4E}{:12.4E}{:12.4E}{:12.4E}{:12.4E}{:12.4E}{:12.4E}{:12.4E}"
          "{:12.4E}{:12.4E}\n",
          id, u[0], u[1], u[2], v[0], v[1], v[2], a[0], a[1], a[2], x[0], x[1], x[2]);
      csv("{:.9e},{},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},"
          "{:.9e}\n",
          s.time, id, u[0], u[1], u[2], v[0], v[1], v[2], a[0], a[1], a[2], x[0], x[1], x[2]);
    }
    flush();
  }

 private:
  std::vector<Index> nodes_;
};

class Spcforc final : public HistoryFile {
 public:
  Spcforc(const HistoryPlace& place, const State& s)
      : HistoryFile(place, "spcforc", s.title, "time,node,x_force,y_force,z_force") {}

  void write(const OutputContext& c) override {
    const State& s = c.state;
    ascii(" single point constraint forces\n\n output at time ={:14.5E}\n", s.time);
    Vec3 total = Vec3::Zero();
    for (const solver::ReactionRecord& reaction : c.records.reactions) {
      const Vec3& r = reaction.force;
      const long long id = reaction.node;
      total += r;
      ascii(" node={:8d} local x,y,z forces ={:14.4E}{:14.4E}{:14.4E}\n", id, r[0], r[1], r[2]);
      csv("{:.9e},{},{:.9e},{:.9e},{:.9e}\n", s.time, id, r[0], r[1], r[2]);
    }
    ascii("             force resultants   ={:14.4E}{:14.4E}{:14.4E}\n", total[0], total[1],
          total[2]);
    flush();
  }
};

// rwforc: the l2a layout is not in the reference; this follows the column order LS-DYNA users
// know (time, wall, normal force, x/y/z force) with one line per wall.
class Rwforc final : public HistoryFile {
 public:
  Rwforc(const HistoryPlace& place, const State& s)
      : HistoryFile(place, "rwforc", s.title, "time,wall,normal_force,x_force,y_force,z_force") {
    ascii("\n r i g i d   w a l l   f o r c e s\n\n");
    ascii("     time       wall#   normal-force      x-force        y-force        z-force\n");
    flush();
  }

  void write(const OutputContext& c) override {
    const State& s = c.state;
    // Force of the structure on the wall; the normal force is positive in contact.
    for (const solver::WallRecord& w : c.records.walls) {
      ascii("{:12.5E}{:8d}{:15.6E}{:15.6E}{:15.6E}{:15.6E}\n", s.time, w.id, w.normal_force,
            w.force[0], w.force[1], w.force[2]);
      csv("{:.9e},{},{:.9e},{:.9e},{:.9e},{:.9e}\n", s.time, w.id, w.normal_force, w.force[0],
          w.force[1], w.force[2]);
    }
    flush();
  }
};

// rcforc (keywords.md §3.2): per contact and output time a slave and a master line, the
// resultant of the contact forces on that side's nodes and its moment about the origin; "mass"
// is the mass of the slave nodes in contact (on the master line too).
class Rcforc final : public HistoryFile {
 public:
  Rcforc(const HistoryPlace& place, const State& s)
      : HistoryFile(place, "rcforc", s.title,
                    "time,contact,side,x_force,y_force,z_force,mass,x_moment,y_moment,z_moment") {
    ascii("\n r e s u l t a n t   i n t e r f a c e   f o r c e s\n\n");
    ascii(" {:>12}  {}\n", "contact", "title");
    for (const solver::ContactRecord& c : solver::history_records(s).contacts)
      ascii(" {:12d}  {}\n", c.id, c.heading);
    ascii("\n");
    flush();
  }

  void write(const OutputContext& c) override {
    const State& s = c.state;
    for (const solver::ContactRecord& in : c.records.contacts) {
      side("slave ", s.time, in.id, in.force_a, in.moment_a, in.mass_in_contact);
      side("master", s.time, in.id, in.force_b, in.moment_b, in.mass_in_contact);
    }
    flush();
  }

 private:
  void side(const char* name, double time, model::Id id, const Vec3& f, const Vec3& m,
            double mass) {
    ascii(
        "  {}{:11d} time{:12.5E}  x {:12.5E}  y {:12.5E}  z {:12.5E} mass {:12.5E}  mx "
        "{:12.5E}  my {:12.5E}  mz {:12.5E}\n",
        name, id, time, f[0], f[1], f[2], mass, m[0], m[1], m[2]);
    csv("{:.9e},{},{},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e}\n", time, id,
        name[0] == 's' ? "slave" : "master", f[0], f[1], f[2], mass, m[0], m[1], m[2]);
  }
};

class Bndout final : public HistoryFile {
 public:
  Bndout(const HistoryPlace& place, const State& s)
      : HistoryFile(place, "bndout", s.title,
                    "time,kind,id,x_force,y_force,z_force,x_moment,y_moment,z_moment,energy") {}

  void write(const OutputContext& c) override {
    const State& s = c.state;
    ascii("\n\n\n\n\n n o d a l   f o r c e/e n e r g y    o u t p u t   t={:9.3E}\n\n\n\n\n\n",
          s.time);
    ascii(" velocity boundary condition forces/rigid body moments\n");
    // The totals are exact sums of the lines (core::ExactSum): the force of a part pulled from
    // both ends cancels to round-off, whose digits then depend on no order of the terms.
    std::vector<core::ExactSum> sums(4);
    // One nd# line per prescribed node, as LS-DYNA prints them, then the rigid parts.
    for (const solver::BoundaryRecord& b : c.records.boundaries) {
      const Vec3& f = b.force;
      if (b.kind == solver::BoundaryRecord::Kind::node) {
        ascii(" nd#{:8d}  xforce={:13.4E}   yforce={:13.4E}  zforce={:13.4E}   energy={:13.4E}\n",
              b.id, f[0], f[1], f[2], b.energy);
        csv("{:.9e},node,{},{:.9e},{:.9e},{:.9e},0,0,0,{:.9e}\n", s.time, b.id, f[0], f[1], f[2],
            b.energy);
      } else {
        const Vec3& m = b.moment;
        ascii("mat#{:8d}  xforce={:13.4E}   yforce={:13.4E}  zforce={:13.4E}   energy={:13.4E}\n",
              b.id, f[0], f[1], f[2], b.energy);
        ascii("             xmoment={:13.4E}  ymoment={:13.4E} zmoment={:13.4E}\n", m[0], m[1],
              m[2]);
        csv("{:.9e},rigid_part,{},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e}\n", s.time, b.id,
            f[0], f[1], f[2], m[0], m[1], m[2], b.energy);
      }
      for (int k = 0; k < 3; ++k)
        sums[static_cast<std::size_t>(k)].add(f[k]);
      sums[3].add(b.energy);
    }
    ascii("              xtotal={:13.4E}   ytotal={:13.4E}  ztotal={:13.4E}   etotal={:13.4E}\n",
          sums[0].value(), sums[1].value(), sums[2].value(), sums[3].value());
    flush();
  }
};

}  // namespace

std::unique_ptr<HistoryFile> make_history(const std::string& name, const HistoryPlace& dir,
                                          const State& state,
                                          const std::vector<Index>& history_nodes) {
  if (name == "glstat") return std::make_unique<Glstat>(dir, state);
  if (name == "matsum") return std::make_unique<Matsum>(dir, state);
  if (name == "nodout") return std::make_unique<Nodout>(dir, state, history_nodes);
  if (name == "spcforc") return std::make_unique<Spcforc>(dir, state);
  if (name == "rwforc") return std::make_unique<Rwforc>(dir, state);
  if (name == "bndout") return std::make_unique<Bndout>(dir, state);
  if (name == "rcforc") return std::make_unique<Rcforc>(dir, state);
  return nullptr;
}

}  // namespace mcdyna::io
