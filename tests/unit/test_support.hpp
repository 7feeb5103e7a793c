#pragma once
// Helpers for tests: temporary deck files and one-call deck reading.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <array>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "core/diagnostics.hpp"
#include "deck/build_model.hpp"
#include "deck/deck.hpp"
#include "deck/registry.hpp"
#include "model/checks.hpp"

namespace mcdyna::test {

/// A fresh directory under the system temp dir, removed at scope exit.
/// Whole contents of a text file ("" if it cannot be read).
inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A file of the source tree, e.g. "decks/taylor_bar/taylor_coarse.k".
inline std::string source_text(const std::string& relative) {
  return read_text(std::filesystem::path(MCDYNA_SOURCE_DIR) / relative);
}

class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("mcdyna_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto p = path_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }

 private:
  std::filesystem::path path_;
};

/// Result of running the mcdyna binary.
struct Run {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr
};

/// Runs a shell command line, stdout and stderr captured.
inline Run run_shell(const std::string& command) {
  Run r;
  const std::string cmd = command + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0)
    r.output.append(buf.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

/// Runs `mcdyna ARGS` (optionally with a command prefix such as "cd DIR &&" or "timeout ...").
inline Run run_mcdyna(const std::string& args, const std::string& prefix = "") {
  return run_shell(prefix + " " + std::string(MCDYNA_BINARY) + " " + args);
}

/// Everything reading a deck produces.
struct Loaded {
  core::Diagnostics diags;
  deck::Deck deck;
  deck::BuildResult built;
  [[nodiscard]] const model::ModelDatabase& model() const { return built.model; }
  [[nodiscard]] bool has_message(const std::string& part) const {
    for (const auto& d : diags.all()) {
      if (d.message.find(part) != std::string::npos) return true;
    }
    return false;
  }
  [[nodiscard]] std::string messages() const {
    std::string s;
    for (const auto& d : diags.all())
      s += core::format_diagnostic(d, deck.files);
    return s;
  }
};

inline const deck::Registry& registry() {
  static const deck::Registry r;
  return r;
}

/// Reads, builds and (optionally) cross-checks a deck file.
inline std::unique_ptr<Loaded> load_file(const std::filesystem::path& path, bool checks = false) {
  auto l = std::make_unique<Loaded>();
  l->deck = deck::read_deck(path, l->diags);
  l->built = deck::build_model(l->deck, registry(), l->diags);
  if (checks) model::check(l->built.model, l->diags);
  return l;
}

/// Same for deck text (written to a temporary main.k).
inline std::unique_ptr<Loaded> load_text(const std::string& text, bool checks = false) {
  TempDir dir;
  return load_file(dir.write("main.k", text), checks);
}

}  // namespace mcdyna::test
