#include "cli/compare_command.hpp"

#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "io/checked_file.hpp"
#include "io/d3plot/d3plot_reader.hpp"
#include "io/history_table.hpp"
#include "post/difference_series.hpp"
#include "post/state_compare.hpp"

extern char** environ;

namespace mcdyna::cli {

namespace {

constexpr int kOutsideTolerance = 1;
constexpr int kCannotCompare = 2;

std::string label(const post::ColumnComparison& c) {
  return c.name_a == c.name_b ? c.name_a : c.name_a + " vs " + c.name_b;
}

std::string number(double v) {
  return std::isnan(v) ? "n/a" : fmt::format("{:.4e}", v);
}

void print_report(const io::HistoryTable& a, const io::HistoryTable& b, const post::Comparison& r,
                  std::ostream& out) {
  out << fmt::format("A  {} ({}, {} columns, {} rows)\n", a.source, a.format, a.names.size(),
                     a.rows());
  out << fmt::format("B  {} ({}, {} columns, {} rows) - the reference\n", b.source, b.format,
                     b.names.size(), b.rows());
  const std::string x = r.x_name_a == r.x_name_b ? r.x_name_a : r.x_name_a + " / " + r.x_name_b;
  out << fmt::format("aligned on {}: {:.6g} … {:.6g}, {} points, linear resampling\n\n", x,
                     r.x.front(), r.x.back(), r.x.size());
  std::size_t width = 6;
  for (const post::ColumnComparison& c : r.columns)
    width = std::max(width, label(c).size());
  const std::string at = fmt::format("at {}", r.x_name_a);
  out << fmt::format(
      "{:<{}}  {:>11}  {:>11}  {:>11}  {:>10}  {:>11}  {:>11}  {:>11}  {:>11}  {:>7}\n", "column",
      width, "max|A-B|", at, "RMS(A-B)", "max/peakB", "peak A", at, "peak B", at, "corr");
  for (const post::ColumnComparison& c : r.columns)
    out << fmt::format(
        "{:<{}}  {:>11}  {:>11.4e}  {:>11}  {:>10}  {:>11}  {:>11.4e}  {:>11}  {:>11.4e}  {:>7}\n",
        label(c), width, number(c.max_difference), c.x_at_max, number(c.rms_difference),
        std::isnan(c.relative_to_peak) ? "n/a" : fmt::format("{:.4g}", c.relative_to_peak),
        number(c.peak_a), c.x_peak_a, number(c.peak_b), c.x_peak_b,
        std::isnan(c.correlation) ? "n/a" : fmt::format("{:.4f}", c.correlation));
}

bool write_resampled(const post::Comparison& r, const std::filesystem::path& path) {
  std::ofstream f(path);
  if (!f) return false;
  f << r.x_name_a;
  for (const post::ColumnComparison& c : r.columns)
    f << ",A " << c.name_a << ",B " << c.name_b;
  f << "\n";
  for (std::size_t i = 0; i < r.x.size(); ++i) {
    f << fmt::format("{:.9e}", r.x[i]);
    for (const post::ColumnComparison& c : r.columns)
      f << fmt::format(",{:.9e},{:.9e}", c.a[i], c.b[i]);
    f << "\n";
  }
  return static_cast<bool>(f);
}

// The plot is drawn by tools/plot_compare.py with Debian's python3-matplotlib.
std::filesystem::path plot_script() {
  if (const char* dir = std::getenv("MCDYNA_TOOLS"))
    return std::filesystem::path(dir) / "plot_compare.py";
  return std::filesystem::path(MCDYNA_TOOLS_DIR) / "plot_compare.py";
}

std::string python() {
  if (const char* p = std::getenv("MCDYNA_PYTHON")) return p;
  return std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

int run_program(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args)
    argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool draw_plot(const post::Comparison& r, const CompareCommandOptions& o, std::ostream& err) {
  const std::filesystem::path data =
      o.csv.empty() ? std::filesystem::path(o.plot).replace_extension(".csv") : o.csv;
  if (o.csv.empty() && !write_resampled(r, data)) {
    err << fmt::format("mcdyna compare: cannot write {}\n", data.string());
    return false;
  }
  const std::filesystem::path script = plot_script();
  if (!std::filesystem::exists(script)) {
    err << fmt::format("mcdyna compare: the plot helper {} is missing\n", script.string());
    return false;
  }
  const int rc = run_program(
      {python(), script.string(), data.string(), o.plot.string(), o.a.string(), o.b.string()});
  if (rc != 0) {
    err << fmt::format(
        "mcdyna compare: the plot helper failed (exit {}); it needs python3-matplotlib "
        "(tools/setup.sh installs it); resampled data in {}\n",
        rc, data.string());
    return false;
  }
  return true;
}

// A d3plot family: a folder holding `d3plot`, or a file named d3plot (its members d3plot01..).
bool is_d3plot(const std::filesystem::path& p) {
  if (std::filesystem::is_directory(p)) return std::filesystem::exists(p / "d3plot");
  const std::string name = p.filename().string();
  return name.rfind("d3plot", 0) == 0 && !p.has_extension();
}

std::string family_line(const std::filesystem::path& p, const io::d3plot::Reader& r) {
  return fmt::format(
      "{} (d3plot, {}-byte words, {} states, {} nodes, {} solids, {} shells, {} "
      "beams, {} particles)",
      p.string(), r.control().word_bytes, r.states(), r.node_ids().size(), r.solids().count(),
      r.shells().count(), r.beams().count(), r.particles().count());
}

// `mcdyna compare A/d3plot B/d3plot`: the states at matching times, per part and field.
int compare_d3plot(const CompareCommandOptions& o, std::ostream& out, std::ostream& err) {
  const io::d3plot::Reader a(o.a), b(o.b);
  std::optional<post::DifferenceSeries> series;
  if (!o.difference_series.empty()) series.emplace(o.difference_series, b);
  const post::StateComparison r = post::compare_states(a, b, -1.0, series ? &*series : nullptr);
  out << "A  " << family_line(o.a, a) << "\n";
  out << "B  " << family_line(o.b, b) << " - the reference\n";
  if (r.matched.empty()) {
    err << "mcdyna compare: no state of A has a state of B at its time\n";
    return kCannotCompare;
  }
  out << fmt::format(
      "matched {} of {} states by time ({:.6g} … {:.6g}, A's times at most {:.3g} from B's); by "
      "user ID {} nodes and {} elements, {} only in A, {} only in B\n\n",
      r.matched.size(), r.states_a, r.matched.front().second, r.matched.back().second,
      r.largest_offset, r.nodes, r.elements, r.only_a, r.only_b);
  out << fmt::format("{:>10}  {:<15}  {:>11}  {:>11}  {:>11}  {:>11}  {:>10}\n", "part", "field",
                     "max|A-B|", "at time", "RMS(A-B)", "peak|B|", "max/peakB");
  std::vector<std::string> outside;
  for (const post::StateFieldDifference& d : r.rows) {
    out << fmt::format("{:>10}  {:<15}  {:>11.4e}  {:>11.4e}  {:>11.4e}  {:>11.4e}  {:>10.4g}\n",
                       d.part, d.field, d.max, d.time_at_max, d.rms, d.peak_b, d.relative());
    if (o.tolerance && !(d.relative() <= *o.tolerance))
      outside.push_back(fmt::format("part {} {} ({:.4g})", d.part, d.field, d.relative()));
  }
  if (series)
    out << fmt::format("\ndifference series: {} ({} states)\n", series->collection().string(),
                       series->states());
  if (!o.tolerance) return 0;
  if (outside.empty()) {
    out << fmt::format("\nwithin tolerance: every part's max|A-B| / peak|B| <= {:g}\n",
                       *o.tolerance);
    return 0;
  }
  out << fmt::format("\nOUTSIDE tolerance {:g} in {} of {} rows:", *o.tolerance, outside.size(),
                     r.rows.size());
  for (const std::string& s : outside)
    out << "\n  " << s;
  out << "\n";
  return kOutsideTolerance;
}

}  // namespace

int run_compare(const CompareCommandOptions& o, std::ostream& out, std::ostream& err) {
  if (is_d3plot(o.a) || is_d3plot(o.b)) {
    if (!is_d3plot(o.a) || !is_d3plot(o.b)) {
      err << "mcdyna compare: a d3plot family compares with a d3plot family only\n";
      return kCannotCompare;
    }
    try {
      return compare_d3plot(o, out, err);
    } catch (const io::d3plot::ReadError& e) {
      err << "mcdyna compare: " << e.what() << "\n";
    } catch (const io::WriteError& e) {
      err << "mcdyna compare: " << e.what() << "\n";
    } catch (const std::filesystem::filesystem_error& e) {
      err << "mcdyna compare: " << e.what() << "\n";
    }
    return kCannotCompare;
  }
  if (!o.difference_series.empty()) {
    err << "mcdyna compare: --diff-series is for two d3plot families\n";
    return kCannotCompare;
  }
  try {
    const io::HistoryTable a = io::read_history(o.a);
    const io::HistoryTable b = io::read_history(o.b);
    const post::Comparison r = post::compare_histories(a, b, o.compare);
    print_report(a, b, r, out);
    if (!o.csv.empty() && !write_resampled(r, o.csv)) {
      err << fmt::format("mcdyna compare: cannot write {}\n", o.csv.string());
      return kCannotCompare;
    }
    if (!o.plot.empty()) {
      if (!draw_plot(r, o, err)) return kCannotCompare;
      out << fmt::format("\nplot: {}\n", o.plot.string());
    }
    if (!o.tolerance) return 0;
    std::vector<std::string> outside;
    for (const post::ColumnComparison& c : r.columns)
      if (!(c.relative_to_peak <= *o.tolerance))
        outside.push_back(fmt::format("{} ({})", label(c),
                                      std::isnan(c.relative_to_peak)
                                          ? "reference is zero"
                                          : fmt::format("{:.4f}", c.relative_to_peak)));
    if (outside.empty()) {
      out << fmt::format("\nwithin tolerance: every column's max|A-B| / peak|B| <= {:g}\n",
                         *o.tolerance);
      return 0;
    }
    out << fmt::format("\nOUTSIDE tolerance {:g} in {} of {} columns:", *o.tolerance,
                       outside.size(), r.columns.size());
    for (const std::string& s : outside)
      out << "\n  " << s;
    out << "\n";
    return kOutsideTolerance;
  } catch (const io::HistoryReadError& e) {
    err << e.what() << "\n";
  } catch (const post::CompareError& e) {
    err << "mcdyna compare: " << e.what() << "\n";
  }
  return kCannotCompare;
}

}  // namespace mcdyna::cli
