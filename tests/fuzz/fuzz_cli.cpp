// libFuzzer harness: the command-line parser of build/boxing (game/cli.h) on arbitrary arguments: the input is
// split at NUL bytes into argv[1..] (an argument cannot hold a NUL).
// Promise checked: parse_cli returns (never throws or exits), its errors are the one message main prints, and
// accepted options are within their documented ranges.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "game/cli.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<std::string> args;
  std::string cur;
  for (size_t i = 0; i < size; ++i) {
    if (data[i] == 0) {
      args.push_back(cur);
      cur.clear();
    } else {
      cur.push_back(static_cast<char>(data[i]));
    }
  }
  if (!cur.empty()) args.push_back(cur);
  auto o = boxing::parse_cli(args);
  if (!o) {
    // The line main prints: "boxing: WHAT (see --help)" (WHAT quotes the argument as given, newlines and all).
    const std::string& e = o.error();
    fuzz::check(e.rfind("boxing: ", 0) == 0 && e.size() >= 13 && e.compare(e.size() - 13, 13, " (see --help)") == 0,
                "an error that is not 'boxing: ... (see --help)': " + e);
    return 0;
  }
  fuzz::check(o->width >= 16 && o->width <= 16384 && o->height >= 16 && o->height <= 16384, "frame size");
  fuzz::check(std::isfinite(o->seconds) && o->seconds >= 0 && o->seconds <= 86400, "seconds");
  fuzz::check(std::isfinite(o->chaos) && o->chaos >= 0 && o->chaos <= 100, "chaos");
  fuzz::check(o->slow == 1 || o->slow == 2 || o->slow == 4 || o->slow == 10, "slow");
  fuzz::check(o->player >= -1 && o->player <= 1 && o->render_every >= 0, "player / render-every");
  fuzz::check(std::isfinite(o->servo_omega_n) && std::isfinite(o->servo_zeta) && std::isfinite(o->push_force) &&
                  std::isfinite(o->push_dir_deg) && std::isfinite(o->round_seconds),
              "numbers not finite");
  fuzz::check(o->command == "play" || o->command == "graph" || o->command == "clips", "command");
  return 0;
}
