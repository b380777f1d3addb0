#pragma once
// What the window tests need from the machine (an X display, xdotool for the ones that type and click): missing it,
// a test skips on a developer's machine but FAILS under CI=true, naming the fix (ci_env.h). At the top of the body:
//   BOXING_REQUIRE_DISPLAY();              // the X server (xvfb-run)
//   BOXING_REQUIRE_DISPLAY_AND_XDOTOOL();  // and xdotool
//   BOXING_SKIP_OR_FAIL(reason);           // anything else the environment lacks (e.g. no Vulkan device)
#include <cstdlib>
#include <string>

#include "engine/platform/window.h"
#include "support/ci_env.h"

namespace boxing_test {

// Why this machine cannot run a window test ("" = it can), with the fix.
inline std::string window_env_missing(bool need_xdotool) {
  if (!eng::platform::display_available())
    return "no X display: run the tests under xvfb-run (scripts/test does; xvfb-run -a -s \"-screen 0 1280x720x24\" "
           "ctest ...); scripts/deps installs xvfb";
  if (need_xdotool && std::system("command -v xdotool >/dev/null 2>&1") != 0)
    return "xdotool missing: scripts/deps installs it (apt-get install xdotool)";
  return "";
}

}  // namespace boxing_test

#define BOXING_REQUIRE_WINDOW_ENV_(need_xdotool)                                                       \
  do {                                                                                                 \
    const std::string boxing_missing_ = boxing_test::window_env_missing(need_xdotool);                 \
    if (!boxing_missing_.empty()) BOXING_SKIP_OR_FAIL(boxing_missing_);                                \
  } while (0)
#define BOXING_REQUIRE_DISPLAY() BOXING_REQUIRE_WINDOW_ENV_(false)
#define BOXING_REQUIRE_DISPLAY_AND_XDOTOOL() BOXING_REQUIRE_WINDOW_ENV_(true)
