#include "io/d3plot/d3plot_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>

#include "io/d3plot/d3plot_words.hpp"

namespace mcdyna::io::d3plot {

namespace {

constexpr int kRigidMaterialType = 20;  // MAT_020: its shells have no state words

std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  if (!f) throw ReadError(fmt::format("cannot read {}", p.string()));
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// Words of one file.
class WordView {
 public:
  WordView(const std::string& bytes, int word_bytes) : b_(bytes), w_(word_bytes) {}
  [[nodiscard]] std::int64_t size() const { return static_cast<std::int64_t>(b_.size()) / w_; }
  [[nodiscard]] std::int64_t integer(std::int64_t k) const {
    check(k);
    if (w_ == 4) {
      std::int32_t v = 0;
      std::memcpy(&v, b_.data() + k * 4, 4);
      return v;
    }
    std::int64_t v = 0;
    std::memcpy(&v, b_.data() + k * 8, 8);
    return v;
  }
  [[nodiscard]] double real(std::int64_t k) const {
    check(k);
    if (w_ == 4) {
      float v = 0.0F;
      std::memcpy(&v, b_.data() + k * 4, 4);
      return v;
    }
    double v = 0.0;
    std::memcpy(&v, b_.data() + k * 8, 8);
    return v;
  }
  [[nodiscard]] std::string text(std::int64_t k, std::int64_t chars) const {
    check(k + (chars + w_ - 1) / w_ - 1);
    std::string s(b_.data() + k * w_, static_cast<std::size_t>(chars));
    s.erase(std::find(s.begin(), s.end(), '\0'), s.end());
    s.erase(s.find_last_not_of(' ') + 1);
    return s;
  }
  [[nodiscard]] bool end_marker(std::int64_t k) const {
    return k < size() && real(k) == kEndOfFile;
  }

 private:
  void check(std::int64_t k) const {
    if (k < 0 || k >= size())
      throw ReadError(fmt::format("word {} is past the end of the file ({} words)", k, size()));
  }
  const std::string& b_;
  int w_;
};

// 4-byte words unless NDIM (word 15) reads as nothing sensible that way.
int word_size(const std::string& bytes) {
  if (bytes.size() < 64 * 4) throw ReadError("shorter than the 64 control words");
  const WordView four(bytes, 4);
  const std::int64_t ndim = four.integer(15);
  if (ndim >= 2 && ndim <= 9) return 4;
  if (bytes.size() >= 64 * 8 && WordView(bytes, 8).integer(15) >= 2) return 8;
  throw ReadError(fmt::format("control word NDIM {} is no d3plot's", ndim));
}

}  // namespace

Reader::Reader(const std::filesystem::path& path) {
  const std::filesystem::path first = std::filesystem::is_directory(path) ? path / "d3plot" : path;
  files_.push_back(first);
  bytes_.push_back(slurp(first));
  // The members: the first file's name followed by a number (01, 02, ..., 100), in the order of
  // the numbers; a family may miss some.
  const std::string base = first.filename().string();
  std::vector<std::pair<long, std::filesystem::path>> members;
  const std::filesystem::path dir = first.has_parent_path() ? first.parent_path() : ".";
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.size() <= base.size() || name.rfind(base, 0) != 0) continue;
    const std::string number = name.substr(base.size());
    if (!std::all_of(number.begin(), number.end(), [](char ch) { return ch >= '0' && ch <= '9'; }))
      continue;
    members.emplace_back(std::stol(number), entry.path());
  }
  std::sort(members.begin(), members.end());
  for (const auto& [number, p] : members) {
    files_.push_back(p);
    bytes_.push_back(slurp(p));
  }
  try {
    c_.word_bytes = word_size(bytes_[0]);
    read_static();
    find_states();
  } catch (const ReadError& e) {
    throw ReadError(fmt::format("{}: {}", first.string(), e.what()));
  }
}

void Reader::read_static() {
  const WordView w(bytes_[0], c_.word_bytes);
  c_.title = w.text(0, 10 * c_.word_bytes);
  auto at = [&](int k) { return w.integer(k); };
  c_.ndim = at(15);
  c_.numnp = at(16);
  c_.nglbv = at(18);
  c_.it = at(19);
  c_.iu = at(20);
  c_.iv = at(21);
  c_.ia = at(22);
  c_.nel8 = at(23);
  c_.nv3d = at(27);
  c_.nel2 = at(28);
  c_.nv1d = at(30);
  c_.nel4 = at(31);
  c_.nv2d = at(33);
  c_.maxint = at(36);
  c_.nmsph = at(37);
  c_.narbs = at(39);
  c_.nelt = at(40);
  c_.nv3dt = at(42);
  c_.nmmat = at(51);
  c_.extra = at(57);
  if (c_.nel8 < 0) throw ReadError("10-node tetrahedra (NEL8 < 0) are not read");
  if (c_.it % 10 > 3 || c_.it / 10 > 1) throw ReadError(fmt::format("IT {} is not read", c_.it));
  if (at(48) != 0 || at(49) != 0) throw ReadError("CFD or multi-solver data are not read");
  if (at(54) != 0) throw ReadError("airbag particles (NPEFG) are not read");
  if (c_.ndim > 7) throw ReadError("rigid-body state data (NDIM 8, 9) are not read");
  if (c_.ndim == 6 || c_.ndim == 7) throw ReadError("rigid road surfaces are not read");
  if (at(56) != 0) throw ReadError(fmt::format("IDTDT {} data are not read", at(56)));
  std::int64_t p = 64 + c_.extra;
  // Material types (NDIM 5, 7): which parts are rigid.
  std::vector<std::int64_t> material_type;
  if (c_.ndim == 5 || c_.ndim == 7) {
    c_.numrbe = w.integer(p);
    const std::int64_t n = w.integer(p + 1);
    for (std::int64_t k = 0; k < n; ++k)
      material_type.push_back(w.integer(p + 2 + k));
    p += 2 + n;
  }
  p += at(47);  // IALEMAT fluid material IDs
  if (c_.nmsph > 0) {
    const std::int64_t flags = w.integer(p);
    c_.sph_words = 1;
    for (std::int64_t k = 1; k < flags; ++k) {
      c_.sph_flags.push_back(std::abs(w.integer(p + k)));
      c_.sph_words += c_.sph_flags.back();
    }
    p += flags;
  }
  // Geometry.
  for (std::int64_t k = 0; k < 3 * c_.numnp; ++k)
    initial_.push_back(w.real(p + k));
  p += 3 * c_.numnp;
  auto read_class = [&](Elements& e, std::int64_t count, int corners, int words) {
    e.corners = corners;
    for (std::int64_t k = 0; k < count; ++k) {
      for (int c = 0; c < corners; ++c)
        e.nodes.push_back(w.integer(p + c) - 1);
      e.parts.push_back(w.integer(p + words - 1));  // the part number, mapped to an ID below
      p += words;
    }
  };
  read_class(solids_, c_.nel8, 8, 9);
  Elements thick;
  read_class(thick, c_.nelt, 8, 9);
  read_class(beams_, c_.nel2, 2, 6);
  read_class(shells_, c_.nel4, 4, 5);
  // User IDs: nodes, solids, beams, shells, thick shells, then the parts (defined order).
  std::vector<std::int64_t> part_ids;
  if (c_.narbs > 0) {
    const std::int64_t section = p;
    const bool parts_listed = w.integer(p) < 0;
    p += parts_listed ? 16 : 10;
    for (std::int64_t k = 0; k < c_.numnp; ++k)
      node_ids_.push_back(w.integer(p + k));
    p += c_.numnp;
    for (std::int64_t k = 0; k < c_.nel8; ++k)
      solids_.ids.push_back(w.integer(p + k));
    p += c_.nel8;
    for (std::int64_t k = 0; k < c_.nel2; ++k)
      beams_.ids.push_back(w.integer(p + k));
    p += c_.nel2;
    for (std::int64_t k = 0; k < c_.nel4; ++k)
      shells_.ids.push_back(w.integer(p + k));
    p += c_.nel4 + c_.nelt;
    if (parts_listed)
      for (std::int64_t k = 0; k < c_.nmmat; ++k)
        part_ids.push_back(w.integer(p + k));
    p = section + c_.narbs;
  } else {
    for (std::int64_t k = 1; k <= c_.numnp; ++k)
      node_ids_.push_back(k);
    for (auto [e, n] : {std::pair{&solids_, c_.nel8}, {&beams_, c_.nel2}, {&shells_, c_.nel4}})
      for (std::int64_t k = 1; k <= n; ++k)
        e->ids.push_back(k);
  }
  // Part numbers to part IDs (the numbers themselves without the list); rigid shells.
  auto part_id = [&](std::int64_t number) {
    return number >= 1 && number <= static_cast<std::int64_t>(part_ids.size())
               ? part_ids[static_cast<std::size_t>(number - 1)]
               : number;
  };
  for (Elements* e : {&solids_, &beams_, &shells_}) {
    e->rigid.assign(e->count(), 0);
    for (std::size_t k = 0; k < e->count(); ++k) {
      const std::int64_t number = e->parts[k];
      if (e == &shells_ && number >= 1 &&
          number <= static_cast<std::int64_t>(material_type.size()) &&
          material_type[static_cast<std::size_t>(number - 1)] == kRigidMaterialType)
        e->rigid[k] = 1;
      e->parts[k] = part_id(number);
    }
  }
  // SPH node and material list.
  particles_.corners = 1;
  for (std::int64_t k = 0; k < c_.nmsph; ++k) {
    particles_.nodes.push_back(w.integer(p + 2 * k) - 1);
    particles_.parts.push_back(part_id(w.integer(p + 2 * k + 1)));
    particles_.ids.push_back(node_ids_[static_cast<std::size_t>(particles_.nodes.back())]);
  }
  p += 2 * c_.nmsph;
  // The end marker, then the titles (90000 title, 90001 parts, 90002 contacts, 90020 ICFD
  // parts), each followed by a marker or not.
  if (w.end_marker(p)) {
    ++p;
    for (;;) {
      if (p >= w.size()) break;
      const std::int64_t type = w.integer(p);
      if (type == 90000) {
        p += 1 + 72 / c_.word_bytes;
      } else if (type == 90001 || type == 90002 || type == 90020) {
        const std::int64_t n = w.integer(p + 1);
        p += 2 + n * (1 + 72 / c_.word_bytes);
      } else {
        break;
      }
      if (w.end_marker(p)) ++p;
    }
  }
  static_end_ = p;
  const std::int64_t rigid_shells = std::count(shells_.rigid.begin(), shells_.rigid.end(), 1);
  const std::int64_t deletion = c_.element_deletion() ? c_.nel8 + c_.nelt + c_.nel4 + c_.nel2
                                : c_.node_deletion()  ? c_.numnp
                                                      : 0;
  state_words_ = 1 + c_.nglbv + (3 * (c_.iu + c_.iv + c_.ia) + c_.thermal_words()) * c_.numnp +
                 c_.nel8 * c_.nv3d + c_.nelt * c_.nv3dt + c_.nel2 * c_.nv1d +
                 (c_.nel4 - rigid_shells) * c_.nv2d + deletion + c_.nmsph * c_.sph_words;
}

void Reader::find_states() {
  // In each file, from its first state word, the states that end at an end-of-file marker
  // (the geometry file's zero padding after its static section holds none).
  for (std::size_t f = 0; f < bytes_.size(); ++f) {
    const WordView w(bytes_[f], c_.word_bytes);
    const std::int64_t start = f == 0 ? static_end_ : 0;
    std::int64_t k = 0;
    while (start + (k + 1) * state_words_ <= w.size() && !w.end_marker(start + k * state_words_))
      ++k;
    if (!w.end_marker(start + k * state_words_)) {
      if (f == 0) continue;
      throw ReadError(
          fmt::format("{}: its states ({} words each) do not end at an end-of-file "
                      "marker",
                      files_[f].string(), state_words_));
    }
    for (std::int64_t j = 0; j < k; ++j)
      where_.push_back({f, start + j * state_words_});
  }
}

double Reader::time(std::size_t k) const {
  const Place at = where_.at(k);
  return WordView(bytes_[at.file], c_.word_bytes).real(at.word);
}

StateData Reader::state(std::size_t k) const {
  const Place at = where_.at(k);
  const WordView w(bytes_[at.file], c_.word_bytes);
  std::int64_t p = at.word;
  StateData s;
  auto take = [&](std::vector<double>& out, std::int64_t n) {
    out.resize(static_cast<std::size_t>(n));
    for (std::int64_t j = 0; j < n; ++j)
      out[static_cast<std::size_t>(j)] = w.real(p + j);
    p += n;
  };
  s.time = w.real(p);
  p += 1 + c_.nglbv;
  if (c_.iu) take(s.x, 3 * c_.numnp);
  p += c_.thermal_words() * c_.numnp;  // temperatures, heat flux, mass scaling: not compared
  if (c_.iv) take(s.v, 3 * c_.numnp);
  if (c_.ia) take(s.a, 3 * c_.numnp);
  take(s.solids, c_.nel8 * c_.nv3d);
  p += c_.nelt * c_.nv3dt;
  take(s.beams, c_.nel2 * c_.nv1d);
  const std::int64_t deformable =
      c_.nel4 - std::count(shells_.rigid.begin(), shells_.rigid.end(), 1);
  take(s.shells, deformable * c_.nv2d);
  auto flags = [&](std::vector<std::uint8_t>& out, std::int64_t n) {
    for (std::int64_t j = 0; j < n; ++j)
      out.push_back(w.real(p + j) == 0.0 ? 1 : 0);
    p += n;
  };
  if (c_.element_deletion()) {
    flags(s.solid_deleted, c_.nel8);
    p += c_.nelt;
    flags(s.shell_deleted, c_.nel4);
    flags(s.beam_deleted, c_.nel2);
  } else if (c_.node_deletion()) {
    p += c_.numnp;
  }
  take(s.particles, c_.nmsph * c_.sph_words);
  return s;
}

}  // namespace mcdyna::io::d3plot
