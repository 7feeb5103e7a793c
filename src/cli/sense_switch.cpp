#include "cli/sense_switch.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <system_error>

namespace mcdyna::cli {

SenseSwitchFile::SenseSwitchFile(std::filesystem::path dir, bool reader, std::ostream& out)
    : path_(std::move(dir) / "d3kil"), reader_(reader), out_(out) {}

bool SenseSwitchFile::parse(const std::string& text, solver::SenseSwitches& out) {
  std::string word;
  std::istringstream(text) >> word;
  std::transform(word.begin(), word.end(), word.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  out = {};
  if (word.empty() || word == "sw1") {
    out.stop = true;
  } else if (word == "sw2") {
    out.status = true;
  } else if (word == "sw3") {
    out.dump = true;
  } else if (word == "sw4") {
    out.state = true;
  } else {
    return false;
  }
  return true;
}

solver::SenseSwitches SenseSwitchFile::poll() {
  if (!reader_) return {};
  const auto now = std::chrono::steady_clock::now();
  if (now - last_look_ < std::chrono::milliseconds(200)) return {};
  last_look_ = now;
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec)) return {};
  std::string text;
  {
    std::ifstream in(path_);
    std::ostringstream all;
    all << in.rdbuf();
    text = all.str();
  }
  std::filesystem::remove(path_, ec);
  solver::SenseSwitches sw;
  if (!parse(text, sw)) {
    fmt::print(out_,
               "d3kil: \"{}\" is no sense switch (sw1 restart dump and stop, sw2 status, sw3 "
               "restart dump, sw4 d3plot state); ignored\n",
               text.substr(0, text.find('\n')));
    out_.flush();
    return {};
  }
  const char* what = sw.stop     ? "sw1: a restart dump, then stop"
                     : sw.status ? "sw2: status"
                     : sw.dump   ? "sw3: a restart dump"
                                 : "sw4: a d3plot state";
  fmt::print(out_, "d3kil read: sense switch {}\n", what);
  out_.flush();
  stop_ = stop_ || sw.stop;
  return sw;
}

}  // namespace mcdyna::cli
