// mcdyna command line: `run`, `check`, `compare`, `keywords`, and LS-DYNA habits (`mcdyna i=deck.k
// ncpu=2`).
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <malloc.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "cli/check_command.hpp"
#include "cli/compare_command.hpp"
#include "cli/keyword_docs.hpp"
#include "cli/partition_command.hpp"
#include "cli/run_command.hpp"
#include "cli/wait_policy.hpp"
#include "deck/registry.hpp"
#include "deck/text_util.hpp"

namespace {

constexpr int kExitUsage = 2;

// A number option that must be finite: CLI11's number checks let "nan" through (every
// comparison with NaN is false), and a NaN tolerance or window makes every answer meaningless.
const CLI::Validator kFinite(
    [](std::string& text) -> std::string {
      double v = 0.0;
      if (!CLI::detail::lexical_cast(text, v) || !std::isfinite(v))
        return "expected a finite number, got " + text;
      return {};
    },
    "FINITE");

// --points: at most ten million (a resampled column pair is then 160 MB; no history has that
// many rows), so a mistyped count is a usage error, not a failed allocation of gigabytes.
constexpr std::size_t kMostPoints = 10'000'000;

// Rewrites LS-DYNA style "key=value" arguments (i=, r=, ncpu=, memory=) into subcommand form.
// Returns false with a message for an unknown key.
bool translate_lsdyna_arguments(std::vector<std::string>& args, std::string& error) {
  std::vector<std::string> out;
  std::string deck, ncpu, restart;
  bool lsdyna_style = false;
  for (const std::string& a : args) {
    const auto eq = a.find('=');
    if (eq == std::string::npos || a.rfind("--", 0) == 0 || a.rfind('-', 0) == 0) {
      out.push_back(a);
      continue;
    }
    lsdyna_style = true;
    const std::string key = mcdyna::deck::upper(a.substr(0, eq));
    const std::string value = a.substr(eq + 1);
    if (key == "I") {
      deck = value;
    } else if (key == "R") {
      restart = value;
    } else if (key == "NCPU") {
      ncpu = value;
    } else if (key == "MEMORY" || key == "MEMORY2") {
      // Memory is allocated as needed; accepted for LS-DYNA command lines.
    } else {
      error = fmt::format(
          "unknown LS-DYNA style argument '{}' (mcdyna knows i=, r=, ncpu=, memory=)", a);
      return false;
    }
  }
  if (lsdyna_style) {
    if (deck.empty()) {
      // LS-DYNA restarts from r= alone; mcdyna compiles the deck's constant data again.
      error = restart.empty() ? "LS-DYNA style command line needs i=DECK"
                              : "r=DUMP needs i=DECK too: mcdyna restarts from the deck that "
                                "wrote the dump";
      return false;
    }
    out.insert(out.begin(), {"run", deck});
    if (!restart.empty()) {
      out.push_back("--restart");
      out.push_back(restart);
    }
    if (!ncpu.empty()) {
      out.push_back("--threads");
      out.push_back(ncpu.rfind('-', 0) == 0 ? ncpu.substr(1) : ncpu);  // ncpu=-2: same count
    }
  }
  args = out;
  return true;
}

CLI::App* add_check_command(CLI::App& app, mcdyna::cli::CheckOptions& check) {
  auto* cmd = app.add_subcommand("check",
                                 "read and cross-check a deck; print the model "
                                 "summary and the migration report");
  cmd->add_option("deck", check.deck, "keyword deck (.k, .key, .dyn)")->required();
  cmd->add_flag("--allow-unsupported", check.allow_unsupported,
                "do not fail on unsupported keywords that change the physics");
  cmd->add_flag("-q,--quiet", check.quiet, "print only diagnostics and the verdict");
  cmd->add_option("--case", check.case_id,
                  "check this *CASE of the deck (default: each case of a deck with *CASE)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--max-messages", check.max_messages, "diagnostics printed (0: all)")
      ->capture_default_str();
  return cmd;
}

CLI::App* add_partition_command(CLI::App& app, mcdyna::cli::PartitionOptions& partition) {
  auto* cmd = app.add_subcommand(
      "partition",
      "the decomposition a run over N processes would use, without running the physics: per "
      "rank the nodes it owns and reads, the elements and SPG rows it computes, the balance");
  cmd->add_option("deck", partition.deck, "keyword deck (.k, .key, .dyn)")->required();
  cmd->add_option("--ranks", partition.ranks, "rank counts, e.g. 2,4,64")
      ->required()
      ->delimiter(',');
  return cmd;
}

CLI::App* add_run_command(CLI::App& app, mcdyna::cli::RunOptions& run) {
  auto* cmd = app.add_subcommand("run",
                                 "run a deck: explicit dynamics, d3plot.pvd states, "
                                 "ASCII/CSV histories and d3hsp");
  cmd->add_option("deck", run.deck, "keyword deck (.k, .key, .dyn)")->required();
  cmd->add_option("--out", run.out_dir, "directory for the outputs (default: working dir)");
  cmd->add_option("--threads", run.threads, "OpenMP threads (default: all cores)");
  cmd->add_option("--restart", run.restart,
                  "continue from a restart dump (d3dumpNN, runrsf) written by this deck");
  cmd->add_flag("--allow-unsupported", run.allow_unsupported,
                "run without unsupported keywords that change the physics");
  cmd->add_flag("-q,--quiet", run.quiet, "no progress line and summary on success");
  cmd->add_option("--case", run.case_id,
                  "run this *CASE of the deck (default: each case in turn, into OUT/JOBID)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--max-messages", run.max_messages, "diagnostics printed (0: all)")
      ->capture_default_str();
  cmd->add_option("--spg-stabilization", run.spg_stabilization,
                  "SPG stabilisation, overriding the sections' ITB: none (plain nodal "
                  "integration), direct (Eq. 7 smoothing, for studies), mc (MC-SPG, ITB 3), spg "
                  "(original SPG strain-gradient stabilisation, ITB 1)")
      ->check(CLI::IsMember({"none", "direct", "mc", "spg"}));
  cmd->add_option("--spg-renewal-strain", run.spg_renewal_strain,
                  "KERNEL 0 SPG parts: at an SMSTEP check, renew the kernel of the particles "
                  "whose Green strain since their last renewal exceeds this (a fifth of it "
                  "under compression; default 0.1; 0: all particles at every check)")
      ->check(CLI::NonNegativeNumber);

  cmd->add_option("--spg-mode-control", run.spg_mode_control,
                  "SPG parts: coefficient of the low-energy-mode stiffness (default from the "
                  "deck: 0.5 with MSC = 1, else 0; 0 turns it off)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--spg-step", run.spg_step,
                  "SPG particle step estimate: nn (nearest-neighbour distance; the default "
                  "for MC-SPG and plain nodal integration) or eigen (stiffness lengths scaled "
                  "every second cycle to the largest eigenvalue of the linearised equations, "
                  "by power iteration; the default for ITB 1)")
      ->check(CLI::IsMember({"nn", "eigen"}));
  cmd->add_flag("--spg-angular-budget", run.spg_angular_budget,
                "record every SPG part's angular-momentum budget each cycle and report the "
                "scheme's own contribution (the gather's first-moment defect, theory.md) at "
                "the end");
  cmd->add_option("--fixed-step", run.fixed_step,
                  "probe: take this step every cycle whatever the stable-step estimate, add no "
                  "mass, write no restart dump (to measure the true critical step from a dump)")
      ->check(CLI::PositiveNumber & kFinite);
  cmd->add_option("--cycles", run.cycles, "stop after this many cycles of this run")
      ->check(CLI::Range(1L, 1000000000000L));
  cmd->add_option("--end-time", run.end_time,
                  "stop at this time instead of the deck's ENDTIM (the outputs' schedule is the "
                  "deck's)")
      ->check(CLI::PositiveNumber & kFinite);
  cmd->add_option("--step-log", run.step_log,
                  "write one CSV row per cycle: the step, what sets it, and the particle "
                  "with the smallest step at its physical mass");
  return cmd;
}

CLI::App* add_compare_command(CLI::App& app, mcdyna::cli::CompareCommandOptions& cmp) {
  auto* cmd = app.add_subcommand(
      "compare",
      "compare two histories (our CSV, other CSV, LS-DYNA ASCII rcforc/glstat/nodout/spcforc/"
      "bndout/matsum) column by column, or two d3plot families state by state; B is the "
      "reference");
  cmd->add_option("a", cmp.a, "history or d3plot family A")->required();
  cmd->add_option("b", cmp.b, "history or d3plot family B, the reference")->required();
  cmd->add_option("-c,--column", cmp.compare.columns,
                  "column to compare: NAME (in both; a quantity like z_force takes all its "
                  "z_force@... columns), A_NAME:B_NAME, or a 1-based index; repeatable "
                  "(default: every column the files share)");
  cmd->add_option("--x", cmp.compare.x_a, "column to align on (name or index)")
      ->capture_default_str();
  cmd->add_option("--x-b", cmp.compare.x_b, "alignment column in B when named differently");
  cmd->add_option("--points", cmp.compare.points,
                  "resampling points (default: the denser file's count in the common range)")
      ->check(CLI::Range(std::size_t{2}, kMostPoints));
  cmd->add_option("--from", cmp.compare.from, "start of the compared range of x")->check(kFinite);
  cmd->add_option("--to", cmp.compare.to, "end of the compared range of x")->check(kFinite);
  cmd->add_option("--tol", cmp.tolerance, "exit 1 when a column's max|A-B| / peak|B| exceeds this")
      ->check(kFinite & CLI::NonNegativeNumber);
  cmd->add_option("--plot", cmp.plot, "PNG with both curves and their difference");
  cmd->add_option("--csv", cmp.csv, "write the resampled curves as CSV");
  cmd->add_option("--diff-series", cmp.difference_series,
                  "two d3plot families: write A - B on B's mesh as a VTK series into DIR");
  return cmd;
}

// `mcdyna keywords [NAME] [--markdown DIR] [--raw]`.
struct KeywordsOptions {
  std::string name;
  std::string markdown_dir;
  bool raw = false;
};

CLI::App* add_keywords_command(CLI::App& app, KeywordsOptions& k) {
  auto* cmd = app.add_subcommand("keywords", "list supported keywords or print one's card layout");
  cmd->add_option("name", k.name, "keyword (with or without '*'), e.g. MAT_JOHNSON_COOK");
  cmd->add_option("--markdown", k.markdown_dir, "write the keyword reference pages into DIR");
  cmd->add_flag("--raw", k.raw, "print the schema file as embedded");
  return cmd;
}

int run_keywords(const KeywordsOptions& k) {
  const mcdyna::deck::Registry registry;
  if (!k.markdown_dir.empty()) {
    if (!mcdyna::cli::write_keyword_pages(k.markdown_dir, registry)) {
      std::cerr << "mcdyna: cannot write keyword pages into " << k.markdown_dir << "\n";
      return 1;
    }
    return 0;
  }
  if (k.name.empty()) {
    mcdyna::cli::print_keyword_list(std::cout, registry);
    return 0;
  }
  std::string name = mcdyna::deck::upper(k.name);
  if (!name.empty() && name.front() == '*') name.erase(0, 1);
  const auto c = registry.classify(name);
  if (c.schema == nullptr) {
    std::cerr << fmt::format("mcdyna: *{} is not a supported keyword ({}{})\n", name,
                             mcdyna::deck::support_name(c.support),
                             c.reason.empty() ? "" : ": " + c.reason);
    return 1;
  }
  if (k.raw)
    std::cout << registry.schema_text(c.schema->name);
  else
    mcdyna::cli::print_keyword_layout(std::cout, *c.schema, false);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  mcdyna::cli::adopt_passive_wait(argv);  // first: it may start the program again
  // Buffers of a particle's size and more are allocated and freed every cycle (SPG velocity
  // changes, contact hits, exchange buffers). Given back to the system each time, they come
  // back as fresh pages: page faults were 4.7 % of an FDS h 0.15 run (perf). Keep freed memory.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string error;
  if (!translate_lsdyna_arguments(args, error)) {
    std::cerr << "mcdyna: " << error << "\n";
    return kExitUsage;
  }
  // The name is given: the arguments are parsed from a vector (after the i= r= translation),
  // so CLI11 never sees argv[0] and its usage line would read "Usage: [OPTIONS]".
  CLI::App app{"mcdyna - LS-DYNA-style keyword decks, explicit dynamics with MC-SPG particles",
               "mcdyna"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "mcdyna 0.1");

  mcdyna::cli::CheckOptions check;
  CLI::App* check_cmd = add_check_command(app, check);
  mcdyna::cli::PartitionOptions partition;
  CLI::App* partition_cmd = add_partition_command(app, partition);
  mcdyna::cli::RunOptions run;
  CLI::App* run_cmd = add_run_command(app, run);
  mcdyna::cli::CompareCommandOptions cmp;
  CLI::App* cmp_cmd = add_compare_command(app, cmp);
  KeywordsOptions keywords;
  add_keywords_command(app, keywords);

  try {
    std::vector<std::string> reversed(args.rbegin(), args.rend());
    app.parse(reversed);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitUsage;
  }

  try {
    if (*check_cmd) return mcdyna::cli::run_check(check, std::cout, std::cerr);
    if (*partition_cmd) return mcdyna::cli::run_partition(partition, std::cout, std::cerr);
    if (*run_cmd) return mcdyna::cli::run_deck(run, std::cout, std::cerr);
    if (*cmp_cmd) return mcdyna::cli::run_compare(cmp, std::cout, std::cerr);
    return run_keywords(keywords);
  } catch (const std::exception& e) {
    std::cerr << "mcdyna: internal error: " << e.what() << "\n";
    return 3;
  }
}
