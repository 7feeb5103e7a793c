#pragma once
/// The files of a d3plot family as LS-DYNA lays them out: `d3plot` holds the control words, the
/// geometry, the user IDs and the titles; the states follow in `d3plot01`, `d3plot02`, ..., as
/// many to a file as fit in the family size (LS-DYNA's default 7 x 512 x 512 words), never a
/// state split over two. Every file ends with the end-of-file marker and zero words up to a
/// whole 512-word record, after every state: a file on disk is complete whenever the run stops.
/// The next state is written over that tail.
#include <cstdint>
#include <filesystem>
#include <string>

#include "io/checked_file.hpp"
#include "io/d3plot/d3plot_words.hpp"

namespace mcdyna::io::d3plot {

/// LS-DYNA's default family size (command line X = 7: 7 x 512 x 512 words).
inline constexpr std::int64_t kDefaultFamilyWords = 7 * 512 * 512;

/// Where a family stands: the file the states go to and its words of states (no tail), for a
/// restart dump.
struct FamilyPosition {
  int member = 0;           ///< 0: no state written yet
  std::int64_t words = 0;   ///< words of states in that member
  std::int64_t states = 0;  ///< states written in the whole family
};
template <class Ar>
void fields(Ar& ar, FamilyPosition& f) {  // its part of a restart dump (core/binary_archive.hpp)
  ar(f.member, f.words, f.states);
}

class Family {
 public:
  /// Starts a family in `dir` (`base`, `base`01, ...): writes the geometry file now.
  Family(std::filesystem::path dir, std::string base, const Words& geometry,
         std::int64_t family_words = kDefaultFamilyWords);
  /// Continues the family of a restart dump: the geometry file is there; states go on after
  /// `at`.
  Family(std::filesystem::path dir, std::string base, int word_bytes, const FamilyPosition& at,
         std::int64_t family_words = kDefaultFamilyWords);

  /// Appends one state (its words, without the end-of-file marker).
  void append(const Words& state);

  [[nodiscard]] const FamilyPosition& position() const { return at_; }
  /// The file of member `k` (0: the geometry file).
  [[nodiscard]] std::filesystem::path member(int k) const;

 private:
  /// The end-of-file marker and the zero words to the end of the record after `words` words.
  [[nodiscard]] Words tail(std::int64_t words) const;
  std::filesystem::path dir_;
  std::string base_;
  int word_bytes_;
  std::int64_t family_words_;
  FamilyPosition at_;
  RecordFile file_;  ///< the member the states go to
};

}  // namespace mcdyna::io::d3plot
