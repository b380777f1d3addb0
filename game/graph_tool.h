#pragma once
// `boxing graph`: builds the motion graph from the clip library and writes its report (JSON) and picture (DOT).
#include "game/cli.h"

namespace boxing {

int run_graph_tool(const Options& options);  // exit code

}  // namespace boxing
