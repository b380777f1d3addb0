// build/boxing: the boxing game. Exit codes: 0 ok, 1 runtime failure (content, Vulkan, display), 2 bad command line.
#include <cstdio>
#include <string>
#include <vector>

#include "game/app.h"
#include "game/cli.h"
#include "game/contact_sheet.h"
#include "game/graph_tool.h"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  auto options = boxing::parse_cli(args);
  if (!options) {
    std::fprintf(stderr, "%s\n", options.error().c_str());
    return 2;
  }
  if (options->help) {
    std::fputs(boxing::help_text().c_str(), stdout);
    return 0;
  }
  if (options->command == "clips") return boxing::run_contact_sheets(*options);
  if (options->command == "graph") return boxing::run_graph_tool(*options);
  return boxing::run(*options);
}
