// Fuzz target for the deck reader: any bytes read as a deck (read, build, cross-check, and
// compile when the deck is clean) give diagnostics, never a crash, a hang, an internal error or
// a message of unbounded size. Two ways to drive it:
//   - libFuzzer (clang, -DMCDYNA_LIBFUZZER=ON): coverage-guided, LLVMFuzzerTestOneInput below;
//   - this file's own mutation driver (any compiler; what CI runs under ASan + UBSan):
//       mcdyna_reader_fuzz --inputs N [--seed S] SEED_DIR_OR_FILE...
//     mutates the seeds (the public decks, tests/data/fuzz/, and the generated hostile cases of
//     issue 22) N times, deterministically for a given S, and reports the first failure with
//     the input written to reader_fuzz_failure.k for replay (`mcdyna_reader_fuzz FILE`).
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostics.hpp"
#include "deck/build_model.hpp"
#include "deck/deck.hpp"
#include "deck/registry.hpp"
#include "deck/text_util.hpp"
#include "model/checks.hpp"
#include "solver/run/compile.hpp"

namespace fs = std::filesystem;
using namespace mcdyna;

namespace {

// A diagnostic longer than this is a message that grew with its input (core::excerpt and the
// clipping in Diagnostics::report bound them to well under it).
constexpr std::size_t kLongestMessage = 2000;

// Reads `text` as a deck the way `mcdyna check` does, then compiles it when it is clean.
// Returns "" or what went wrong.
std::string read_one(const std::string& text) {
  static const deck::Registry registry;
  core::Diagnostics diags;
  try {
    deck::Deck d = deck::read_deck_text(text, fs::temp_directory_path() / "fuzz" / "main.k", diags);
    deck::BuildResult built = deck::build_model(d, registry, diags);
    model::check(built.model, diags);
    for (const core::Diagnostic& diag : diags.all()) {
      // build_model's messages for a builder that threw begin so (a deck may quote the words).
      if (diag.message.rfind("internal error", 0) == 0) return diag.message;
      const std::string shown = core::format_diagnostic(diag, d.files);
      if (shown.size() > kLongestMessage)
        return fmt::format("a diagnostic of {} bytes: {}", shown.size(), shown.substr(0, 300));
    }
    if (!diags.has_errors()) {
      core::Diagnostics compile_diags;
      solver::compile(built.model, compile_diags);
    }
  } catch (const std::exception& e) {
    return std::string("exception: ") + e.what();
  }
  return {};
}

// The hostile decks of issue 22, made here rather than committed (some are megabytes).
std::vector<std::string> generated_seeds() {
  std::vector<std::string> out;
  std::string chain = "*KEYWORD\n*PARAMETER_EXPRESSION\n";
  for (int i = 10000; i > 0; --i)
    chain += fmt::format("R Q{},Q{}+1\n", i, i - 1);
  out.push_back(chain + "R Q0,1\n*END\n");
  for (const char* op : {"1**", "-", "+", "(", "sqrt("}) {
    std::string e = "*KEYWORD\n*PARAMETER_EXPRESSION\nR X,";
    for (int i = 0; i < 300000; ++i)
      e += op;
    out.push_back(e + "1\n*END\n");
  }
  out.push_back("*KEYWORD\n*NODE\n1,0.0," + std::string(70000, '7') + "x,0.0\n*END\n");
  out.push_back("");
  out.push_back(std::string("*KEYWORD\n\0\0*NODE\n1\0,0,0\n", 24));
  out.push_back("*KEYWORD\n*CONTROL_TERMINATION\n1.0E-5\n*NODE\n1,0,0,0\n2,1,0,0\n*END\n");
  out.push_back("\xEF\xBB\xBF*KEYWORD\n*PARAMETER\nR a,1.0\n*END\n");
  return out;
}

// Lines of a text (without their '\n'), as strings to edit.
std::vector<std::string> lines_of(const std::string& text) {
  const std::vector<std::string_view> views = deck::split_lines(text);
  return {views.begin(), views.end()};
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines)
    out += l + '\n';
  return out;
}

// One mutation of `text` (`other`: another seed, for splices).
std::string mutate(std::string text, const std::string& other, std::mt19937_64& rng) {
  static const std::vector<std::string> kTokens = {
      "1.0E+309", "-0",     "nan",   "inf",   "&x",      "&",           "99999999999999999999",
      "1**-2",    "(((",    "0x10",  "1e",    "-",       ".",           "  ",
      "\t",       ",,,,,,", "*",     "$",     "&q10000", "-2147483648", "1.5",
      "1d400",    "+",      "1,2,3", "\"a\"", "1/0",     "sqrt(-1)",    std::string(300, '9')};
  static const std::vector<std::string> kKeywords = {"*INCLUDE\nmissing.k\n",
                                                     "*INCLUDE\n/dev/zero\n",
                                                     "*PARAMETER\nR x 1.0\n",
                                                     "*PARAMETER_EXPRESSION\nR y,&y+1\n",
                                                     "*PARAMETER_EXPRESSION\nR z,&q10000*2\n",
                                                     "*KEYWORD LONG=Y\n",
                                                     "*KEYWORD I10=Y\n",
                                                     "*DEFINE_CURVE\n1\n0,0\n",
                                                     "*END\n",
                                                     "*CONTROL_TIMESTEP\n0.0,0.9,0,0,1.0E30\n",
                                                     "*DATABASE_BINARY_D3PLOT\n1.0E-21\n",
                                                     "*PART\np\n1,1,1\n",
                                                     "*SECTION_SOLID_SPG\n1,47\n",
                                                     "*SET_NODE_LIST_GENERATE\n1\n1,999999999\n"};
  auto pick = [&](std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(rng() % n); };
  std::vector<std::string> lines = lines_of(text);
  switch (rng() % 8) {
    case 0:  // flip bytes
      for (int k = 0, n = 1 + static_cast<int>(rng() % 8); k < n && !text.empty(); ++k)
        text[pick(text.size())] ^= static_cast<char>(1 + rng() % 255);
      return text;
    case 1:  // truncate anywhere, mid-line included
      text.resize(pick(text.size() + 1));
      return text;
    case 2:  // delete a line
      if (!lines.empty()) lines.erase(lines.begin() + static_cast<long>(pick(lines.size())));
      return joined(lines);
    case 3: {  // repeat a line up to 1000 times, adding at most a megabyte
      if (lines.empty()) return text;
      const std::size_t at = pick(lines.size());
      const std::size_t times = std::min(1 + pick(1000), (1u << 20) / (lines[at].size() + 1));
      lines.insert(lines.begin() + static_cast<long>(at), times, lines[at]);
      return joined(lines);
    }
    case 4: {  // a line of another seed
      const std::vector<std::string> from = lines_of(other);
      if (from.empty()) return text;
      lines.insert(lines.begin() + static_cast<long>(pick(lines.size() + 1)),
                   from[pick(from.size())]);
      return joined(lines);
    }
    case 5: {  // a nasty token over a field (10-column or comma-separated)
      if (lines.empty()) return text;
      std::string& l = lines[pick(lines.size())];
      const std::size_t at = pick(l.size() + 1);
      l.replace(at, std::min<std::size_t>(10, l.size() - at), kTokens[pick(kTokens.size())]);
      return joined(lines);
    }
    case 6:  // a keyword block anywhere
      lines.insert(lines.begin() + static_cast<long>(pick(lines.size() + 1)),
                   kKeywords[pick(kKeywords.size())]);
      return joined(lines);
    default:  // swap two lines
      if (lines.size() > 1) std::swap(lines[pick(lines.size())], lines[pick(lines.size())]);
      return joined(lines);
  }
}

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Seed decks: every .k/.key/.dyn file under the paths of at most `largest` bytes (bigger decks
// cost more per input than they add), in a fixed order.
std::vector<std::string> load_seeds(const std::vector<fs::path>& paths, std::uintmax_t largest) {
  std::vector<fs::path> files;
  for (const fs::path& p : paths) {
    if (fs::is_regular_file(p)) files.push_back(p);
    if (!fs::is_directory(p)) continue;
    for (const auto& e : fs::recursive_directory_iterator(p)) {
      const std::string ext = e.path().extension().string();
      if (e.is_regular_file() && (ext == ".k" || ext == ".key" || ext == ".dyn" || ext == ".K") &&
          e.file_size() <= largest)
        files.push_back(e.path());
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<std::string> seeds;
  for (const fs::path& f : files)
    seeds.push_back(read_file(f));
  return seeds;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string failure = read_one(std::string(reinterpret_cast<const char*>(data), size));
  if (!failure.empty()) {
    std::fprintf(stderr, "reader fuzz: %s\n", failure.c_str());
    std::abort();  // libFuzzer keeps the input as a crash
  }
  return 0;
}

#ifndef MCDYNA_LIBFUZZER
int main(int argc, char** argv) {
  long inputs = 0;
  std::uint64_t seed = 22;
  std::vector<fs::path> paths;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--inputs" && i + 1 < argc) {
      inputs = std::atol(argv[++i]);
    } else if (a == "--seed" && i + 1 < argc) {
      seed = std::strtoull(argv[++i], nullptr, 10);
    } else {
      paths.emplace_back(a);
    }
  }
  if (inputs == 0) {  // replay: each file as it is
    for (const fs::path& p : paths) {
      const std::string failure = read_one(read_file(p));
      fmt::print("{}: {}\n", p.string(), failure.empty() ? "ok" : failure);
      if (!failure.empty()) return 1;
    }
    return 0;
  }
  std::vector<std::string> seeds = load_seeds(paths, 64 * 1024);
  const std::size_t from_files = seeds.size();
  for (std::string& g : generated_seeds())
    seeds.push_back(std::move(g));
  // The seeds as they are first, then the mutations.
  for (const std::string& s : seeds) {
    const std::string failure = read_one(s);
    if (!failure.empty()) {
      std::ofstream("reader_fuzz_failure.k", std::ios::binary) << s;
      fmt::print("reader fuzz: a seed fails: {} (written to reader_fuzz_failure.k)\n", failure);
      return 1;
    }
  }
  std::mt19937_64 rng(seed);
  for (long n = 0; n < inputs; ++n) {
    const std::size_t base = static_cast<std::size_t>(rng() % seeds.size());
    std::string text = seeds[base];
    for (int k = 0, m = 1 + static_cast<int>(rng() % 3); k < m; ++k)
      text = mutate(std::move(text), seeds[static_cast<std::size_t>(rng() % seeds.size())], rng);
    const std::string failure = read_one(text);
    if (!failure.empty()) {
      std::ofstream("reader_fuzz_failure.k", std::ios::binary) << text;
      fmt::print(
          "reader fuzz: input {} (seed {}, from seed deck {}) fails: {}\n"
          "  written to reader_fuzz_failure.k; replay: mcdyna_reader_fuzz "
          "reader_fuzz_failure.k\n",
          n, seed, base, failure);
      return 1;
    }
  }
  fmt::print("reader fuzz: {} seeds ({} decks, {} generated), {} mutated inputs, no failure\n",
             seeds.size(), from_files, seeds.size() - from_files, inputs);
  return 0;
}
#endif
