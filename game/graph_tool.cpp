#include "game/graph_tool.h"

#include <cstdio>
#include <fstream>

#include "engine/anim/clip.h"
#include "engine/anim/motion_graph.h"
#include "engine/assets/character.h"
#include "engine/assets/gltf.h"
#include "game/boxing_motion.h"
#include "game/world.h"

namespace boxing {

int run_graph_tool(const Options& o) {
  const std::string dir = content_dir(o);
  auto scene = eng::assets::load_gltf(dir + "/boxer/boxer.gltf");
  if (!scene) {
    std::fprintf(stderr, "boxing: %s\n", scene.error().c_str());
    return 1;
  }
  auto desc = eng::assets::load_character(*scene);
  if (!desc) {
    std::fprintf(stderr, "boxing: %s\n", desc.error().c_str());
    return 1;
  }
  auto clips = eng::anim::load_clips(dir + "/clips/boxing_clips.gltf", desc->skeleton);
  if (!clips) {
    std::fprintf(stderr, "boxing: %s\n", clips.error().c_str());
    return 1;
  }
  eng::anim::MotionGraph graph;
  graph.build(*clips, eng::anim::GraphOptions{}, boxing_graph_options(desc->skeleton), desc->skeleton);
  const nlohmann::json report = eng::anim::graph_report(graph);
  auto write = [](const std::string& path, const std::string& text) {
    std::ofstream f(path);
    if (!f) {
      std::fprintf(stderr, "boxing: cannot write '%s' (check the folder exists and is writable)\n", path.c_str());
      return false;
    }
    f << text;
    return true;
  };
  if (!o.graph_report.empty() && !write(o.graph_report, report.dump(2) + "\n")) return 1;
  if (!o.graph_dot.empty() && !write(o.graph_dot, eng::anim::graph_dot(graph))) return 1;
  std::printf("%s\n", report.dump(2).c_str());
  return 0;
}

}  // namespace boxing
