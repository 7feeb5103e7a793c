// LS-DYNA ASCII history files (the layouts of LSTC's l2a, keywords.md §3) into wide tables whose
// column names match our CSV files of the same kind (histories.cpp).
#include <fmt/format.h>

#include <cctype>
#include <map>
#include <optional>
#include <sstream>

#include "deck/numbers.hpp"
#include "deck/text_util.hpp"
#include "io/history_table.hpp"

namespace mcdyna::io::detail {

namespace {

bool contains(const std::string& line, const char* what) {
  return line.find(what) != std::string::npos;
}

std::vector<std::string> tokens(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string t; in >> t;)
    out.push_back(t);
  return out;
}

// Reads LS-DYNA numbers, including the E-less three-digit exponents of %E formats (1.2345-100).
class LineReader {
 public:
  LineReader(const std::string& source, const std::vector<std::string>& lines)
      : source_(source), lines_(lines) {}

  double number(std::size_t n, std::string_view text) const {
    const auto v = deck::parse_real(deck::trim(text));
    if (!v) fail(n, text, fmt::format("'{}' is not a number", deck::trim(text)));
    return *v;
  }
  /// The number that follows `label` on line n (e.g. "time =", "at time", "t=").
  double after(std::size_t n, const std::string& label) const {
    const std::string& line = lines_[n];
    const std::size_t at = line.find(label);
    if (at == std::string::npos) fail(n, line, fmt::format("'{}' not found", label));
    std::istringstream in(line.substr(at + label.size()));
    std::string t;
    in >> t;
    return number(n, t.empty() ? std::string_view(line).substr(at) : std::string_view(t));
  }
  /// `label=value` pairs of a line (labels are the word before each '=').
  std::vector<std::pair<std::string, double>> pairs(std::size_t n) const {
    const std::string& line = lines_[n];
    std::vector<std::pair<std::string, double>> out;
    std::size_t eq = line.find('=');
    while (eq != std::string::npos) {
      std::size_t end = eq;
      while (end > 0 && line[end - 1] == ' ')
        --end;
      std::size_t begin = end;
      while (begin > 0 && line[begin - 1] != ' ')
        --begin;
      std::size_t v = eq + 1;
      while (v < line.size() && line[v] == ' ')
        ++v;
      std::size_t v_end = v;
      while (v_end < line.size() && line[v_end] != ' ')
        ++v_end;
      out.emplace_back(line.substr(begin, end - begin),
                       number(n, std::string_view(line).substr(v, v_end - v)));
      eq = line.find('=', v_end);
    }
    return out;
  }
  [[noreturn]] void fail(std::size_t n, std::string_view text, const std::string& what) const {
    const std::string& line = lines_[n];
    const std::size_t at = text.empty() ? std::string::npos : line.find(text);
    throw HistoryReadError(
        located_message(source_, n + 1, line, at == std::string::npos ? 1 : at + 1, what));
  }
  const std::vector<std::string>& lines() const { return lines_; }

 private:
  const std::string& source_;
  const std::vector<std::string>& lines_;
};

// Lower-case with runs of other characters as one '_': "x-disp" -> x_disp.
std::string snake(std::string_view label) {
  std::string out;
  bool gap = false;
  for (const char c : label) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      if (gap && !out.empty()) out += '_';
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      gap = false;
    } else {
      gap = true;
    }
  }
  return out;
}

// glstat: "label.....value" lines; labels renamed to the columns of our glstat.csv.
HistoryTable read_glstat(const LineReader& r, const std::string& source) {
  static const std::map<std::string, std::string> renamed{
      {"sliding_interface_energy", "sliding_energy"},
      {"total_energy_initial_energy", "energy_ratio"},
      {"energy_ratio_w_o_eroded_energy", "energy_ratio_without_eroded"},
      {"global_x_velocity", "x_velocity"},
      {"global_y_velocity", "y_velocity"},
      {"global_z_velocity", "z_velocity"},
      {"percentage_increase", "percent_mass_increase"},
      {"time_per_zone_cycle_nanosec", "time_per_zone_cycle"}};
  WideTableBuilder b;
  double stonewall = 0.0;
  bool in_block = false;
  for (std::size_t n = 0; n < r.lines().size(); ++n) {
    const std::string& line = r.lines()[n];
    const std::size_t dots = line.find("..");
    if (dots == std::string::npos) continue;
    std::string name = snake(line.substr(0, dots));
    std::size_t v = line.find_first_not_of('.', dots);
    const std::vector<std::string> rest = tokens(v == std::string::npos ? "" : line.substr(v));
    if (rest.empty()) r.fail(n, line, "no value after the label");
    const double value = r.number(n, rest.front());
    if (name == "time") {
      b.new_row();
      stonewall = 0.0;
      in_block = true;
    }
    if (!in_block) r.fail(n, line, "a glstat value before the first 'time' line");
    if (const auto it = renamed.find(name); it != renamed.end()) name = it->second;
    if (name == "stonewall_energy") {  // one line per wall: glstat.csv has their sum
      stonewall += value;
      b.set(name, stonewall);
      if (rest.size() >= 2 && rest[1].rfind("wall#", 0) == 0) {
        const std::string wall = rest[1].size() > 5 ? rest[1].substr(5)
                                 : rest.size() > 2  ? rest[2]
                                                    : "";
        if (!wall.empty()) b.set("stonewall_energy@" + wall, value);
      }
      continue;
    }
    b.set(name, value);
  }
  return b.finish(source, "glstat");
}

// rcforc: "master|slave ID time t x fx y fy z fz mass m [mx Mx my My mz Mz]".
HistoryTable read_rcforc(const LineReader& r, const std::string& source) {
  static const std::map<std::string, std::string> renamed{
      {"x", "x_force"},   {"y", "y_force"},   {"z", "z_force"},  {"mass", "mass"},
      {"mx", "x_moment"}, {"my", "y_moment"}, {"mz", "z_moment"}};
  WideTableBuilder b;
  for (std::size_t n = 0; n < r.lines().size(); ++n) {
    const std::vector<std::string> t = tokens(r.lines()[n]);
    if (t.size() < 4 || (t[0] != "master" && t[0] != "slave") || t[2] != "time") continue;
    const double time = r.number(n, t[3]);
    b.row_at(time);
    const std::string key = "@" + t[1] + "/" + t[0];
    for (std::size_t k = 4; k + 1 < t.size(); k += 2) {
      const auto it = renamed.find(t[k]);
      const std::string name = it != renamed.end() ? it->second : snake(t[k]);
      b.set(name + key, r.number(n, t[k + 1]));
    }
  }
  return b.finish(source, "rcforc");
}

// nodout: blocks "n o d a l   p r i n t   o u t   f o r   t i m e  s t e p ... ( at time t )",
// a header, one row per node (translational block, or rotational with "x-rot" headers).
HistoryTable read_nodout(const LineReader& r, const std::string& source) {
  static const std::vector<std::string> translational{"x_disp", "y_disp", "z_disp", "x_vel",
                                                      "y_vel",  "z_vel",  "x_accl", "y_accl",
                                                      "z_accl", "x_coor", "y_coor", "z_coor"};
  static const std::vector<std::string> rotational{"x_rot",     "y_rot",     "z_rot",
                                                   "x_rot_vel", "y_rot_vel", "z_rot_vel",
                                                   "x_rot_acc", "y_rot_acc", "z_rot_acc"};
  WideTableBuilder b;
  const std::vector<std::string>* names = nullptr;
  for (std::size_t n = 0; n < r.lines().size(); ++n) {
    const std::string& line = r.lines()[n];
    if (contains(line, "n o d a l   p r i n t")) {
      const double time = r.after(n, "at time");
      b.row_at(time);
      names = nullptr;
      continue;
    }
    if (contains(line, "nodal point")) {
      names = contains(line, "x-rot") ? &rotational : &translational;
      continue;
    }
    const std::vector<std::string> t = tokens(line);
    if (names == nullptr || t.empty() || !std::isdigit(static_cast<unsigned char>(t[0][0])))
      continue;
    if (t.size() != names->size() + 1)
      r.fail(n, line,
             fmt::format("{} values after the node ID where nodout has {}", t.size() - 1,
                         names->size()));
    for (std::size_t k = 0; k < names->size(); ++k)
      b.set((*names)[k] + "@" + t[0], r.number(n, t[k + 1]));
  }
  return b.finish(source, "nodout");
}

// spcforc: "output at time =", "node= N local x,y,z forces = fx fy fz" (and moments), "force
// resultants = fx fy fz".
HistoryTable read_spcforc(const LineReader& r, const std::string& source) {
  WideTableBuilder b;
  for (std::size_t n = 0; n < r.lines().size(); ++n) {
    const std::string& line = r.lines()[n];
    if (contains(line, "output at time")) {
      const double time = r.after(n, "=");
      b.row_at(time);
      continue;
    }
    std::string key;
    std::string kind = "force";
    if (contains(line, "node=")) {
      key = fmt::format("{}", static_cast<long long>(r.after(n, "node=")));
      if (contains(line, "moments")) kind = "moment";
    } else if (contains(line, "force resultants")) {
      key = "resultant";
    } else {
      continue;
    }
    const std::size_t eq = line.rfind('=');
    const std::vector<std::string> v = tokens(line.substr(eq + 1));
    if (v.size() != 3) r.fail(n, line, "three components expected after '='");
    for (int c = 0; c < 3; ++c)
      b.set(fmt::format("{}_{}@{}", "xyz"[c], kind, key),
            r.number(n, v[static_cast<std::size_t>(c)]));
  }
  return b.finish(source, "spcforc");
}

// bndout: per time "... o u t p u t   t= t", sections of "nd#"/"mat#" lines with
// xforce/yforce/zforce/energy (and xmoment… lines for rigid bodies) and their totals.
HistoryTable read_bndout(const LineReader& r, const std::string& source) {
  WideTableBuilder b;
  std::string section = "velocity";
  std::string last_key;
  for (std::size_t n = 0; n < r.lines().size(); ++n) {
    const std::string& line = r.lines()[n];
    if (contains(line, "o u t p u t")) {
      const double time = r.after(n, "t=");
      b.row_at(time);
      continue;
    }
    if (contains(line, "discrete nodal")) section = "discrete";
    if (contains(line, "pressure boundary")) section = "pressure";
    if (contains(line, "velocity boundary")) section = "velocity";
    const std::string prefix = section == "velocity" ? "" : section + "_";
    const std::vector<std::string> t = tokens(line);
    if (t.empty()) continue;
    std::string key;
    if (t[0].rfind("nd#", 0) == 0 || t[0].rfind("mat#", 0) == 0) {
      const bool node = t[0][0] == 'n';
      const std::string id = t[0].size() > (node ? 3u : 4u) ? t[0].substr(node ? 3 : 4) : t[1];
      key = prefix + (node ? "node/" : "rigid_part/") + id;
      last_key = key;
    } else if (t[0].rfind("xtotal", 0) == 0) {
      key = section + "_total";
    } else if (t[0].rfind("xmoment", 0) == 0) {
      key = last_key;
    } else {
      continue;
    }
    for (const auto& [label, value] : r.pairs(n)) {
      std::string name;
      if (label == "energy" || label == "etotal")
        name = "energy";
      else if (label.size() > 1 && (label.substr(1) == "force" || label.substr(1) == "total"))
        name = label.substr(0, 1) + "_force";
      else if (label.size() > 1 && label.substr(1) == "moment")
        name = label.substr(0, 1) + "_moment";
      else
        continue;  // the entity number itself ("nd#=" forms)
      b.set(name + "@" + key, value);
    }
  }
  return b.finish(source, "bndout");
}

// matsum: "time =", then per part "mat.#= ID inten= kinen= …", "x-mom= …", "x-rbv= …",
// "hgeng= … +mass= …".
HistoryTable read_matsum(const LineReader& r, const std::string& source) {
  static const std::map<std::string, std::string> renamed{{"inten", "internal_energy"},
                                                          {"kinen", "kinetic_energy"},
                                                          {"eroded_ie", "eroded_internal_energy"},
                                                          {"eroded_ke", "eroded_kinetic_energy"},
                                                          {"x-mom", "x_momentum"},
                                                          {"y-mom", "y_momentum"},
                                                          {"z-mom", "z_momentum"},
                                                          {"x-rbv", "x_rigid_velocity"},
                                                          {"y-rbv", "y_rigid_velocity"},
                                                          {"z-rbv", "z_rigid_velocity"},
                                                          {"hgeng", "hourglass_energy"},
                                                          {"+mass", "added_mass"}};
  WideTableBuilder b;
  std::string part;
  for (std::size_t n = 0; n < r.lines().size(); ++n) {
    const std::string& line = r.lines()[n];
    const std::string trimmed(deck::trim(line));
    if (trimmed.rfind("time =", 0) == 0 || trimmed.rfind("time=", 0) == 0) {
      const double time = r.after(n, "=");
      b.row_at(time);
      continue;
    }
    if (trimmed.find('=') == std::string::npos || trimmed.rfind("Maximum", 0) == 0) continue;
    for (const auto& [label, value] : r.pairs(n)) {
      if (label == "mat.#") {
        part = fmt::format("{}", static_cast<long long>(value));
        continue;
      }
      if (part.empty()) r.fail(n, line, "a matsum value before the first 'mat.#=' line");
      const auto it = renamed.find(label);
      b.set((it != renamed.end() ? it->second : snake(label)) + "@" + part, value);
    }
  }
  return b.finish(source, "matsum");
}

// rwforc (as histories.cpp writes it): "time wall# normal-force x-force y-force z-force" rows.
HistoryTable read_rwforc(const LineReader& r, const std::string& source) {
  WideTableBuilder b;
  for (std::size_t n = 0; n < r.lines().size(); ++n) {
    const std::vector<std::string> t = tokens(r.lines()[n]);
    if (t.size() != 6 || !deck::parse_real(t[0])) continue;
    const double time = r.number(n, t[0]);
    b.row_at(time);
    const std::string key = "@" + t[1];
    b.set("normal_force" + key, r.number(n, t[2]));
    b.set("x_force" + key, r.number(n, t[3]));
    b.set("y_force" + key, r.number(n, t[4]));
    b.set("z_force" + key, r.number(n, t[5]));
  }
  return b.finish(source, "rwforc");
}

}  // namespace

std::string detect_lsdyna_ascii(const std::vector<std::string>& lines) {
  const std::size_t scan = std::min<std::size_t>(lines.size(), 400);
  for (std::size_t n = 0; n < scan; ++n) {
    const std::string& l = lines[n];
    if (contains(l, "n o d a l   p r i n t")) return "nodout";
    if (contains(l, "r e s u l t a n t   i n t e r f a c e")) return "rcforc";
    if (contains(l, "single point constraint forces")) return "spcforc";
    if (contains(l, "n o d a l   f o r c e/e n e r g y")) return "bndout";
    if (contains(l, "r i g i d   w a l l   f o r c e s")) return "rwforc";
    if (contains(l, "mat.#=")) return "matsum";
    if (contains(l, "dt of cycle") || contains(l, "kinetic energy....")) return "glstat";
    const std::vector<std::string> t = tokens(l);
    if (t.size() >= 4 && (t[0] == "master" || t[0] == "slave") && t[2] == "time") return "rcforc";
  }
  return "";
}

HistoryTable read_lsdyna_ascii(const std::string& format, const std::vector<std::string>& lines,
                               const std::string& source) {
  const LineReader r(source, lines);
  HistoryTable t;
  if (format == "glstat") t = read_glstat(r, source);
  if (format == "rcforc") t = read_rcforc(r, source);
  if (format == "nodout") t = read_nodout(r, source);
  if (format == "spcforc") t = read_spcforc(r, source);
  if (format == "bndout") t = read_bndout(r, source);
  if (format == "matsum") t = read_matsum(r, source);
  if (format == "rwforc") t = read_rwforc(r, source);
  if (t.rows() == 0)
    throw HistoryReadError(fmt::format(
        "{}: error: looks like an LS-DYNA {} file but holds no output time", source, format));
  return t;
}

}  // namespace mcdyna::io::detail
