// `mcdyna compare`: the history readers (CSV pivoting, LS-DYNA ASCII layouts of keywords.md §3)
// and the comparison figures on series with known answers.
#include <cmath>
#include <functional>
#include <sstream>

#include "io/history_table.hpp"
#include "post/history_compare.hpp"
#include "test_support.hpp"

namespace mcdyna::test {

namespace {

// A CSV of x in [0, 1] at n points with columns y_k = f_k(x).
std::string csv_of(const std::string& header, std::size_t n,
                   const std::function<std::string(double)>& row) {
  std::string s = header + "\n";
  for (std::size_t i = 0; i < n; ++i)
    s += row(static_cast<double>(i) / static_cast<double>(n - 1)) + "\n";
  return s;
}

double value(const io::HistoryTable& t, const std::string& name, std::size_t row) {
  const int k = t.find(name);
  REQUIRE_MESSAGE(k >= 0, "no column " << name);
  return t.columns[static_cast<std::size_t>(k)][row];
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("compare: a linear drift between differently sampled series gives the exact figures") {
  // B = 2x + 1 at 51 points, A = 2.2x + 1 at 101: linear interpolation is exact, A - B = 0.2 x.
  const auto b = io::read_history_text(
      csv_of("time,force", 51, [](double x) { return fmt::format("{},{}", x, 2.0 * x + 1.0); }),
      "b.csv");
  const auto a = io::read_history_text(
      csv_of("time,force", 101, [](double x) { return fmt::format("{},{}", x, 2.2 * x + 1.0); }),
      "a.csv");
  const post::Comparison r = post::compare_histories(a, b, {});
  REQUIRE(r.columns.size() == 1);
  REQUIRE(r.x.size() == 101);  // the denser file's count
  const post::ColumnComparison& c = r.columns[0];
  CHECK(c.max_difference == doctest::Approx(0.2).scale(0.0).epsilon(1e-12));
  CHECK(c.x_at_max == 1.0);
  double sum = 0.0;
  for (std::size_t i = 0; i <= 100; ++i)
    sum += std::pow(0.2 * static_cast<double>(i) / 100.0, 2);
  CHECK(c.rms_difference == doctest::Approx(std::sqrt(sum / 101.0)).scale(0.0).epsilon(1e-12));
  CHECK(c.relative_to_peak == doctest::Approx(0.2 / 3.0).scale(0.0).epsilon(1e-12));
  CHECK(c.peak_a == doctest::Approx(3.2).scale(0.0).epsilon(1e-12));
  CHECK(c.peak_b == doctest::Approx(3.0).scale(0.0).epsilon(1e-12));
  CHECK(c.x_peak_b == 1.0);
  CHECK(c.correlation == doctest::Approx(1.0).scale(0.0).epsilon(1e-12));
}

TEST_CASE("compare: peaks keep their sign, an inverted curve correlates -1, ranges overlap") {
  // B = -sin(pi x) on [0, 1]; A = sin(pi x) on [0.5, 2]: compared on [0.5, 1] only.
  const auto b = io::read_history_text(
      csv_of("t,f", 201, [](double x) { return fmt::format("{},{}", x, -std::sin(M_PI * x)); }),
      "b.csv");
  const auto a =
      io::read_history_text(csv_of("t,f", 301,
                                   [](double x) {
                                     const double t = 0.5 + 1.5 * x;
                                     return fmt::format("{:.17g},{:.17g}", t, std::sin(M_PI * t));
                                   }),
                            "a.csv");
  post::CompareOptions o;
  o.x_a = "t";
  o.points = 51;
  const post::Comparison r = post::compare_histories(a, b, o);
  REQUIRE(r.x.size() == 51);
  CHECK(r.x.front() == 0.5);
  CHECK(r.x.back() == 1.0);
  const post::ColumnComparison& c = r.columns[0];
  CHECK(c.peak_b == doctest::Approx(-1.0).scale(0.0).epsilon(1e-12));  // at x = 0.5
  CHECK(c.x_peak_b == 0.5);
  CHECK(c.max_difference == doctest::Approx(2.0).scale(0.0).epsilon(1e-4));
  CHECK(c.correlation == doctest::Approx(-1.0).scale(0.0).epsilon(1e-6));
}

TEST_CASE("compare: aligned on another column, named differently in each file") {
  // Two runs of a plunge at different speeds: force against plunge is the same curve.
  const auto a = io::read_history_text(
      csv_of("time,plunge,force", 41,
             [](double x) { return fmt::format("{},{},{}", x, 2.0 * x, 100.0 * 2.0 * x); }),
      "fast.csv");
  const auto b = io::read_history_text(
      csv_of("t,depth_mm,thrust", 81,
             [](double x) { return fmt::format("{},{},{}", 10.0 * x, 2.0 * x, 200.0 * x); }),
      "slow.csv");
  post::CompareOptions o;
  o.x_a = "plunge";
  o.x_b = "depth_mm";
  o.columns = {"force:thrust"};
  const post::Comparison r = post::compare_histories(a, b, o);
  REQUIRE(r.columns.size() == 1);
  CHECK(r.columns[0].max_difference <= 1e-12);
  CHECK(r.columns[0].peak_a == doctest::Approx(400.0 / 2.0).scale(0.0).epsilon(1e-12));
  // Columns by 1-based index: 3 in both.
  o.columns = {"3"};
  CHECK(post::compare_histories(a, b, o).columns[0].name_b == "thrust");
}

TEST_CASE("compare: requests that cannot be met are said plainly") {
  const auto a = io::read_history_text("time,f\n0,1\n1,2\n0.5,3\n", "a.csv");
  const auto b = io::read_history_text("time,g\n2,1\n3,2\n", "b.csv");
  const auto same = io::read_history_text("time,f\n0,1\n1,2\n", "same.csv");
  CHECK(error_of([&] { post::compare_histories(a, same, {}); }).find("not monotonic") !=
        std::string::npos);
  const auto a2 = io::read_history_text("time,f\n0,1\n1,2\n", "a2.csv");
  CHECK(error_of([&] { post::compare_histories(a2, b, {}); }).find("share no column") !=
        std::string::npos);
  post::CompareOptions o;
  o.columns = {"f:g"};
  CHECK(error_of([&] { post::compare_histories(a2, b, o); }).find("no common range") !=
        std::string::npos);
  o.columns = {"h"};
  CHECK(error_of([&] { post::compare_histories(a2, b, o); }).find("no column 'h'") !=
        std::string::npos);
}

TEST_CASE("history CSV: rows keyed by entity are pivoted into quantity@key columns") {
  const auto t = io::read_history_text(
      "time,contact,side,z_force\n0,1,slave,1.5\n0,1,master,-1.5\n1e-3,1,slave,2.5\n"
      "1e-3,1,master,-2.5\n",
      "rcforc.csv");
  REQUIRE(t.rows() == 2);
  CHECK(value(t, "z_force@1/slave", 1) == 2.5);
  CHECK(value(t, "z_force@1/master", 0) == -1.5);
  CHECK(value(t, "time", 1) == 1e-3);
  // A bad number is named with file, line, column and the line echoed.
  const std::string e = error_of([] { io::read_history_text("time,f\n0,1\n1,x2\n", "bad.csv"); });
  CHECK(e.find("bad.csv:3:3: error: 'x2' in column 'f' is not a number") != std::string::npos);
  CHECK(e.find("\n  1,x2\n") != std::string::npos);
  CHECK(error_of([] {
          io::read_history_text("time,f\n0,1,2\n", "c.csv");
        }).find("c.csv:2:1: error: 3 fields where the header has 2") != std::string::npos);
}

TEST_CASE("LS-DYNA ASCII: glstat, rcforc, nodout, spcforc, bndout and matsum layouts") {
  // Lines in the l2a formats of keywords.md §3 (widths as LS-DYNA prints them).
  const std::string glstat =
      " drop test\n                         ls-dyna (version R9)     date 01/02/2020\n\n\n"
      " dt of cycle       0 is controlled by solid             1 of part         1\n"
      " time...........................   0.00000E+00\n"
      " time step......................   1.00000E-06\n"
      " kinetic energy.................   5.00000E+01\n"
      " internal energy................   0.00000E+00\n"
      " stonewall energy...............   0.00000E+00 wall# 1\n"
      " hourglass energy ..............   0.00000E+00\n"
      " sliding interface energy.......   0.00000E+00\n"
      " total energy / initial energy..   1.00000E+00\n"
      " global z velocity..............  -1.00000E+03\n"
      " time per zone cycle.(nanosec)..           110\n\n\n"
      " dt of cycle     100 is controlled by solid             1 of part         1\n"
      " time...........................   1.00000E-04\n"
      " kinetic energy.................   4.00000E+01\n"
      " stonewall energy...............   2.50000E+00 wall# 1\n"
      " stonewall energy...............   1.50000E+00 wall# 2\n"
      " sliding interface energy.......   6.00000E+00\n"
      " total energy / initial energy..   9.99000E-01\n";
  auto g = io::read_history_text(glstat, "glstat");
  CHECK(g.format == "glstat");
  REQUIRE(g.rows() == 2);
  CHECK(value(g, "time", 1) == 1e-4);
  CHECK(value(g, "kinetic_energy", 1) == 40.0);
  CHECK(value(g, "sliding_energy", 1) == 6.0);
  CHECK(value(g, "energy_ratio", 1) == 0.999);
  CHECK(value(g, "stonewall_energy", 1) == 4.0);  // the walls summed, as glstat.csv has it
  CHECK(value(g, "stonewall_energy@2", 1) == 1.5);
  CHECK(value(g, "z_velocity", 0) == -1000.0);
  CHECK(value(g, "time_per_zone_cycle", 0) == 110.0);
  CHECK(std::isnan(value(g, "time_step", 1)));  // not printed at the second time

  const std::string rcforc =
      " drop test\n                         ls-dyna (version R9)     date 01/02/2020\n"
      "{BEGIN LEGEND}\n Entity #        Title\n        7     cube on plate\n{END LEGEND}\n"
      "  master          7 time  1.00000E-04  x -1.00000E+00  y  2.00000E+00  z -3.00000E+02 "
      "mass  0.00000E+00  mx  1.00000E+00  my  0.00000E+00  mz  5.00000E+00\n"
      "  slave           7 time  1.00000E-04  x  1.00000E+00  y -2.00000E+00  z  3.00000E+02 "
      "mass  4.00000E-03\n";
  auto rc = io::read_history_text(rcforc, "rcforc");
  CHECK(rc.format == "rcforc");
  REQUIRE(rc.rows() == 1);
  CHECK(value(rc, "z_force@7/master", 0) == -300.0);
  CHECK(value(rc, "z_force@7/slave", 0) == 300.0);
  CHECK(value(rc, "mass@7/slave", 0) == 0.004);
  CHECK(value(rc, "z_moment@7/master", 0) == 5.0);

  const std::string nodout =
      " drop test\n\n\n\n n o d a l   p r i n t   o u t   f o r   t i m e  s t e p       1"
      "                              ( at time 1.00000E-04 )\n\n"
      " nodal point  x-disp     y-disp      z-disp      x-vel       y-vel       z-vel      x-accl"
      "      y-accl      z-accl      x-coor      y-coor      z-coor\n"
      "       25 1.0000E-03  0.0000E+00 -2.0000E-03  0.0000E+00  0.0000E+00 -1.0000E+01  0.0000E+00"
      "  0.0000E+00  5.0000E+03  1.0010E+00  0.0000E+00  9.9800E-01\n"
      "       26 0.0000E+00  0.0000E+00  0.0000E+00  0.0000E+00  0.0000E+00  0.0000E+00  0.0000E+00"
      "  0.0000E+00  0.0000E+00  0.0000E+00  0.0000E+00  0.0000E+00\n"
      "\n\n\n n o d a l   p r i n t   o u t   f o r   t i m e  s t e p       1"
      "                              ( at time 1.00000E-04 )\n\n"
      " nodal point  x-rot      y-rot       z-rot       x-rot vel   y-rot vel   z-rot vel   x-rot "
      "acc"
      "   y-rot acc   z-rot acc\n"
      "       25 0.0000E+00  0.0000E+00  1.0000E-02  0.0000E+00  0.0000E+00  2.0000E+00  0.0000E+00"
      "  0.0000E+00  0.0000E+00\n";
  auto no = io::read_history_text(nodout, "nodout");
  CHECK(no.format == "nodout");
  REQUIRE(no.rows() == 1);
  CHECK(value(no, "z_disp@25", 0) == -0.002);
  CHECK(value(no, "z_accl@25", 0) == 5000.0);
  CHECK(value(no, "z_coor@25", 0) == 0.998);
  CHECK(value(no, "z_rot_vel@25", 0) == 2.0);

  const std::string spcforc =
      " drop test\n single point constraint forces\n\n output at time =   1.00000E-04\n"
      " node=       3 local x,y,z forces =    0.0000E+00    0.0000E+00    1.2500E+02\n"
      " node=       3 local x,y,z moments=    0.0000E+00    3.0000E+00    0.0000E+00\n"
      "             force resultants   =    0.0000E+00    0.0000E+00    1.2500E+02\n"
      " single point constraint forces\n\n output at time =   2.00000E-04\n"
      " node=       3 local x,y,z forces =    0.0000E+00    0.0000E+00    1.5000E+02\n";
  auto sp = io::read_history_text(spcforc, "spcforc");
  REQUIRE(sp.rows() == 2);
  CHECK(value(sp, "z_force@3", 1) == 150.0);
  CHECK(value(sp, "y_moment@3", 0) == 3.0);
  CHECK(value(sp, "z_force@resultant", 0) == 125.0);

  const std::string bndout =
      " drop test\n\n\n\n\n\n n o d a l   f o r c e/e n e r g y    o u t p u t   t= 1.000E-04\n"
      "\n\n\n\n\n discrete nodal point forces\n"
      " nd#       4  xforce=   1.0000E+00   yforce=   0.0000E+00  zforce=   0.0000E+00   "
      "energy=   1.0000E-03\n"
      " velocity boundary condition forces/rigid body moments\n"
      " nd#      19  xforce=   0.0000E+00   yforce=   0.0000E+00  zforce=  -4.0000E+00   "
      "energy=   2.0000E-02\n"
      "mat#       3  xforce=   0.0000E+00   yforce=   0.0000E+00  zforce=  -2.1000E+03   "
      "energy=   5.0000E+00\n"
      "             xmoment=   0.0000E+00  ymoment=   0.0000E+00 zmoment=   8.5000E-01\n"
      "              xtotal=   0.0000E+00   ytotal=   0.0000E+00  ztotal=  -2.1040E+03   "
      "etotal=   5.0200E+00\n";
  auto bo = io::read_history_text(bndout, "bndout");
  CHECK(bo.format == "bndout");
  REQUIRE(bo.rows() == 1);
  CHECK(value(bo, "x_force@discrete_node/4", 0) == 1.0);
  CHECK(value(bo, "z_force@node/19", 0) == -4.0);
  CHECK(value(bo, "z_force@rigid_part/3", 0) == -2100.0);
  CHECK(value(bo, "z_moment@rigid_part/3", 0) == 0.85);
  CHECK(value(bo, "energy@rigid_part/3", 0) == 5.0);
  CHECK(value(bo, "z_force@velocity_total", 0) == -2104.0);

  const std::string matsum =
      " drop test\n\n\n time =   1.0000E-04\n"
      " mat.#=    1             inten=   2.0000E+00     kinen=   3.0000E+01     eroded_ie=   "
      "0.0000E+00     eroded_ke=   0.0000E+00\n"
      " x-mom=   0.0000E+00     y-mom=   0.0000E+00     z-mom=  -6.0000E-02\n"
      " x-rbv=   0.0000E+00     y-rbv=   0.0000E+00     z-rbv=   0.0000E+00\n"
      "                         hgeng=   1.0000E-03     +mass=   0.0000E+00\n"
      " mat.#=    2             inten=   0.0000E+00     kinen=   1.0000E+00\n"
      " x-mom=   0.0000E+00     y-mom=   0.0000E+00     z-mom=   1.0000E+00\n"
      " x-rbv=   0.0000E+00     y-rbv=   0.0000E+00     z-rbv=   5.0000E-01\n";
  auto ms = io::read_history_text(matsum, "matsum");
  CHECK(ms.format == "matsum");
  CHECK(value(ms, "kinetic_energy@1", 0) == 30.0);
  CHECK(value(ms, "z_momentum@1", 0) == -0.06);
  CHECK(value(ms, "hourglass_energy@1", 0) == 0.001);
  CHECK(value(ms, "z_rigid_velocity@2", 0) == 0.5);

  // A damaged value is named with its place.
  const std::string broken =
      std::string(spcforc).replace(spcforc.find("1.5000E+02"), 10, "1.50#0E+02");
  CHECK(error_of([&] { io::read_history_text(broken, "spcforc"); }).find("spcforc:11:") !=
        std::string::npos);
}

TEST_CASE("mcdyna compare: the report, --tol as the exit code, --csv and --plot") {
  TempDir dir;
  dir.write("b.csv", csv_of("time,force,energy", 21,
                            [](double x) { return fmt::format("{},{},{}", x, 100.0 * x, 1.0); }));
  dir.write("a.csv", csv_of("time,force,energy", 21,
                            [](double x) { return fmt::format("{},{},{}", x, 103.0 * x, 1.0); }));
  const std::string cd = "cd " + dir.path().string() + " && ";
  Run r = run_mcdyna("compare a.csv b.csv --tol 0.05 --csv res.csv", cd);
  CHECK_MESSAGE(r.exit_code == 0, r.output);
  CHECK(r.output.find("within tolerance") != std::string::npos);
  CHECK(r.output.find("force") != std::string::npos);
  CHECK(read_text(dir.path() / "res.csv").rfind("time,A force,B force,A energy,B energy\n", 0) ==
        0);
  r = run_mcdyna("compare a.csv b.csv --tol 0.01 -c force", cd);
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("OUTSIDE tolerance 0.01 in 1 of 1 columns") != std::string::npos);
  CHECK(r.output.find("force (0.0300)") != std::string::npos);
  r = run_mcdyna("compare a.csv missing.csv", cd);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("missing.csv: error: cannot open the file") != std::string::npos);
  r = run_mcdyna("compare a.csv b.csv --plot cmp.png", cd);
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(read_text(dir.path() / "cmp.png").rfind("\x89PNG", 0) == 0);
}

}  // namespace mcdyna::test

namespace mcdyna::test {

TEST_CASE("history reader: endless, binary and odd files are located errors, never memory") {
  // /dev/zero has no line end: refused at its first line once it passes the line limit (it
  // read until bad_alloc, 6-11 s and gigabytes). /dev/urandom holds a NUL within its first lines.
  CHECK(error_of([] { io::read_history("/dev/zero"); }) ==
        "/dev/zero:1:1: error: a line longer than 1048576 characters: not a history file");
  CHECK(error_of([] { io::read_history("/dev/urandom"); }).find("error: a NUL byte") !=
        std::string::npos);
  // A NUL byte cut the messages that quoted the name it was in.
  CHECK(error_of([] { io::read_history_text(std::string("time,fo\0rce\n0,1\n", 16), "n.csv"); }) ==
        "n.csv:1:8: error: a NUL byte: not a text file");
  // A UTF-8 byte-order mark (spreadsheet exports) is not part of the first column's name.
  const io::HistoryTable bom = io::read_history_text("\xEF\xBB\xBFtime,force\n0,0\n1,2\n", "b.csv");
  CHECK(bom.names == std::vector<std::string>{"time", "force"});
  // Two columns of one name were merged into one silently.
  CHECK(error_of([] {
          io::read_history_text("time,force,force\n0,1,2\n", "d.csv");
        }).find("d.csv:1:12: error: column name 'force' appears twice") != std::string::npos);
  TempDir dir;
  CHECK(error_of([&] { io::read_history(dir.path()); }) ==
        dir.path().string() + ": error: is a directory");
  // The rows of a CSV are read one by one into the columns: the same table as before.
  const io::HistoryTable t = io::read_history_text("time;a;b\r\n0;1;2\r\n\r\n1;3;4\r\n", "s.csv");
  REQUIRE(t.rows() == 2);
  CHECK(value(t, "b", 1) == 4.0);
}

TEST_CASE("mcdyna compare: NaN or absurd option values are usage errors") {
  TempDir dir;
  const std::string a = dir.write("a.csv", "time,force\n0,0\n1,1\n2,4\n").string();
  const std::pair<std::string, std::string> cases[] = {
      {"--tol nan", "--tol: expected a finite number, got nan"},
      {"--from nan", "--from: expected a finite number, got nan"},
      {"--to inf", "--to: expected a finite number, got inf"},
      {"--points 4000000000", "--points: Value 4000000000 not in range 2 to 10000000"}};
  for (const auto& [option, message] : cases) {
    CAPTURE(option);
    const Run r = run_mcdyna("compare " + a + " " + a + " " + option);
    CHECK(r.exit_code == 2);
    CHECK_MESSAGE(r.output.find(message) != std::string::npos, r.output);
  }
  CHECK(run_mcdyna("compare " + a + " " + a + " --tol 0.01").exit_code == 0);
}

}  // namespace mcdyna::test
