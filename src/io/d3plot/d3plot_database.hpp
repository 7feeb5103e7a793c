#pragma once
/// LS-DYNA's binary state database, d3plot (issue 49), written beside the VTK series for the
/// LS-PrePost habit, in the layout of LSTC's "LS-DYNA Database Binary Output Files":
///  - `d3plot`: 64 control words, the geometry (node coordinates; solids, beams, shells with
///    their part numbers), the user IDs (nodes, elements, parts) and the part titles;
///  - `d3plot01`, ...: the states, each the time, the global and per-part energies, velocities
///    and masses, the nodes' coordinates, velocities and accelerations, every element's words
///    (d3plot_cells.hpp), the element deletion flags (1 intact, 0 eroded) and the SPG
///    particles in the SPH particle section (their part number, pressure, stress, plastic
///    strain, bond damage and integration state).
/// Parts are numbered by ascending user ID, so the sorted, the defined and the cross-reference
/// part lists of the ID section agree. Single precision (4-byte words). The control words that
/// carry a date or a code version hold fixed values, so that two runs of a deck, on any number
/// of processes, write the same bytes.
#include <Eigen/Core>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/d3plot/d3plot_family.hpp"
#include "solver/state.hpp"

namespace mcdyna::io::d3plot {

using solver::Index;
class StateCells;

/// The layout of the database, fixed by the first state: counts, word counts per element, the
/// part numbering. What the control words say and every state is sized by.
struct Layout {
  Index nodes = 0, solids = 0, beams = 0, shells = 0;
  Index solid_parts = 0, beam_parts = 0, shell_parts = 0;  ///< NUMMAT8, NUMMAT2, NUMMAT4
  Index particles = 0, particle_parts = 0;                 ///< NMSPH, NGPSPH
  std::vector<model::Id> parts;                            ///< by number - 1: ascending IDs
  [[nodiscard]] std::int64_t global_words() const;         ///< NGLBV
  [[nodiscard]] std::int64_t id_words() const;             ///< NARBS
  /// Words of one state (the time word included, the end-of-file marker not), by LS-DYNA's
  /// formula.
  [[nodiscard]] std::int64_t state_words() const;
};

class Database {
 public:
  /// A new family in `dir`, or the one a restart dump continues (`resume`).
  explicit Database(std::filesystem::path dir, const FamilyPosition* resume = nullptr);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  /// Writes the state at its current time (the geometry first, with the first state):
  /// `previous` v^{n-1/2} for the energies, `velocity` the nodal velocities at t.
  void write(const solver::State& state, const Eigen::Matrix3Xd& previous,
             const Eigen::Matrix3Xd& velocity);

  /// Where the family stands, for a restart dump.
  [[nodiscard]] FamilyPosition position() const;
  [[nodiscard]] std::int64_t states() const { return position().states; }
  [[nodiscard]] const std::filesystem::path& dir() const { return dir_; }

 private:
  [[nodiscard]] Words control_and_geometry(const solver::State& s, const StateCells& c) const;
  [[nodiscard]] Words state_words(const solver::State& s, const StateCells& c,
                                  const Eigen::Matrix3Xd& previous,
                                  const Eigen::Matrix3Xd& velocity) const;
  std::filesystem::path dir_;
  std::optional<FamilyPosition> resume_;
  std::optional<Layout> layout_;
  std::unique_ptr<Family> family_;
};

}  // namespace mcdyna::io::d3plot
