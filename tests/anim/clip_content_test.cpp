// The committed clip content (content/clips/boxing_clips.gltf) and loader errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unistd.h>

#include "anim/anim_test_util.h"
#include "engine/assets/gltf.h"
#include "test_paths.h"
#include "support/ci_env.h"

using namespace eng::anim;
using anim_test::boxer_skeleton;
using anim_test::clips_path;
using anim_test::content_clips;

namespace {

const std::vector<std::string> kExpected = {
    "guard",         "jab",          "cross",        "lead_hook",     "rear_hook",  "lead_uppercut",
    "rear_uppercut", "combo_jab_cross", "slip_left", "slip_right",    "duck",       "block_high",
    "block_low",     "step_forward",  "step_back",    "hit_head",     "hit_body",      "stagger",    "fall_back",
    "fall_forward",  "down_back",    "down_front",   "getup_back",    "getup_front"};

std::string tmp_dir() {
  auto d = std::filesystem::temp_directory_path() / ("anim_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(d);
  return d.string();
}

nlohmann::json read_json(const std::string& p) {
  std::ifstream f(p);
  return nlohmann::json::parse(f);
}

std::string write_json(const nlohmann::json& j, const std::string& name) {
  const std::string p = tmp_dir() + "/" + name;
  std::ofstream(p) << j.dump();
  return p;
}

}  // namespace

TEST(ClipContent, AllClipsLoadWithTags) {
  auto r = load_clips(clips_path(), boxer_skeleton());
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_GE(r->size(), 16u);
  for (const auto& n : kExpected) {
    const int i = find_clip(*r, n);
    ASSERT_GE(i, 0) << "missing clip " << n;
    const Clip& c = (*r)[i];
    EXPECT_FALSE(c.tags.empty()) << n;
    EXPECT_GT(c.duration(), 0.1) << n;
    EXPECT_EQ(c.keys.size(), c.key_times.size());
    for (const auto& k : c.keys) EXPECT_EQ(static_cast<int>(k.rotation.size()), 16);
  }
  const Skeleton s = boxer_skeleton();
  int punches = 0;
  for (const Clip& c : *r) {
    if (!c.has_tag("punch")) continue;
    ++punches;
    EXPECT_TRUE(c.glove == s.find("glove_l") || c.glove == s.find("glove_r")) << c.name;
    EXPECT_GT(c.impact_time, 0.0) << c.name;
    EXPECT_LT(c.impact_time, c.duration()) << c.name;
  }
  EXPECT_GE(punches, 7);
  EXPECT_TRUE((*r)[find_clip(*r, "guard")].loop);
  EXPECT_TRUE((*r)[find_clip(*r, "guard")].has_tag("guard"));
}

TEST(ClipContent, PunchGloveIsExtendedAtImpact) {
  // At impact the striking glove is well in front of the chest (reach along the facing).
  const Skeleton s = boxer_skeleton();
  for (const Clip& c : content_clips()) {
    if (!c.has_tag("punch")) continue;
    std::vector<Eigen::Vector3d> g0, gi;
    std::vector<Eigen::Quaterniond> r;
    forward_kinematics(s, sample_clip_pose(c, 0.0), &g0, &r);
    forward_kinematics(s, sample_clip_pose(c, c.impact_time), &gi, &r);
    const double reach0 = (g0[c.glove] - g0[2]).head<2>().norm();
    const double reachi = (gi[c.glove] - gi[2]).head<2>().norm();
    EXPECT_GT(reachi, reach0 + 0.08) << c.name;
  }
}

TEST(ClipContent, StandingClipsKeepFeetOnTheFloor) {
  // Guard, punches and defence keep both soles planted (< 1 cm) over the whole spline, not just at keys.
  const Skeleton s = boxer_skeleton();
  const int fl = s.find("foot_l"), fr = s.find("foot_r");
  for (const Clip& c : content_clips()) {
    if (!(c.has_tag("guard") || c.has_tag("punch") || c.has_tag("defence"))) continue;
    if (c.name == "cross" || c.name == "combo_jab_cross" || c.name == "rear_hook" || c.name == "rear_uppercut") {
      // rear heel pivots: only the lead foot is checked
      for (double t = 0; t <= c.duration(); t += 1.0 / 120)
        EXPECT_LT(std::abs(anim_test::sole(s, sample_clip_pose(c, t), fl).z()), 0.01) << c.name << " t=" << t;
      continue;
    }
    for (double t = 0; t <= c.duration(); t += 1.0 / 120) {
      const Pose p = sample_clip_pose(c, t);
      EXPECT_LT(std::abs(anim_test::sole(s, p, fl).z()), 0.01) << c.name << " t=" << t;
      EXPECT_LT(std::abs(anim_test::sole(s, p, fr).z()), 0.01) << c.name << " t=" << t;
    }
  }
}

TEST(ClipContent, ClipsStartAndEndNearGuard) {
  const auto& clips = content_clips();
  ASSERT_GE(find_clip(clips, "guard"), 0);
  const Pose g = clips[find_clip(clips, "guard")].keys[0];
  for (const Clip& c : clips) {
    if (c.has_tag("fall") || c.has_tag("down")) continue;
    for (const Pose* p : {&c.keys.front(), &c.keys.back()}) {
      if (c.has_tag("getup") && p == &c.keys.front()) continue;
      for (int b = 1; b < 16; ++b)
        EXPECT_LT(quat_log(p->rotation[b].conjugate() * g.rotation[b]).norm(), 0.35)
            << c.name << " bone " << b;
    }
  }
}

TEST(ClipErrors, MissingFile) {
  auto r = load_clips("/nonexistent/clips.gltf", boxer_skeleton());
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("/nonexistent/clips.gltf"), std::string::npos) << r.error();
}

TEST(ClipErrors, BrokenJson) {
  const std::string p = tmp_dir() + "/broken.gltf";
  std::ofstream(p) << "{ \"asset\": { \"version\": \"2.0\" }, \"nodes\": [ ";
  auto r = load_clips(p, boxer_skeleton());
  ASSERT_FALSE(r.ok());
  EXPECT_FALSE(r.error().empty());
}

TEST(ClipErrors, UnknownNode) {
  nlohmann::json j = read_json(clips_path());
  j["nodes"][3]["name"] = "antenna";
  auto r = load_clips(write_json(j, "unknown_node.gltf"), boxer_skeleton());
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("antenna"), std::string::npos) << r.error();
  EXPECT_NE(r.error().find("not a skeleton bone"), std::string::npos) << r.error();
}

TEST(ClipErrors, MissingMetadata) {
  nlohmann::json j = read_json(clips_path());
  j["animations"][0]["extras"].erase("tags");
  auto r = load_clips(write_json(j, "no_tags.gltf"), boxer_skeleton());
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("metadata"), std::string::npos) << r.error();

  nlohmann::json k = read_json(clips_path());
  for (auto& a : k["animations"])
    if (a["name"] == "jab") a["extras"].erase("impact");
  auto r2 = load_clips(write_json(k, "no_impact.gltf"), boxer_skeleton());
  ASSERT_FALSE(r2.ok());
  EXPECT_NE(r2.error().find("jab"), std::string::npos) << r2.error();
}

// Found by fuzz_clips (tests/fuzz/): a NaN rotation key in the binary buffer (which JSON cannot hold) loaded as a NaN
// pose; now the glTF loader refuses it and says where.
TEST(ClipErrors, NanKeyIsAnErrorNotANanPose) {
  // A .glb: the root translates over two keys, the chest turns; the chest's key 1 is given as `w`.
  auto clip_glb = [](float w) {
    std::string js =
        R"({"asset":{"version":"2.0"},"nodes":[{"name":"pelvis","children":[1]},{"name":"chest"}],)"
        R"("buffers":[{"byteLength":64}],"bufferViews":[{"buffer":0,"byteLength":8},)"
        R"({"buffer":0,"byteOffset":8,"byteLength":24},{"buffer":0,"byteOffset":32,"byteLength":32}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":2,"type":"SCALAR","min":[0],"max":[1]},)"
        R"({"bufferView":1,"componentType":5126,"count":2,"type":"VEC3"},)"
        R"({"bufferView":2,"componentType":5126,"count":2,"type":"VEC4"}],)"
        R"("animations":[{"name":"nan_key","extras":{"tags":["guard"],"loop":false},)"
        R"("channels":[{"sampler":0,"target":{"node":0,"path":"translation"}},)"
        R"({"sampler":1,"target":{"node":1,"path":"rotation"}}],)"
        R"("samplers":[{"input":0,"output":1},{"input":0,"output":2}]}]})";
    while (js.size() % 4) js += ' ';
    const float bin[16] = {0, 1, 0, 0.9f, 0, 0, 0.9f, 0, 0, 0, 0, 1, 0, 0, 0, w};
    auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    return "glTF" + u32(2) + u32(12 + 8 + static_cast<uint32_t>(js.size()) + 8 + 64) +
           u32(static_cast<uint32_t>(js.size())) + "JSON" + js + u32(64) + std::string("BIN\0", 4) +
           std::string(reinterpret_cast<const char*>(bin), 64);
  };
  auto load = [&](float w) -> eng::Result<std::vector<Clip>> {
    const std::string bytes = clip_glb(w);
    auto scene = eng::assets::load_gltf_memory(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(),
                                               "nan_key.glb");
    if (!scene) return eng::make_error(scene.error());
    return load_clips(*scene, boxer_skeleton());
  };
  auto good = load(1.0f);
  ASSERT_TRUE(good.ok()) << good.error();
  EXPECT_EQ(good->at(0).keys.size(), 2u);
  auto r = load(std::numeric_limits<float>::quiet_NaN());
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("nan_key.glb"), std::string::npos) << r.error();
  EXPECT_NE(r.error().find("element 1 is NaN or infinite"), std::string::npos) << r.error();
}

TEST(ClipErrors, ConverterNamesFileAndLine) {
  // make_clips.py validates the text form: an unknown bone is reported as file:line.
  const std::string d = tmp_dir();
  const std::string clip = d + "/bad.clip";
  std::ofstream(clip) << "name bad\ntags guard\nloop no\nkey 0\nroot 0 0 0.9 0\nkey 0.5\nroot 0 0 0.9 0\n"
                         "tail 1 2 3\n";
  const std::string out = d + "/bad.txt";
  const std::string cmd = "python3 " + std::string(BOXING_SOURCE_DIR) + "/scripts/content/make_clips.py --check " +
                          clip + " > " + out + " 2>&1";
  const int rc = std::system(cmd.c_str());
  if (rc == -1) BOXING_SKIP_OR_FAIL("cannot run python3 (scripts/deps installs it)");
  std::stringstream ss;
  ss << std::ifstream(out).rdbuf();
  EXPECT_NE(rc, 0);
  EXPECT_NE(ss.str().find("bad.clip:8"), std::string::npos) << ss.str();
  EXPECT_NE(ss.str().find("tail"), std::string::npos) << ss.str();

  std::ofstream(clip) << "name bad\ntags guard\nloop no\nkey 0\nroot 0 0 0.9\n";
  const int rc2 = std::system(cmd.c_str());
  std::stringstream s2;
  s2 << std::ifstream(out).rdbuf();
  EXPECT_NE(rc2, 0);
  EXPECT_NE(s2.str().find("bad.clip:5"), std::string::npos) << s2.str();
}

TEST(ClipContent, NoPopsInsideClips) {
  // No joint turns more than 0.7 rad between 30 Hz frames inside a clip (21 rad/s: the elbow of a
  // snapping jab); catches quaternion flips and IK branch switches in the converted content.
  for (const Clip& c : content_clips())
    for (double t = 0; t + 1.0 / 30 <= c.duration() + 1e-9; t += 1.0 / 30) {
      const Pose a = sample_clip_pose(c, t), b = sample_clip_pose(c, t + 1.0 / 30);
      for (int i = 0; i < 16; ++i)
        EXPECT_LT(quat_log(a.rotation[i].conjugate() * b.rotation[i]).norm(), 0.7) << c.name << " bone " << i << " t=" << t;
    }
}

TEST(ClipContent, BodyStaysAboveTheFloor) {
  // No joint centre sinks deeper under the floor than the thinnest limb's radius (the forearm capsule's 5 cm,
  // content/boxer/boxer.gltf): at that depth the limb still reaches up to the floor, so the tracking body's floor
  // contact holds it up and the pose is one the physics can come near; deeper, the whole limb would be under the
  // floor. measured (this test's lines, the content is fixed): every clip's lowest joint at +3.2 cm or higher
  // (standing clips: the ankles at +7.5-8.0 cm) but fall_forward's, its kneeling left knee at -3.2 cm at t=0.57 s.
  // (Before: "2 cm" in the comment, 4 cm asserted after that knee's 3 cm was seen, neither with a source.)
  constexpr double kThinnestLimbRadius = 0.05;  // m, forearm_l / forearm_r
  const Skeleton s = boxer_skeleton();
  for (const Clip& c : content_clips()) {
    double lowest = std::numeric_limits<double>::infinity(), at = 0.0;
    int joint = -1;
    for (double t = 0; t <= c.duration(); t += 1.0 / 60) {
      std::vector<Eigen::Vector3d> wp;
      std::vector<Eigen::Quaterniond> wr;
      forward_kinematics(s, sample_clip_pose(c, t), &wp, &wr);
      for (int i = 0; i < 16; ++i)
        if (wp[i].z() < lowest) lowest = wp[i].z(), at = t, joint = i;
    }
    std::printf("%-16s lowest joint %-12s %+.3f m at t=%.2f s\n", c.name.c_str(), joint >= 0 ? s.name[joint].c_str() : "-",
                lowest, at);
    EXPECT_GT(lowest, -kThinnestLimbRadius) << c.name << " " << (joint >= 0 ? s.name[joint] : "") << " t=" << at;
  }
}

TEST(ClipContent, SkeletonMatchesBoxerContent) {
  // boxer_skeleton() (tests/tools) and the clip file's nodes must agree with content/boxer/boxer.gltf.
  const Skeleton s = boxer_skeleton();
  for (const std::string rel : {"/content/boxer/boxer.gltf", "/content/clips/boxing_clips.gltf"}) {
    const std::string p = std::string(BOXING_SOURCE_DIR) + rel;
    if (!std::filesystem::exists(p)) continue;
    auto sc = eng::assets::load_gltf(p);
    ASSERT_TRUE(sc.ok()) << sc.error();
    for (int i = 0; i < s.size(); ++i) {
      const int n = sc->find_node(s.name[i]);
      ASSERT_GE(n, 0) << rel << ": " << s.name[i];
      const auto& node = sc->nodes[n];
      const std::string parent = node.parent >= 0 ? sc->nodes[node.parent].name : "";
      EXPECT_EQ(parent, s.parent[i] >= 0 ? s.name[s.parent[i]] : "") << rel << ": " << s.name[i];
      const Eigen::Vector3d off(node.translation.x, node.translation.y, node.translation.z);
      EXPECT_LT((off - s.offset[i]).norm(), 1e-5) << rel << ": " << s.name[i];
    }
  }
}
