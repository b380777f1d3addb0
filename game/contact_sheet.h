#pragma once
// `boxing clips --sheet DIR`: one PNG per clip with six frames across the clip, rendered headless from the side
// and the front-left, so a person can judge the poses of the motion library at a glance.
#include "game/cli.h"

namespace boxing {

int run_contact_sheets(const Options& options);  // exit code

}  // namespace boxing
