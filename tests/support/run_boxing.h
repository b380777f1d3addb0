#pragma once
// The game's executable run as a person runs it (lavapipe pinned, stderr with stdout): its exit code and output.
#include <sys/wait.h>

#include <cstdio>
#include <string>

#include "support/vulkan_test_env.h"
#include "test_paths.h"

namespace boxing_test {

struct ExeRun {
  int code;
  std::string output;
};

inline ExeRun run_boxing(const std::string& args) {
  pin_lavapipe_env();
  const std::string cmd = std::string(BOXING_BINARY_DIR) + "/boxing " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  char buf[512];
  while (p && fgets(buf, sizeof buf, p)) out += buf;
  const int status = p ? pclose(p) : -1;
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

}  // namespace boxing_test
