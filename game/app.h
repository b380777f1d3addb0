#pragma once
// The game's two run loops: headless (fixed number of 60 Hz frames, render only what is asked, write PNGs and the
// report) and windowed (GLFW window, input, F12 screenshots). Both drive the same World and the same renderer.
#include <nlohmann/json.hpp>
#include <string>

#include "engine/core/image.h"
#include "engine/core/result.h"
#include "game/cli.h"

namespace boxing {

struct HeadlessRun {
  eng::Image image;  // the last frame
  nlohmann::json report;
  std::string driver;  // device name and driver version, as the renderer reports them
  int validation_errors = 0;
  bool validation_active = false;
};

// Runs the scenario headless for options.seconds (default 2 s) and renders the last frame (and every
// render_every-th frame into frames_dir). Writes --screenshot / --report when given.
eng::Result<HeadlessRun> run_headless(const Options& options);

// main(): windowed when a display exists (or headless when asked / when there is none). Returns the exit code.
int run(const Options& options);

}  // namespace boxing
