// The committed content as other tools see it: the Khronos glTF-Validator's verdict on every file,
// the viewer .glb against the two files the game loads, and content/README.md against the loaders.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>

#include "engine/assets/character.h"
#include "engine/assets/gltf.h"
#include "test_paths.h"
#include "support/ci_env.h"

namespace {

namespace fs = std::filesystem;
const std::string kRoot = BOXING_SOURCE_DIR;

std::string read_text(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

struct Proc {
  int rc = -1;
  std::string output;
};

Proc run(const std::string& cmd) {
  Proc r;
  FILE* p = popen((cmd + " 2>&1").c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.output.append(buf.data(), n);
  const int status = pclose(p);
  r.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

bool in_ci() {
  const char* ci = std::getenv("CI");
  return ci && std::string(ci) != "" && std::string(ci) != "0" && std::string(ci) != "false";
}

std::vector<std::string> content_gltf_files() {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(kRoot + "/content"))
    if (e.is_regular_file() && (e.path().extension() == ".gltf" || e.path().extension() == ".glb"))
      out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Content, EveryGltfFileHasNoValidatorErrorsOrWarnings) {
  // scripts/content/validate.js runs the Khronos glTF-Validator (npm gltf-validator, installed by
  // scripts/deps into build/tools): exit 0 = every file clean, 1 = issues, 2 = validator missing.
  const std::vector<std::string> files = content_gltf_files();
  ASSERT_GE(files.size(), 3u);  // boxer.gltf, boxer.glb, boxing_clips.gltf
  std::string cmd = "node '" + kRoot + "/scripts/content/validate.js'";
  for (const auto& f : files) cmd += " '" + f + "'";
  const Proc r = run(cmd);
  if (r.rc == 2 || r.rc == 127 || r.rc == -1) {
    if (in_ci()) FAIL() << "the Khronos glTF-Validator is required in CI (scripts/deps installs it):\n" << r.output;
    GTEST_SKIP() << "glTF-Validator not installed (run scripts/deps): " << r.output;
  }
  EXPECT_EQ(r.rc, 0) << r.output;
  for (const auto& f : files) {  // each file reported, with zero counts
    const std::string line = f + " errors=0 warnings=0";
    EXPECT_NE(r.output.find(line), std::string::npos) << line << "\n" << r.output;
  }
}

TEST(Content, CommittedFilesAreWhatTheScriptsGenerate) {
  // One source of truth: the scripts. A stale file (e.g. clips converted against an older boxer) fails here.
  const std::string tmp = (fs::temp_directory_path() / ("content_test_" + std::to_string(::getpid()))).string();
  fs::create_directories(tmp);
  const Proc boxer = run("python3 '" + kRoot + "/scripts/content/make_boxer.py' '" + tmp + "/boxer.gltf'");
  if (boxer.rc == 127) BOXING_SKIP_OR_FAIL("no python3 (scripts/deps installs it)");
  ASSERT_EQ(boxer.rc, 0) << boxer.output;
  const Proc clips = run("python3 '" + kRoot + "/scripts/content/make_clips.py' --out '" + tmp + "/clips.gltf'");
  ASSERT_EQ(clips.rc, 0) << clips.output;
  EXPECT_EQ(read_text(tmp + "/boxer.gltf"), read_text(kRoot + "/content/boxer/boxer.gltf"))
      << "content/boxer/boxer.gltf is stale: run scripts/content/make_boxer.py";
  EXPECT_EQ(read_text(tmp + "/clips.gltf"), read_text(kRoot + "/content/clips/boxing_clips.gltf"))
      << "content/clips/boxing_clips.gltf is stale: run scripts/content/make_clips.py";
  fs::remove_all(tmp);
}

TEST(Content, ViewerGlbIsTheGameFilesMerged) {
  // make_glb.py --check: the committed .glb is byte for byte what the two .gltf files give.
  const Proc check = run("python3 '" + kRoot + "/scripts/content/make_glb.py' --check");
  if (check.rc == 127) BOXING_SKIP_OR_FAIL("no python3 (scripts/deps installs it)");
  EXPECT_EQ(check.rc, 0) << check.output;

  auto glb = eng::assets::load_gltf(kRoot + "/content/boxer/boxer.glb");
  auto boxer = eng::assets::load_gltf(kRoot + "/content/boxer/boxer.gltf");
  auto clips = eng::assets::load_gltf(kRoot + "/content/clips/boxing_clips.gltf");
  ASSERT_TRUE(glb.ok()) << glb.error();
  ASSERT_TRUE(boxer.ok()) << boxer.error();
  ASSERT_TRUE(clips.ok()) << clips.error();
  ASSERT_EQ(glb->nodes.size(), boxer->nodes.size());
  for (size_t i = 0; i < glb->nodes.size(); ++i) {
    const auto &a = glb->nodes[i], &b = boxer->nodes[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.children, b.children) << a.name;
    EXPECT_EQ(a.translation, b.translation) << a.name;
    EXPECT_EQ(a.rotation, b.rotation) << a.name;
    ASSERT_GE(a.mesh, 0) << a.name << " has no mesh to see";
    const auto &ma = glb->meshes[static_cast<size_t>(a.mesh)], &mb = boxer->meshes[static_cast<size_t>(b.mesh)];
    ASSERT_EQ(ma.primitives.size(), mb.primitives.size()) << a.name;
    for (size_t p = 0; p < ma.primitives.size(); ++p) {
      EXPECT_EQ(ma.primitives[p].positions, mb.primitives[p].positions) << a.name;
      EXPECT_EQ(ma.primitives[p].normals, mb.primitives[p].normals) << a.name;
      EXPECT_EQ(ma.primitives[p].indices, mb.primitives[p].indices) << a.name;
    }
  }
  // Every clip, by name, on the bone nodes of the same name, with the same keys and metadata.
  ASSERT_EQ(glb->animations.size(), clips->animations.size());
  ASSERT_EQ(glb->animations.size(), 24u);
  for (size_t i = 0; i < glb->animations.size(); ++i) {
    const auto &a = glb->animations[i], &b = clips->animations[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.extras, b.extras) << a.name;
    ASSERT_EQ(a.channels.size(), b.channels.size()) << a.name;
    for (size_t c = 0; c < a.channels.size(); ++c) {
      EXPECT_EQ(glb->nodes[static_cast<size_t>(a.channels[c].node)].name,
                clips->nodes[static_cast<size_t>(b.channels[c].node)].name);
      EXPECT_EQ(a.channels[c].path, b.channels[c].path);
      EXPECT_EQ(a.channels[c].times, b.channels[c].times) << a.name;
      EXPECT_EQ(a.channels[c].values, b.channels[c].values) << a.name;
    }
  }
}

// Every key the loaders read from extras: found in the loader sources by the call that reads it.
std::set<std::string> loader_keys(const std::string& source) {
  std::set<std::string> keys;
  const std::regex patterns[] = {
      std::regex(R"re((?:member|number|vec<\d>)\(\s*\w+,\s*"(\w+)")re"),  // character.cpp's readers
      std::regex(R"re(contains\("(\w+)"\))re"),
      std::regex(R"re(\["(\w+)"\])re"),
  };
  for (const auto& re : patterns)
    for (auto it = std::sregex_iterator(source.begin(), source.end(), re); it != std::sregex_iterator(); ++it)
      keys.insert((*it)[1].str());
  return keys;
}

TEST(Content, ReadmeDocumentsEveryExtrasFieldTheLoadersRead) {
  const std::string readme = read_text(kRoot + "/content/README.md");
  ASSERT_FALSE(readme.empty());
  const std::set<std::string> character = loader_keys(read_text(kRoot + "/engine/assets/character.cpp"));
  const std::set<std::string> clips = loader_keys(read_text(kRoot + "/engine/anim/clip.cpp"));
  // The scan finds what it should (so an empty set cannot pass by accident).
  for (const char* k : {"physics", "joint", "swing_limit", "inertia", "half_extents", "quat", "collision",
                        "group_bit", "exclude_pairs"})
    EXPECT_TRUE(character.count(k)) << k << " not found in character.cpp by the scan";
  for (const char* k : {"tags", "loop", "glove", "impact", "next"})
    EXPECT_TRUE(clips.count(k)) << k << " not found in clip.cpp by the scan";
  for (const auto* set : {&character, &clips})
    for (const std::string& k : *set)
      EXPECT_NE(readme.find("`" + k + "`"), std::string::npos)
          << "content/README.md does not document the extras field `" << k << "` the loader reads";
}

TEST(Content, ReadmeLimitsMatchTheBoxerFile) {
  // The skeleton table's joint limits are the file's: "swing S, twist T" per ball joint.
  const std::string readme = read_text(kRoot + "/content/README.md");
  auto s = eng::assets::load_gltf(kRoot + "/content/boxer/boxer.gltf");
  ASSERT_TRUE(s.ok()) << s.error();
  auto c = eng::assets::load_character(*s);
  ASSERT_TRUE(c.ok()) << c.error();
  for (int i = 0; i < c->skeleton.size(); ++i) {
    const auto& b = c->bones[static_cast<size_t>(i)];
    if (b.joint != "ball") continue;
    std::string name = c->skeleton.name[static_cast<size_t>(i)];
    if (name.size() > 2 && name[name.size() - 2] == '_') name = name.substr(0, name.size() - 2) + "_l/r";
    const std::regex row("\\| " + name + " \\|[^\\n]*swing ([0-9.]+), twist ([0-9.]+)");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(readme, m, row)) << "no skeleton row with limits for " << name;
    EXPECT_DOUBLE_EQ(std::stod(m[1].str()), b.swing_limit) << name << " swing limit";
    EXPECT_DOUBLE_EQ(std::stod(m[2].str()), b.twist_limit) << name << " twist limit";
  }
}

}  // namespace
