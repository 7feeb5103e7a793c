#pragma once
// Helpers for solver tests: a box mesh as deck text and one-call simulation of a deck.
#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "solver/contact/contact.hpp"
#include "solver/energy.hpp"
#include "solver/run/compile.hpp"
#include "solver/run/driver.hpp"
#include "solver/solids/solids.hpp"
#include "solver/spg/spg_parts.hpp"
#include "solver/spg/spg_solver.hpp"
#include "test_support.hpp"

namespace mcdyna::test {

/// *NODE and *ELEMENT_SOLID text of an nx x ny x nz box of edge h from the origin, part 1.
inline std::string box_mesh(int nx, int ny, int nz, double h, int first_node = 1,
                            int first_element = 1, int part = 1, double z0 = 0.0) {
  auto id = [&](int i, int j, int k) { return first_node + i + (nx + 1) * (j + (ny + 1) * k); };
  std::string s = "*NODE\n";
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        s += fmt::format("{:8d}{:16.8f}{:16.8f}{:16.8f}\n", id(i, j, k), i * h, j * h, z0 + k * h);
  s += "*ELEMENT_SOLID\n";
  int e = first_element;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        s += fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}\n", e++, part,
                         id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                         id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                         id(i, j + 1, k + 1));
  return s;
}

/// A 6 x 1 x 1 MAT_003 bar (FS = 0.05), one end held by SPC, the other pulled at 5 length/time
/// by prescribed motion until it necks and its elements erode. `controls`: the control and
/// database keywords after *KEYWORD.
inline std::string eroding_bar(const std::string& controls) {
  return "*KEYWORD\n" + controls +
         "*PART\nbar\n1,1,1\n*SECTION_SOLID\n1,1\n"
         "*MAT_PLASTIC_KINEMATIC\n1,1.0,100.0,0.3,0.5,1.0,1.0\n0,0,0.05\n" +
         box_mesh(6, 1, 1, 0.5) +
         "*SET_NODE_LIST\n1\n1,8,15,22\n*SET_NODE_LIST\n2\n7,14,21,28\n"
         "*BOUNDARY_SPC_SET\n1,0,1,1,1,0,0,0\n*BOUNDARY_PRESCRIBED_MOTION_SET\n2,1,0,3,1.0\n"
         "*DEFINE_CURVE\n3\n0,5\n1,5\n*END\n";
}

struct Simulation {
  std::unique_ptr<Loaded> loaded;
  std::unique_ptr<solver::State> state;
  solver::RunResult result;
};

/// A restart check's two runs of `deck` (a file): through to the end into DIR/through, then a
/// copy of those outputs continued from the first restart dump, d3dump01, into DIR/resumed
/// (REQUIREs both to end normally). Returns {through, resumed}.
inline std::pair<std::filesystem::path, std::filesystem::path> run_through_and_resumed(
    const TempDir& dir, const std::filesystem::path& deck) {
  const std::filesystem::path through = dir.path() / "through", resumed = dir.path() / "resumed";
  auto run = [&](const std::filesystem::path& out, const std::string& more) {
    const Run r = run_mcdyna("run " + deck.string() + " --out " + out.string() + " -q " + more);
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  };
  run(through, "");
  std::filesystem::copy(through, resumed);
  run(resumed, "--restart " + (resumed / "d3dump01").string());
  return {through, resumed};
}

/// Reads, checks and compiles a deck (REQUIREs no errors); run() then runs it.
/// The state's contact interface `k` (deck order, ties left out), owned by its block.
inline const solver::contact::Interface& contact_interface(const solver::State& s, std::size_t k) {
  return *solver::contact::interfaces_of(s).at(k);
}

inline Simulation prepare(const TempDir& dir, const std::string& text) {
  Simulation sim;
  sim.loaded = load_file(dir.write("deck.k", text), true);
  REQUIRE_MESSAGE(!sim.loaded->diags.has_errors(), sim.loaded->messages());
  core::Diagnostics d;
  sim.state = solver::compile(sim.loaded->model(), d);
  REQUIRE(sim.state != nullptr);
  return sim;
}

inline void run(Simulation& sim, const solver::RunHooks& hooks = {}) {
  sim.result = solver::run(*sim.state, hooks);
}

/// The largest |E_total / E_0 - 1| of a run, sampled every cycle: pass hooks() to run() (the
/// tracker must outlive the run). E_0 is the energy at cycle `from_cycle`: from 1, the drift
/// leaves out the start-up's one-step offset of central differences (first order in the step:
/// measured on a noisy free SPG block, 2.6e-6 at the code's step and 1.6e-6 at half of it,
/// with plain nodal integration as with ITB 1).
struct EnergyDrift {
  long from_cycle = 0;
  double initial = -1.0, worst = 0.0;
  [[nodiscard]] solver::RunHooks hooks() {
    solver::RunHooks h;
    h.output_due = [](const solver::State&) { return true; };
    h.write = [this](const solver::State& s, const Eigen::Matrix3Xd& previous, bool) {
      if (s.cycle < from_cycle) return;
      const solver::EnergySummary e = solver::energy_summary(s, previous);
      if (initial < 0.0) initial = e.total;
      worst = std::max(worst, std::abs(e.total / initial - 1.0));
    };
    return h;
  }
};

/// A deck run on 1 and on 2 threads: the nodes' final positions and angular velocities of each
/// (the bitwise-identity checks of the shells and beams).
struct ThreadRuns {
  std::array<Eigen::Matrix3Xd, 2> positions, spins;
};
inline ThreadRuns run_on_one_and_two_threads(const std::string& deck) {
  ThreadRuns r;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    TempDir dir;
    Simulation sim = prepare(dir, deck);
    run(sim);
    r.positions[static_cast<std::size_t>(threads - 1)] = sim.state->nodes.position;
    r.spins[static_cast<std::size_t>(threads - 1)] = sim.state->nodes.angular_velocity;
  }
  omp_set_num_threads(omp_get_num_procs());
  return r;
}

/// The largest node speed of the model.
inline double largest_speed(const solver::State& s) {
  double v = 0.0;
  for (solver::Index n = 0; n < s.nodes.count(); ++n)
    v = std::max(v, s.nodes.velocity.col(n).norm());
  return v;
}

/// The critical-step check of the SPG tests: `deck` (a free SPG block, 400 cycles), its
/// velocities from `setup`, is run at 0.9 and 1.1 x the critical step its first renewal found
/// (2 / omega_max by power iteration): bounded below it, blown up above it (the run stopped, or
/// the largest node speed grown a thousandfold). Returns that critical step.
template <class Setup>
double check_blow_up_at_critical_step(const std::string& deck, Setup setup) {
  double critical = 0.0;
  auto at_fixed_step = [&](double factor, double& speed_ratio) {
    TempDir dir;
    Simulation sim = prepare(dir, deck);
    setup(*sim.state);
    solver::spg::Domain& d = solver::spg::domain_of(*sim.state, 0);
    solver::spg::initialise(*sim.state, d);
    critical = d.kernel.step_bound.initial_critical;
    sim.state->time_control.fixed_step = factor * critical;
    const double v0 = largest_speed(*sim.state);
    run(sim);
    speed_ratio = largest_speed(*sim.state) / v0;
    return sim.result.reason;
  };
  double below = 0.0, above = 0.0;
  const solver::StopReason stable = at_fixed_step(0.9, below);
  MESSAGE("critical step ", critical, "; largest speed after 400 cycles at 0.9 x: ", below,
          " x the initial");
  CHECK(stable == solver::StopReason::end_cycle);
  CHECK(below < 1.5);
  const solver::StopReason unstable = at_fixed_step(1.1, above);
  MESSAGE("at 1.1 x: stop reason ", static_cast<int>(unstable), ", speed ratio ", above);
  CHECK((unstable != solver::StopReason::end_cycle || !(above < 1e3)));
  return critical;
}

/// Whether any diagnostic's message contains `text`.
inline bool mentions(const core::Diagnostics& d, const std::string& text) {
  for (const auto& m : d.all())
    if (m.message.find(text) != std::string::npos) return true;
  return false;
}

/// Replaces the first occurrence of `from` in `text` (which must hold it).
inline std::string with(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

/// The 1 kg elastic cube of the walls' and sensors' tests (one hexahedron, 0.1 m, E 1 GPa,
/// TSSFAC 0.6: a lone one-point hexahedron breathes above its step estimate). Its corners at x, y
/// in [-0.05, 0.05] + (cx, cy), z in [cz, cz + 0.1]; gravity g along -z; initial velocity (vx, 0,
/// vz); `wall`: more keywords (a wall and its curves).
struct Cube {
  double cx = 0.0, cy = 0.0, cz = 0.0;
  double vx = 0.0, vz = 0.0, gravity = 0.0, end = 0.5;
};

inline std::string cube_deck(const Cube& c, const std::string& wall) {
  std::string nodes = "*NODE\n";
  int id = 1;
  for (const double z : {c.cz, c.cz + 0.1})
    for (const auto& [x, y] : {std::pair{-0.05, -0.05}, {0.05, -0.05}, {0.05, 0.05}, {-0.05, 0.05}})
      nodes += fmt::format("{},{},{},{:.17g}\n", id++, c.cx + x, c.cy + y, z);
  return fmt::format(
      "*KEYWORD\n*CONTROL_TERMINATION\n{}\n*CONTROL_TIMESTEP\n0,0.6\n*PART\ncube\n1,1,1\n"
      "*SECTION_SOLID\n1\n*MAT_ELASTIC\n1,1000,1e9,0.3\n{}*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n"
      "*INITIAL_VELOCITY_GENERATION\n1,2,0,{},0,{}\n0,0,0,0,0,0\n"
      "*LOAD_BODY_Z\n1\n*DEFINE_CURVE\n1\n0,{}\n100,{}\n{}*END\n",
      c.end, nodes, c.vx, c.vz, c.gravity, c.gravity, wall);
}

/// Gaps along z between consecutive layers (particles of equal initial z, mean current z) of
/// the first SPG part's particles that `keep` selects, in order of initial z.
template <class Keep>
std::vector<double> layer_gaps(const solver::State& s, Keep keep) {
  const solver::spg::Domain& d = solver::spg::domain_of(s, 0);
  std::map<long, std::pair<double, int>> layers;  // initial z in micrometres -> (sum z, count)
  for (solver::Index i = 0; i < d.count(); ++i) {
    if (!keep(i)) continue;
    auto& l = layers[std::lround(1000.0 * d.particles.initial_position(2, i))];
    l.first += s.nodes.position(2, d.particles.nodes[static_cast<std::size_t>(i)]);
    ++l.second;
  }
  std::vector<double> mean, gaps;
  for (const auto& [z, l] : layers)
    mean.push_back(l.first / l.second);
  for (std::size_t k = 1; k < mean.size(); ++k)
    gaps.push_back(mean[k] - mean[k - 1]);
  return gaps;
}

/// Layers that pair up show as gaps alternating long-short: the depth of the deepest local
/// extremum of the gap sequence (the smaller of its two steps), 0 for a smooth (monotone or
/// single-humped) sequence. Gaps skip_first..skip_last are left out (e.g. a notch).
inline double deepest_extremum(const std::vector<double>& g, std::size_t skip_first = 1,
                               std::size_t skip_last = 0) {
  double worst = 0.0;
  for (std::size_t k = 1; k + 1 < g.size(); ++k) {
    if (k >= skip_first && k <= skip_last) continue;
    const double below = g[k] - g[k - 1], above = g[k] - g[k + 1];
    if (below * above > 0.0) worst = std::max(worst, std::min(std::abs(below), std::abs(above)));
  }
  return worst;
}

/// Oscillation of an SPG velocity field: RMS over the particles of v_I - sum_J phi_J(X_I) v_J
/// relative to `scale`. The spurious modes of nodal integration alternate from particle to
/// particle and are not reproduced by the smooth interpolant; a physical wave is, to O(h^2).
inline double oscillation_norm(const solver::State& s, double scale) {
  const solver::spg::Domain& d = solver::spg::domain_of(s, 0);
  const Eigen::Matrix3Xd& v = s.nodes.velocity;
  double r2 = 0.0;
  for (solver::Index i = 0; i < d.count(); ++i) {
    const auto ii = static_cast<std::size_t>(i);
    solver::Vec3 interp = solver::Vec3::Zero();
    for (solver::Index p = d.kernel.list.offsets[ii]; p < d.kernel.list.offsets[ii + 1]; ++p) {
      const auto pp = static_cast<std::size_t>(p);
      interp += d.kernel.shape.value[pp] *
                v.col(d.particles.nodes[static_cast<std::size_t>(d.kernel.list.neighbours[pp])]);
    }
    r2 += (v.col(d.particles.nodes[ii]) - interp).squaredNorm();
  }
  return std::sqrt(r2 / static_cast<double>(d.count())) / scale;
}

/// The coarse rod of the elastic-wave benchmark (decks/elastic_wave/rod_spg_h0.2.k) to t = 80
/// (two wave periods) with the given stabilisation and the kernel renewed at every SMSTEP
/// check, as under large deformation (the renewals take up the particle-scale motion that
/// nodal integration does not see): the oscillation norm of its final velocities relative to
/// |v0| = 0.01.
inline double elastic_wave_oscillation(solver::spg::Stabilization mode) {
  TempDir dir;
  Simulation sim = prepare(dir, source_text("decks/elastic_wave/rod_spg_h0.2.k"));
  for (solver::spg::Domain* d : solver::spg::domains_of(*sim.state)) {
    d->settings.stabilization = mode;
    d->settings.renewal_strain = std::getenv("RENEW") ? std::atof(std::getenv("RENEW")) : 0.0;
  }
  run(sim);
  REQUIRE(sim.result.reason == solver::StopReason::end_time);
  return oscillation_norm(*sim.state, 0.01);
}

/// Runs `deck` to its end on 1 and then 2 threads, `setup` applied to each fresh state first,
/// and returns whether the final node positions agree bit for bit.
template <class Setup>
bool same_bits_on_1_and_2_threads(const std::string& deck, Setup setup) {
  Eigen::Matrix3Xd positions[2];
  for (int threads = 1; threads <= 2; ++threads) {
    TempDir dir;
    Simulation sim = prepare(dir, deck);
    setup(*sim.state);
    omp_set_num_threads(threads);
    run(sim);
    REQUIRE(sim.result.reason == solver::StopReason::end_cycle);
    positions[threads - 1] = sim.state->nodes.position;
  }
  omp_set_num_threads(2);
  return (positions[0].array() == positions[1].array()).all();
}

}  // namespace mcdyna::test
