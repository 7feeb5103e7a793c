#include "io/d3plot/d3plot_family.hpp"

#include <fmt/format.h>

#include <utility>

namespace mcdyna::io::d3plot {

Family::Family(std::filesystem::path dir, std::string base, const Words& geometry,
               std::int64_t family_words)
    : dir_(std::move(dir)),
      base_(std::move(base)),
      word_bytes_(geometry.word_bytes()),
      family_words_(family_words) {
  Words file = geometry;
  file.pad_to_record();
  write_file_atomically(member(0), file.bytes());
}

Family::Family(std::filesystem::path dir, std::string base, int word_bytes,
               const FamilyPosition& at, std::int64_t family_words)
    : dir_(std::move(dir)),
      base_(std::move(base)),
      word_bytes_(word_bytes),
      family_words_(family_words),
      at_(at) {
  // The member as it stood at the dump, its tail included: the next state is written over the
  // tail, or goes to a new member and leaves this one closed.
  if (at_.member > 0)
    file_ = RecordFile::continue_at(
        member(at_.member),
        static_cast<std::uint64_t>((at_.words + tail(at_.words).size()) * word_bytes_));
}

std::filesystem::path Family::member(int k) const {
  return dir_ / (k == 0 ? base_ : fmt::format("{}{:02d}", base_, k));
}

Words Family::tail(std::int64_t words) const {
  Words t(word_bytes_);
  t.real(kEndOfFile);
  const std::int64_t used = words + 1;
  const std::int64_t rest = (kRecordWords - used % kRecordWords) % kRecordWords;
  for (std::int64_t k = 0; k < rest; ++k)
    t.integer(0);
  return t;
}

void Family::append(const Words& state) {
  // A new member when there is none yet, or when this state would take the current one past
  // the family size (a member holds at least one state, however large).
  if (at_.member == 0 || (at_.words > 0 && at_.words + state.size() + 1 > family_words_)) {
    ++at_.member;
    at_.words = 0;
    file_ = RecordFile::create(member(at_.member));
  } else {
    file_.cut_back(static_cast<std::uint64_t>(at_.words * word_bytes_));
  }
  const std::int64_t words = at_.words + state.size();
  file_.pending() = state.bytes() + tail(words).bytes();
  file_.commit();
  at_.words = words;
  ++at_.states;
}

}  // namespace mcdyna::io::d3plot
