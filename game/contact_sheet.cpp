#include "game/contact_sheet.h"

#include <cstdio>
#include <filesystem>

#include "engine/anim/clip.h"
#include "engine/assets/character.h"
#include "engine/assets/gltf.h"
#include "engine/core/image.h"
#include "engine/render/renderer.h"
#include "game/scene_view.h"
#include "engine/control/servo/world_pose.h"
#include "game/world.h"

namespace boxing {

namespace fs = std::filesystem;

int run_contact_sheets(const Options& o) {
  const std::string dir = content_dir(o);
  auto scene = eng::assets::load_gltf(dir + "/boxer/boxer.gltf");
  if (!scene) return std::fprintf(stderr, "boxing: %s\n", scene.error().c_str()), 1;
  auto desc = eng::assets::load_character(*scene);
  if (!desc) return std::fprintf(stderr, "boxing: %s\n", desc.error().c_str()), 1;
  auto clips = eng::anim::load_clips(dir + "/clips/boxing_clips.gltf", desc->skeleton);
  if (!clips) return std::fprintf(stderr, "boxing: %s\n", clips.error().c_str()), 1;

  constexpr int kTile = 320, kCols = 6;
  eng::render::RendererConfig cfg;
  cfg.width = kTile;
  cfg.height = kTile;
  cfg.validation = o.validation;
  auto renderer = eng::render::Renderer::create_headless(cfg);
  if (!renderer) return std::fprintf(stderr, "boxing: %s\n", renderer.error().c_str()), 1;
  eng::render::Renderer& r = **renderer;
  const std::vector<BonePart> parts = upload_character_parts(*scene, *desc, r);
  std::error_code ec;
  fs::create_directories(o.sheet_dir, ec);

  std::vector<Eigen::Quaterniond> W;
  std::vector<Eigen::Vector3d> P;
  for (const auto& clip : *clips) {
    // Two rows: side view (the boxer faces +X, seen from its right) and a front-left three-quarter view.
    eng::Image sheet;
    sheet.width = kTile * kCols;
    sheet.height = kTile * 2;
    sheet.rgba.assign(size_t(sheet.width) * sheet.height * 4, 0);
    for (int k = 0; k < kCols; ++k) {
      const double t = clip.duration() * k / (kCols - 1);
      const eng::anim::Pose pose = eng::anim::sample_clip_pose(clip, t);
      eng::control::pose_fk(desc->skeleton, pose, W, P);
      eng::render::FrameDesc f;
      for (const BonePart& part : parts) {
        eng::render::Instance in;
        in.mesh = part.mesh;
        in.model = pose_matrix(W[part.bone], P[part.bone]);
        in.material = part.material;
        if (part.team) in.material.base_color = {0.75f, 0.08f, 0.06f, 1.0f};
        f.opaque.push_back(in);
      }
      const glm::vec3 at(float(pose.root_position.x()), float(pose.root_position.y()), 0.85f);
      for (int row = 0; row < 2; ++row) {
        f.camera.target = at;
        f.camera.eye = at + (row == 0 ? glm::vec3(0.0f, -3.4f, 0.35f) : glm::vec3(2.4f, 2.2f, 0.6f));
        f.camera.fov_y_deg = 40.0f;
        if (auto ok = r.render(f); !ok) return std::fprintf(stderr, "boxing: %s\n", ok.error().c_str()), 1;
        auto img = r.read_back();
        if (!img) return std::fprintf(stderr, "boxing: %s\n", img.error().c_str()), 1;
        for (int y = 0; y < kTile; ++y)
          std::copy_n(img->at(0, y), kTile * 4, sheet.at(k * kTile, row * kTile + y));
      }
    }
    const std::string path = (fs::path(o.sheet_dir) / (clip.name + ".png")).string();
    if (auto ok = eng::write_png(sheet, path); !ok)
      return std::fprintf(stderr, "boxing: cannot write %s: %s\n", path.c_str(), ok.error().c_str()), 1;
    std::printf("%s\n", path.c_str());
  }
  if (r.validation_errors() > 0) return std::fprintf(stderr, "boxing: Vulkan validation errors\n"), 1;
  return 0;
}

}  // namespace boxing
