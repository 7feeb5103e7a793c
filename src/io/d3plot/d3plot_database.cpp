#include "io/d3plot/d3plot_database.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "io/d3plot/d3plot_cells.hpp"
#include "solver/block.hpp"
#include "solver/energy.hpp"

namespace mcdyna::io::d3plot {

namespace {

constexpr int kWordBytes = 4;
// The code, version and format words LS-DYNA writes (ICODE 6: a 3-D explicit code; NDIM 4:
// element connectivity unpacked; format version 960), MAXINT -10003: three shell layers and
// element deletion flags in every state; IOSHL 1000 written, 999 not.
constexpr int kCode = 6, kDimensionWord = 4;
constexpr double kFormatVersion = 960.0;
constexpr int kMaxIntWithDeletion = -(10000 + kShellLayers);
constexpr int kWritten = 1000, kNotWritten = 999;
constexpr int kGlobalWords = 6, kPartWords = 7;  // KE IE TE vx vy vz; per part IE KE v(3) m HGE
constexpr int kIdHeaderWords = 16;               // NSORT .. NMMAT, the part IDs' pointers included
constexpr int kPartTitles = 90001, kTitleChars = 72;

// The number (1-based) of each part ID in the ascending list.
Index part_number(const Layout& l, model::Id id) {
  const auto it = std::lower_bound(l.parts.begin(), l.parts.end(), id);
  if (it == l.parts.end() || *it != id)
    throw std::logic_error("d3plot: an element of a part the state does not list");
  return static_cast<Index>(it - l.parts.begin()) + 1;
}

Index distinct_parts(const ElementClass& c) {
  std::vector<model::Id> p = c.parts;
  std::sort(p.begin(), p.end());
  return static_cast<Index>(std::unique(p.begin(), p.end()) - p.begin());
}

StateCells cells_of(const solver::State& s) {
  StateCells c;
  for (const std::unique_ptr<solver::Block>& b : s.blocks)
    b->write_state(s, c);
  return c;
}

Layout layout_of(const solver::State& s, const StateCells& c) {
  Layout l;
  l.nodes = s.nodes.count();
  l.solids = c.solids.count();
  l.beams = c.beams.count();
  l.shells = c.shells.count();
  l.solid_parts = distinct_parts(c.solids);
  l.beam_parts = distinct_parts(c.beams);
  l.shell_parts = distinct_parts(c.shells);
  l.particles = c.particles.count();
  l.particle_parts = distinct_parts(c.particles);
  for (const solver::PartInfo& p : s.parts)
    l.parts.push_back(p.id);
  std::sort(l.parts.begin(), l.parts.end());
  return l;
}

void connectivity(Words& w, const Layout& l, const ElementClass& c, int extra_zero_nodes) {
  for (Index e = 0; e < c.count(); ++e) {
    for (int k = 0; k < c.corners; ++k)
      w.integer(c.nodes[static_cast<std::size_t>(e * c.corners + k)] + 1);
    for (int k = 0; k < extra_zero_nodes; ++k)
      w.integer(0);
    w.integer(part_number(l, c.parts[static_cast<std::size_t>(e)]));
  }
}

void element_words(Words& w, const ElementClass& c) {
  for (const double v : c.values)
    w.real(v);
}

void deletion_flags(Words& w, const ElementClass& c) {
  for (const std::uint8_t d : c.deleted)
    w.real(d ? 0.0 : 1.0);
}

}  // namespace

std::int64_t Layout::global_words() const {
  return kGlobalWords + kPartWords * static_cast<std::int64_t>(parts.size());
}

std::int64_t Layout::id_words() const {
  return kIdHeaderWords + std::int64_t{nodes} + solids + beams + shells +
         3 * static_cast<std::int64_t>(parts.size());
}

std::int64_t Layout::state_words() const {
  return 1 + global_words() + 9 * std::int64_t{nodes} + std::int64_t{solids} * kSolidWords +
         std::int64_t{beams} * kBeamWords + std::int64_t{shells} * kShellWords +
         (std::int64_t{solids} + beams + shells) +  // the deletion flags
         std::int64_t{particles} * (1 + kParticleWords);
}

Database::Database(std::filesystem::path dir, const FamilyPosition* resume) : dir_(std::move(dir)) {
  if (resume != nullptr) resume_ = *resume;
}

Database::~Database() = default;

FamilyPosition Database::position() const {
  if (family_) return family_->position();
  return resume_.value_or(FamilyPosition{});
}

void Database::write(const solver::State& s, const Eigen::Matrix3Xd& previous,
                     const Eigen::Matrix3Xd& velocity) {
  const StateCells cells = cells_of(s);
  if (!layout_) {
    layout_ = layout_of(s, cells);
    family_ = resume_ ? std::make_unique<Family>(dir_, "d3plot", kWordBytes, *resume_)
                      : std::make_unique<Family>(dir_, "d3plot", control_and_geometry(s, cells));
  }
  const Layout& l = *layout_;
  if (cells.solids.count() != l.solids || cells.beams.count() != l.beams ||
      cells.shells.count() != l.shells || cells.particles.count() != l.particles)
    throw std::logic_error(
        "d3plot: the blocks showed another set of elements than at the first "
        "state");
  const Words state = state_words(s, cells, previous, velocity);
  if (state.size() != l.state_words())
    throw std::logic_error("d3plot: a state of " + std::to_string(state.size()) +
                           " words where the control words give " +
                           std::to_string(l.state_words()));
  family_->append(state);
}

Words Database::control_and_geometry(const solver::State& s, const StateCells& c) const {
  const Layout& l = *layout_;
  Words w(kWordBytes);
  // Control words 0-63.
  w.text(s.title, 10);
  w.integer(0);  // RUNTIME: no date, so that every run of a deck writes the same bytes
  w.integer(1);  // FILETYPE: d3plot
  w.integer(0);  // SOURCE: no LS-DYNA revision
  w.text("MCDY", 1);
  w.real(kFormatVersion);
  w.integer(kDimensionWord);
  w.integer(l.nodes);
  w.integer(kCode);
  w.integer(l.global_words());
  w.integer(0);  // IT: no temperatures
  w.integer(1);  // IU: coordinates
  w.integer(1);  // IV: velocities
  w.integer(1);  // IA: accelerations
  w.integer(l.solids);
  w.integer(l.solid_parts);
  w.integer(0);  // NUMDS
  w.integer(0);  // NUMST
  w.integer(kSolidWords);
  w.integer(l.beams);
  w.integer(l.beam_parts);
  w.integer(kBeamWords);
  w.integer(l.shells);
  w.integer(l.shell_parts);
  w.integer(kShellWords);
  w.integer(0);  // NEIPH
  w.integer(0);  // NEIPS
  w.integer(kMaxIntWithDeletion);
  w.integer(l.particles);       // NMSPH
  w.integer(l.particle_parts);  // NGPSPH
  w.integer(l.id_words());
  w.integer(0);            // NELT
  w.integer(0);            // NUMMATT
  w.integer(0);            // NV3DT
  w.integer(kWritten);     // IOSHL1: stress
  w.integer(kWritten);     // IOSHL2: plastic strain
  w.integer(kNotWritten);  // IOSHL3: shell force resultants
  w.integer(kWritten);     // IOSHL4: thickness, energy
  for (int k = 47; k < 51; ++k)
    w.integer(0);                                        // IALEMAT NCFDV1 NCFDV2 NADAPT
  w.integer(static_cast<std::int64_t>(l.parts.size()));  // NMMAT
  for (int k = 52; k < 64; ++k)
    w.integer(0);  // NUMFLUID INN NPEFG NEL48 IDTDT EXTRA and the unused words
  // The SPH flags (the SPG particles' state words): ISPHFG1 the number of flags, then radius
  // (not written), pressure, stress, plastic strain, density, energy, neighbours, strain,
  // mass (not written) and the history words (bond damage, integration state).
  if (l.particles > 0)
    for (const std::int64_t v : {11, 0, 1, 6, 1, 0, 0, 0, 0, 0, 2})
      w.integer(v);
  // Geometry: the initial coordinates, then each class's connectivity with its part number.
  for (Index n = 0; n < l.nodes; ++n)
    for (int k = 0; k < 3; ++k)
      w.real(s.nodes.initial(k, n));
  connectivity(w, l, c.solids, 0);
  connectivity(w, l, c.beams, 3);  // N3 (orientation) and two unused words: 0
  connectivity(w, l, c.shells, 0);
  // User IDs. The pointer words are word addresses in LS-DYNA's memory that readers do not use;
  // written as the 1-based word of each list within this section.
  const std::int64_t np = static_cast<std::int64_t>(l.parts.size());
  const std::int64_t node_ids = kIdHeaderWords + 1, solid_ids = node_ids + l.nodes,
                     beam_ids = solid_ids + l.solids, shell_ids = beam_ids + l.beams,
                     thick_ids = shell_ids + l.shells, defined = thick_ids, sorted = defined + np,
                     cross = sorted + np;
  for (const std::int64_t v :
       {-node_ids, solid_ids, beam_ids, shell_ids, thick_ids, std::int64_t{l.nodes},
        std::int64_t{l.solids}, std::int64_t{l.beams}, std::int64_t{l.shells}, std::int64_t{0},
        sorted, defined, cross, np, std::int64_t{0}, np})
    w.integer(v);
  for (const model::Id id : s.nodes.ids)
    w.integer(id);
  for (const ElementClass* cl : {&c.solids, &c.beams, &c.shells})
    for (const model::Id id : cl->ids)
      w.integer(id);
  for (int list = 0; list < 2; ++list)  // in the order defined, then sorted: the same here
    for (const model::Id id : l.parts)
      w.integer(id);
  for (std::int64_t k = 1; k <= np; ++k)
    w.integer(k);
  // The SPH node and material list: each particle's node number and part number.
  for (Index p = 0; p < l.particles; ++p) {
    w.integer(c.particles.nodes[static_cast<std::size_t>(p)] + 1);
    w.integer(part_number(l, c.particles.parts[static_cast<std::size_t>(p)]));
  }
  w.real(kEndOfFile);
  // Part titles (*PART's heading), then the end of the geometry.
  w.integer(kPartTitles);
  w.integer(np);
  for (const model::Id id : l.parts) {
    const auto p = std::find_if(s.parts.begin(), s.parts.end(),
                                [id](const solver::PartInfo& q) { return q.id == id; });
    w.integer(id);
    w.chars(p->heading, kTitleChars);
  }
  w.real(kEndOfFile);
  return w;
}

Words Database::state_words(const solver::State& s, const StateCells& c,
                            const Eigen::Matrix3Xd& previous,
                            const Eigen::Matrix3Xd& velocity) const {
  const Layout& l = *layout_;
  Words w(kWordBytes);
  w.real(s.time);
  // Globals: the model's energies and mean velocity, then per part (by number) its internal and
  // kinetic energy, velocity (a rigid part's centre velocity, else momentum / mass), mass and
  // hourglass energy, each as one list over the parts.
  const solver::EnergySummary e = solver::energy_summary(s, previous);
  w.real(e.kinetic);
  w.real(e.internal);
  w.real(e.total);
  const solver::Vec3 mean = e.mass > 0.0 ? solver::Vec3(e.momentum / e.mass) : solver::Vec3::Zero();
  for (int k = 0; k < 3; ++k)
    w.real(mean[k]);
  std::vector<solver::PartSummary> parts = solver::part_summaries(s, previous);
  std::sort(
      parts.begin(), parts.end(),
      [](const solver::PartSummary& a, const solver::PartSummary& b) { return a.part < b.part; });
  for (const solver::PartSummary& p : parts)
    w.real(p.internal);
  for (const solver::PartSummary& p : parts)
    w.real(p.kinetic);
  for (const solver::PartSummary& p : parts) {
    const solver::Vec3 v = !p.rigid_velocity.isZero() ? p.rigid_velocity
                           : p.mass > 0.0             ? solver::Vec3(p.momentum / p.mass)
                                                      : solver::Vec3::Zero();
    for (int k = 0; k < 3; ++k)
      w.real(v[k]);
  }
  for (const solver::PartSummary& p : parts)
    w.real(p.mass);
  for (const solver::PartSummary& p : parts)
    w.real(p.hourglass);
  // Nodes: current coordinates, velocities, accelerations.
  const solver::Nodes& nd = s.nodes;
  for (const Eigen::Matrix3Xd* m : {&nd.position, &velocity, &nd.acceleration})
    for (Index n = 0; n < l.nodes; ++n)
      for (int k = 0; k < 3; ++k)
        w.real((*m)(k, n));
  element_words(w, c.solids);
  element_words(w, c.beams);
  element_words(w, c.shells);
  deletion_flags(w, c.solids);
  deletion_flags(w, c.shells);
  deletion_flags(w, c.beams);
  // The particles: the part number (never negative: a particle is not deleted; a torn one is
  // debris, state 3), then its words.
  const ElementClass& pc = c.particles;
  for (Index p = 0; p < pc.count(); ++p) {
    w.real(part_number(l, pc.parts[static_cast<std::size_t>(p)]));  // a real word, as all state
    for (int k = 0; k < pc.words; ++k)
      w.real(pc.values[static_cast<std::size_t>(p * pc.words + k)]);
  }
  return w;
}

}  // namespace mcdyna::io::d3plot
