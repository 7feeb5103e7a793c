#include "post/history_compare.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcdyna::post {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool is_index(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::string describe(const io::HistoryTable& t) {
  return fmt::format("{} ({}, {} columns, {} rows)", t.source, t.format, t.names.size(), t.rows());
}

// Columns of `t` that `spec` names: a 1-based index, an exact name, or a quantity whose keyed
// columns (`spec@…`) are all meant.
std::vector<std::string> resolve(const io::HistoryTable& t, const std::string& spec) {
  if (is_index(spec)) {
    const auto k = std::stoul(spec);
    if (k < 1 || k > t.names.size())
      throw CompareError(fmt::format("column {} does not exist in {}: it has {} columns", spec,
                                     t.source, t.names.size()));
    return {t.names[k - 1]};
  }
  if (t.find(spec) >= 0) return {spec};
  std::vector<std::string> keyed;
  for (const std::string& n : t.names)
    if (n.rfind(spec + "@", 0) == 0) keyed.push_back(n);
  if (keyed.empty()) {
    std::string known;
    for (std::size_t k = 0; k < t.names.size() && k < 12; ++k)
      known += (k ? ", " : "") + t.names[k];
    if (t.names.size() > 12) known += ", …";
    throw CompareError(
        fmt::format("no column '{}' in {}; its columns are: {}", spec, describe(t), known));
  }
  return keyed;
}

std::string single(const io::HistoryTable& t, const std::string& spec) {
  const std::vector<std::string> r = resolve(t, spec);
  if (r.size() != 1)
    throw CompareError(fmt::format("'{}' names {} columns of {} ({}, …); give one", spec, r.size(),
                                   t.source, r.front()));
  return r.front();
}

std::vector<std::pair<std::string, std::string>> chosen_pairs(const io::HistoryTable& a,
                                                              const io::HistoryTable& b,
                                                              const CompareOptions& o,
                                                              const std::string& xa,
                                                              const std::string& xb) {
  std::vector<std::pair<std::string, std::string>> pairs;
  if (o.columns.empty()) {
    for (const std::string& n : a.names)
      if (n != xa && n != xb && b.find(n) >= 0) pairs.emplace_back(n, n);
    if (pairs.empty())
      throw CompareError(fmt::format(
          "{} and {} share no column name besides the alignment column; choose columns with "
          "-c NAME or -c A_NAME:B_NAME",
          a.source, b.source));
    return pairs;
  }
  for (const std::string& spec : o.columns) {
    const std::size_t colon = spec.find(':');
    if (colon != std::string::npos) {
      pairs.emplace_back(single(a, spec.substr(0, colon)), single(b, spec.substr(colon + 1)));
      continue;
    }
    if (is_index(spec)) {
      pairs.emplace_back(single(a, spec), single(b, spec));
      continue;
    }
    const std::vector<std::string> in_a = resolve(a, spec);
    bool any = false;
    for (const std::string& n : in_a)
      if (b.find(n) >= 0) {
        pairs.emplace_back(n, n);
        any = true;
      }
    if (!any) resolve(b, spec);  // says what B has instead
    if (!any) throw CompareError(fmt::format("'{}' matches no column present in both files", spec));
  }
  return pairs;
}

// The rows of `t` ordered by x ascending (x must be monotonic; equal x keep the last row).
std::vector<std::size_t> ordered_rows(const io::HistoryTable& t, int x_col) {
  const std::vector<double>& x = t.columns[static_cast<std::size_t>(x_col)];
  std::vector<std::size_t> rows;
  for (std::size_t r = 0; r < x.size(); ++r)
    if (std::isfinite(x[r])) rows.push_back(r);
  if (rows.size() < 2)
    throw CompareError(fmt::format("column '{}' of {} has fewer than two values",
                                   t.names[static_cast<std::size_t>(x_col)], t.source));
  const bool descending = x[rows.back()] < x[rows.front()];
  if (descending) std::reverse(rows.begin(), rows.end());
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (!out.empty() && x[rows[k]] < x[out.back()])
      throw CompareError(fmt::format(
          "column '{}' of {} is not monotonic (row {}: {:.6g} after {:.6g}); align on a "
          "monotonic column with --x",
          t.names[static_cast<std::size_t>(x_col)], t.source, rows[k] + 1, x[rows[k]],
          x[out.back()]));
    if (!out.empty() && x[rows[k]] == x[out.back()])
      out.back() = rows[k];
    else
      out.push_back(rows[k]);
  }
  return out;
}

struct Samples {
  std::vector<double> x, y;
};

Samples samples(const io::HistoryTable& t, const std::vector<std::size_t>& rows, int x_col,
                const std::string& name) {
  const std::vector<double>& x = t.columns[static_cast<std::size_t>(x_col)];
  const std::vector<double>& y = t.columns[static_cast<std::size_t>(t.find(name))];
  Samples s;
  for (const std::size_t r : rows)
    if (std::isfinite(y[r])) {
      s.x.push_back(x[r]);
      s.y.push_back(y[r]);
    }
  if (s.x.empty())
    throw CompareError(fmt::format("column '{}' of {} has no values", name, t.source));
  return s;
}

std::size_t count_in(const io::HistoryTable& t, const std::vector<std::size_t>& rows, int x_col,
                     double lo, double hi) {
  const std::vector<double>& x = t.columns[static_cast<std::size_t>(x_col)];
  return static_cast<std::size_t>(std::count_if(
      rows.begin(), rows.end(), [&](std::size_t r) { return x[r] >= lo && x[r] <= hi; }));
}

void measure(const std::vector<double>& x, ColumnComparison& c) {
  const std::size_t n = x.size();
  double sum_sq = 0.0, peak_a = -1.0, peak_b = -1.0;
  double mean_a = 0.0, mean_b = 0.0;
  c.max_difference = -1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = std::abs(c.a[i] - c.b[i]);
    sum_sq += d * d;
    if (d > c.max_difference) {
      c.max_difference = d;
      c.x_at_max = x[i];
    }
    if (std::abs(c.a[i]) > peak_a) {
      peak_a = std::abs(c.a[i]);
      c.peak_a = c.a[i];
      c.x_peak_a = x[i];
    }
    if (std::abs(c.b[i]) > peak_b) {
      peak_b = std::abs(c.b[i]);
      c.peak_b = c.b[i];
      c.x_peak_b = x[i];
    }
    mean_a += c.a[i];
    mean_b += c.b[i];
  }
  mean_a /= static_cast<double>(n);
  mean_b /= static_cast<double>(n);
  c.rms_difference = std::sqrt(sum_sq / static_cast<double>(n));
  c.relative_to_peak =
      peak_b > 0.0 ? c.max_difference / peak_b : (c.max_difference > 0.0 ? kNaN : 0.0);
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sab += (c.a[i] - mean_a) * (c.b[i] - mean_b);
    saa += (c.a[i] - mean_a) * (c.a[i] - mean_a);
    sbb += (c.b[i] - mean_b) * (c.b[i] - mean_b);
  }
  c.correlation = saa > 0.0 && sbb > 0.0 ? sab / std::sqrt(saa * sbb) : kNaN;
}

}  // namespace

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (x.size() == 1 || at <= x.front()) return y.front();
  if (at >= x.back()) return y.back();
  const auto hi = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin());
  const std::size_t lo = hi - 1;
  const double w = (at - x[lo]) / (x[hi] - x[lo]);
  return (1.0 - w) * y[lo] + w * y[hi];
}

Comparison compare_histories(const io::HistoryTable& a, const io::HistoryTable& b,
                             const CompareOptions& o) {
  Comparison out;
  out.x_name_a = single(a, o.x_a);
  out.x_name_b = single(b, o.x_b.empty() ? o.x_a : o.x_b);
  const int xa = a.find(out.x_name_a), xb = b.find(out.x_name_b);
  const auto pairs = chosen_pairs(a, b, o, out.x_name_a, out.x_name_b);
  const std::vector<std::size_t> rows_a = ordered_rows(a, xa), rows_b = ordered_rows(b, xb);
  const std::vector<double>& ax = a.columns[static_cast<std::size_t>(xa)];
  const std::vector<double>& bx = b.columns[static_cast<std::size_t>(xb)];
  const double lo = std::max({ax[rows_a.front()], bx[rows_b.front()], o.from});
  const double hi = std::min({ax[rows_a.back()], bx[rows_b.back()], o.to});
  if (!(hi > lo))
    throw CompareError(fmt::format(
        "no common range: {} spans {:.6g} … {:.6g} in {}, {} spans {:.6g} … {:.6g} in {}{}",
        out.x_name_a, ax[rows_a.front()], ax[rows_a.back()], a.source, out.x_name_b,
        bx[rows_b.front()], bx[rows_b.back()], b.source,
        o.from > -1e300 || o.to < 1e300 ? fmt::format(" (window {:.6g} … {:.6g})", o.from, o.to)
                                        : ""));
  const std::size_t n = o.points > 1 ? o.points
                                     : std::max<std::size_t>({2, count_in(a, rows_a, xa, lo, hi),
                                                              count_in(b, rows_b, xb, lo, hi)});
  out.x.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    out.x[i] =
        i + 1 == n ? hi : lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(n - 1);

  for (const auto& [name_a, name_b] : pairs) {
    ColumnComparison c;
    c.name_a = name_a;
    c.name_b = name_b;
    const Samples sa = samples(a, rows_a, xa, name_a), sb = samples(b, rows_b, xb, name_b);
    c.a.resize(n);
    c.b.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      c.a[i] = interpolate(sa.x, sa.y, out.x[i]);
      c.b[i] = interpolate(sb.x, sb.y, out.x[i]);
    }
    measure(out.x, c);
    out.columns.push_back(std::move(c));
  }
  return out;
}

}  // namespace mcdyna::post
