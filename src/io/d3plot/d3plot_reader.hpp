#pragma once
/// The project's own d3plot reader (issue 49): mcdyna's families and LS-DYNA's, for `mcdyna
/// compare` and the checks where VTK 9.1's reader falls short (it reads the user IDs of a 4-byte
/// file as 8-byte words). It reads what LSTC's "LS-DYNA Database Binary Output Files" lays out
/// for the data compared: the control words (with the EXTRA words), the material-type section
/// (rigid shells carry no state words), the SPH flags, the geometry, the user IDs, the SPH node
/// list, and per state the time, the nodes' coordinates, velocities and accelerations, each
/// element's words, the deletion flags and the SPH particles' words. 4- and 8-byte words. What
/// it does not read (thick shells' words aside from their size, airbags, road surfaces, rigid
/// body states, CFD and multi-solver data) is refused with a message naming it, never misread.
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace mcdyna::io::d3plot {

class ReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What the control words say (LSTC's names).
struct Control {
  int word_bytes = 4;
  std::string title;
  std::int64_t ndim = 0, numnp = 0, nglbv = 0, it = 0, iu = 0, iv = 0, ia = 0;
  std::int64_t nel8 = 0, nv3d = 0, nel2 = 0, nv1d = 0, nel4 = 0, nv2d = 0, nelt = 0, nv3dt = 0;
  std::int64_t maxint = 0, nmsph = 0, narbs = 0, nmmat = 0, extra = 0, numrbe = 0;
  std::int64_t sph_words = 0;           ///< NUM_SPH_DATA: words per particle in a state
  std::vector<std::int64_t> sph_flags;  ///< ISPHFG(2..): words of radius, pressure, stress, ...
  [[nodiscard]] bool element_deletion() const { return maxint <= -10000; }
  /// Words per node between the coordinates and the velocities: IT's temperatures (1, 4 with
  /// the heat flux, 6 in three layers) and the mass-scaling word (IT 1x).
  [[nodiscard]] std::int64_t thermal_words() const {
    const std::int64_t t = it % 10;
    return (t == 1 ? 1 : t == 2 ? 4 : t == 3 ? 6 : 0) + (it / 10 == 1 ? 1 : 0);
  }
  [[nodiscard]] bool node_deletion() const { return maxint < 0 && maxint > -10000; }
};

/// One element class's geometry: node numbers (0-based), user IDs and part IDs.
struct Elements {
  int corners = 0;
  std::vector<std::int64_t> nodes;
  std::vector<std::int64_t> ids, parts;
  std::vector<std::uint8_t> rigid;  ///< shells of a rigid material (no state words)
  [[nodiscard]] std::size_t count() const { return ids.size(); }
};

/// One state: values as read (single or double precision, widened).
struct StateData {
  double time = 0.0;
  std::vector<double> x, v, a;        ///< 3 per node, or empty when not written
  std::vector<double> solids, beams;  ///< nv3d / nv1d words per element
  std::vector<double> shells;         ///< nv2d words per deformable shell (rigid: none)
  std::vector<double> particles;      ///< sph_words per particle
  std::vector<std::uint8_t> solid_deleted, shell_deleted, beam_deleted;
};

class Reader {
 public:
  /// Opens the family whose first file is `path` (a file, or a folder holding `d3plot`).
  explicit Reader(const std::filesystem::path& path);

  [[nodiscard]] const Control& control() const { return c_; }
  [[nodiscard]] const std::vector<std::int64_t>& node_ids() const { return node_ids_; }
  [[nodiscard]] const std::vector<double>& initial() const { return initial_; }
  [[nodiscard]] const Elements& solids() const { return solids_; }
  [[nodiscard]] const Elements& beams() const { return beams_; }
  [[nodiscard]] const Elements& shells() const { return shells_; }
  [[nodiscard]] const Elements& particles() const { return particles_; }
  [[nodiscard]] std::size_t states() const { return where_.size(); }
  [[nodiscard]] double time(std::size_t k) const;  ///< the state's first word only
  [[nodiscard]] StateData state(std::size_t k) const;
  [[nodiscard]] std::int64_t state_words() const { return state_words_; }

 private:
  struct Place {
    std::size_t file;
    std::int64_t word;
  };
  void read_static();
  void find_states();
  Control c_;
  std::vector<std::filesystem::path> files_;
  std::vector<std::string> bytes_;  ///< each member's contents
  std::vector<std::int64_t> node_ids_;
  std::vector<double> initial_;
  Elements solids_, beams_, shells_, particles_;
  std::int64_t static_end_ = 0;  ///< first word after the geometry file's static section
  std::int64_t state_words_ = 0;
  std::vector<Place> where_;
};

}  // namespace mcdyna::io::d3plot
