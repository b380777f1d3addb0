// Command-line parsing of build/boxing: good flags land in Options, every bad flag or value is one error line.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "game/cli.h"

using boxing::parse_cli;

TEST(Cli, DefaultsAreTheDocumentedOnes) {
  auto o = parse_cli({});
  ASSERT_TRUE(o.ok());
  EXPECT_EQ(o->width, 1280);
  EXPECT_EQ(o->height, 720);
  EXPECT_EQ(o->seed, 1u);
  EXPECT_EQ(o->scenario, "arena");
  EXPECT_FALSE(o->headless);
  EXPECT_TRUE(o->validation);
  EXPECT_EQ(o->root_spring, "auto");  // root help for the paper's boxers (graph-walk, match), not the balance lab
  EXPECT_LT(o->root_spring_max, 0.0);  // its limit by the balance layer (world.cpp)
}

TEST(Cli, ParsesEveryValueFlag) {
  auto o = parse_cli({"--headless", "--width", "640", "--height=360", "--seconds", "2.5", "--seed", "42",
                      "--scenario", "push", "--screenshot", "a.png", "--report", "r.json", "--servo",
                      "parent-meathook", "--push-dir", "90", "--push-force", "150", "--push-duration", "0.1",
                      "--push-at", "3", "--push-shape", "sine", "--camera", "closeup", "--ghost", "--render-every", "30", "--root-spring",
                      "on", "--root-spring-max", "80", "--audio-out", "out/m.wav"});
  ASSERT_TRUE(o.ok()) << o.error();
  EXPECT_TRUE(o->headless);
  EXPECT_EQ(o->width, 640);
  EXPECT_EQ(o->height, 360);
  EXPECT_DOUBLE_EQ(o->seconds, 2.5);
  EXPECT_EQ(o->seed, 42u);
  EXPECT_EQ(o->scenario, "push");
  EXPECT_EQ(o->screenshot, "a.png");
  EXPECT_EQ(o->report, "r.json");
  EXPECT_EQ(o->audio_out, "out/m.wav");
  EXPECT_EQ(o->servo, "parent-meathook");
  EXPECT_DOUBLE_EQ(o->push_dir_deg, 90.0);
  EXPECT_DOUBLE_EQ(o->push_force, 150.0);
  EXPECT_DOUBLE_EQ(o->push_at, 3.0);
  EXPECT_TRUE(o->push_sine);
  EXPECT_EQ(o->camera, "closeup");
  EXPECT_TRUE(o->ghost);
  EXPECT_EQ(o->render_every, 30);
  EXPECT_EQ(o->root_spring, "on");
  EXPECT_DOUBLE_EQ(o->root_spring_max, 80.0);
}

TEST(Cli, GraphSubcommandTakesReportAndDot) {
  auto o = parse_cli({"graph", "--report", "g.json", "--dot", "g.dot"});
  ASSERT_TRUE(o.ok()) << o.error();
  EXPECT_EQ(o->command, "graph");
  EXPECT_EQ(o->graph_report, "g.json");
  EXPECT_EQ(o->graph_dot, "g.dot");
}

// Each bad input gives an error that names the flag and points at --help.
struct BadCase {
  std::vector<std::string> args;
  std::string mentions;
};

TEST(Cli, RejectsBadFlagsAndValuesWithOneLine) {
  const std::vector<BadCase> cases = {
      {{"--bogus"}, "--bogus"},
      {{"--width", "abc"}, "--width"},
      {{"--width", "0"}, "--width"},
      {{"--width"}, "--width"},
      {{"--seconds", "-1"}, "--seconds"},
      {{"--seconds", "nan"}, "--seconds"},
      {{"--seed", "-3"}, "--seed"},
      {{"--scenario", "tennis"}, "tennis"},
      {{"--servo", "magic"}, "magic"},
      {{"--screenshot", "a.jpg"}, ".png"},
      {{"--audio-out", "a.mp3"}, ".wav"},
      {{"--audio-out"}, "--audio-out"},
      {{"--headless=yes"}, "--headless"},
      {{"--dot", "g.dot"}, "--dot"},
      {{"--root-spring", "maybe"}, "--root-spring"},
      {{"--root-spring-max", "-5"}, "--root-spring-max"},
      {{"--push-shape", "square"}, "--push-shape"},
  };
  for (const BadCase& c : cases) {
    auto o = parse_cli(c.args);
    ASSERT_FALSE(o.ok()) << c.args[0];
    EXPECT_NE(o.error().find(c.mentions), std::string::npos) << o.error();
    EXPECT_NE(o.error().find("--help"), std::string::npos) << o.error();
    EXPECT_EQ(o.error().find('\n'), std::string::npos) << "one line: " << o.error();
  }
}

TEST(Cli, HelpListsTheRequiredFlags) {
  const std::string h = boxing::help_text();
  for (const char* f : {"--headless", "--width", "--height", "--seconds", "--seed", "--screenshot", "--report",
                        "--scenario", "--servo", "--push-dir"})
    EXPECT_NE(h.find(f), std::string::npos) << f;
}

TEST(Cli, EveryScenarioNameParsesToItsEnumAndBack) {
  using boxing::Scenario;
  const std::pair<const char*, Scenario> names[] = {{"arena", Scenario::Arena},         {"ragdolls", Scenario::Ragdolls},
                                                    {"stand", Scenario::Stand},         {"push", Scenario::Push},
                                                    {"graph-walk", Scenario::GraphWalk}, {"match", Scenario::Match}};
  for (const auto& [name, id] : names) {
    auto o = parse_cli({"--scenario", name});
    ASSERT_TRUE(o.ok()) << name;
    EXPECT_EQ(o->scenario_id, id) << name;
    EXPECT_EQ(o->scenario, name);
    EXPECT_STREQ(boxing::scenario_name(id), name);
    // The help lists it.
    EXPECT_NE(boxing::help_text().find(name), std::string::npos) << name;
  }
  EXPECT_EQ(parse_cli({})->scenario_id, Scenario::Arena);
  EXPECT_FALSE(boxing::scenario_from_name("Arena").has_value()) << "names are the flag's, case and all";
}

TEST(Cli, ContactGapIsOffByDefaultAndParsedInMetres) {
  EXPECT_LT(parse_cli({})->contact_gap, 0.0) << "each foot-contact purpose keeps its own gap by default";
  auto o = parse_cli({"--contact-gap", "0.002"});
  ASSERT_TRUE(o.ok());
  EXPECT_DOUBLE_EQ(o->contact_gap, 0.002);
  auto bad = parse_cli({"--contact-gap", "0.5"});
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("--contact-gap"), std::string::npos);
}

namespace {
TEST(Cli, SteppingPlacementAndFlatParseAndRejectBadValues) {
  auto d = boxing::parse_cli({});
  ASSERT_TRUE(d.ok());
  EXPECT_EQ(d->stepping, "auto");
  EXPECT_EQ(d->step_placement, "capture");
  EXPECT_FALSE(d->flat);
  auto o = boxing::parse_cli({"--stepping", "off", "--step-placement", "ipc", "--flat"});
  ASSERT_TRUE(o.ok()) << o.error();
  EXPECT_EQ(o->stepping, "off");
  EXPECT_EQ(o->step_placement, "ipc");
  EXPECT_TRUE(o->flat);
  auto bad = boxing::parse_cli({"--stepping", "sometimes"});
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("--stepping must be on, off or auto"), std::string::npos) << bad.error();
  bad = boxing::parse_cli({"--step-placement", "lqr"});
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("--step-placement must be capture or ipc"), std::string::npos) << bad.error();
  EXPECT_FALSE(boxing::parse_cli({"--flat=1"}).ok());
  EXPECT_NE(boxing::help_text().find("--stepping"), std::string::npos);
}
}  // namespace

TEST(Cli, RenderScaleIsAutoByDefaultAndTakesAShareFromAQuarterToOne) {
  auto d = boxing::parse_cli({});
  ASSERT_TRUE(d.ok());
  EXPECT_EQ(d->render_scale, 0.0);  // auto: by device (renderer.h)
  auto o = boxing::parse_cli({"--render-scale", "0.5"});
  ASSERT_TRUE(o.ok()) << o.error();
  EXPECT_EQ(o->render_scale, 0.5);
  o = boxing::parse_cli({"--render-scale", "auto"});
  ASSERT_TRUE(o.ok()) << o.error();
  EXPECT_EQ(o->render_scale, 0.0);
  for (const char* v : {"0", "0.2", "1.5", "nan", "big"}) {
    auto bad = boxing::parse_cli({"--render-scale", v});
    ASSERT_FALSE(bad.ok()) << v;
    EXPECT_NE(bad.error().find("--render-scale must be auto or a number from 0.25 to 1"), std::string::npos) << bad.error();
  }
}

TEST(Cli, PresentIsAutoByDefaultAndTakesSwapchainOrShm) {
  auto d = boxing::parse_cli({});
  ASSERT_TRUE(d.ok());
  EXPECT_EQ(d->present, "auto");
  for (const char* v : {"auto", "swapchain", "shm"}) {
    auto o = boxing::parse_cli({"--present", v});
    ASSERT_TRUE(o.ok()) << o.error();
    EXPECT_EQ(o->present, v);
  }
  for (const char* v : {"", "x11", "SHM"}) {
    auto bad = boxing::parse_cli({"--present", v});
    ASSERT_FALSE(bad.ok()) << v;
    EXPECT_NE(bad.error().find("--present must be auto, swapchain or shm"), std::string::npos) << bad.error();
  }
}

TEST(Cli, ModeAiAndRestSecondsParseAndRejectBadValuesNamingTheFix) {
  auto d = parse_cli({});
  ASSERT_TRUE(d.ok());
  EXPECT_EQ(d->mode, "");  // the window opens the title screen
  EXPECT_EQ(d->ai, (std::array<std::string, 2>{"normal", "normal"}));
  EXPECT_DOUBLE_EQ(d->rest_seconds, 60.0);
  EXPECT_FALSE(d->scenario_given);
  auto o = parse_cli({"--mode", "play", "--ai", "hard", "--rest-seconds", "2"});
  ASSERT_TRUE(o.ok()) << o.error();
  EXPECT_EQ(o->mode, "play");
  EXPECT_EQ(o->ai, (std::array<std::string, 2>{"hard", "hard"}));  // one level: both boxers
  EXPECT_DOUBLE_EQ(o->rest_seconds, 2.0);
  auto two = parse_cli({"--ai", "easy,hard", "--scenario", "match"});
  ASSERT_TRUE(two.ok()) << two.error();
  EXPECT_EQ(two->ai, (std::array<std::string, 2>{"easy", "hard"}));  // red's, blue's
  EXPECT_TRUE(two->scenario_given);
  for (const auto& [args, says] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--ai", "brutal"}, "--ai takes easy, normal or hard"},
           {{"--ai", "easy,"}, "--ai takes easy, normal or hard"},
           {{"--ai", "easy,hard,normal"}, "--ai takes easy, normal or hard"},
           {{"--mode", "arcade"}, "--mode must be watch, play, versus or sandbox"},
           {{"--rest-seconds", "0"}, "--rest-seconds must be a number from 1 to 600"},
           {{"--mode", "watch", "--scenario", "stand"}, "--mode and --scenario both choose what runs"}}) {
    auto bad = parse_cli(args);
    ASSERT_FALSE(bad.ok()) << args[0] << " " << args[1];
    EXPECT_NE(bad.error().find(says), std::string::npos) << bad.error();
    EXPECT_NE(bad.error().find("--help"), std::string::npos) << bad.error();
  }
}
