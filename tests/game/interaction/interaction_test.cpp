// The player's hands, headless (game/interaction/interaction.h): drags pull the grabbed point and the boxer recovers,
// a press bends the knees and the boxer stands back up, beach balls do not floor a boxer and a crate does, violent
// drags keep the simulation bounded, and a session's recorded events replay bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "game/cli.h"
#include "game/interaction/interaction.h"
#include "game/world.h"
#include "test_paths.h"

using boxing::InputEvent;
using boxing::InputKind;
using boxing::World;

namespace {

std::unique_ptr<World> make(const std::vector<std::string>& args, std::vector<InputEvent> script = {}) {
  auto o = boxing::parse_cli(args);
  EXPECT_TRUE(o.ok()) << o.error();
  auto w = boxing::make_world(*o);
  EXPECT_TRUE(w.ok()) << w.error();
  // As --input does: after the scenario's own schedule (impacts), in time order.
  auto& in = (*w)->interaction->script;
  in.insert(in.end(), script.begin(), script.end());
  std::stable_sort(in.begin(), in.end(), [](const InputEvent& a, const InputEvent& b) { return a.t < b.t; });
  return std::move(*w);
}

void run_until(World& w, double t) {
  while (w.data.time < t - 1e-9) boxing::step_world(w);
}

InputEvent drag(double t, int boxer, const char* bone, Eigen::Vector3d offset, double duration, bool strong = false) {
  InputEvent e;
  e.kind = InputKind::Drag;
  e.t = t;
  e.boxer = boxer;
  e.bone = bone;
  e.vec = offset;
  e.duration = duration;
  e.strong = strong;
  return e;
}

// A throw of a ball or crate from a point with a velocity (world), at t.
InputEvent throw_from(double t, boxing::ObjectKind kind, Eigen::Vector3d from, Eigen::Vector3d velocity) {
  InputEvent e;
  e.kind = InputKind::Throw;
  e.t = t;
  e.object_kind = kind;
  e.from = from;
  e.velocity = velocity;
  return e;
}

int body_of(const World& w, int boxer, const char* bone) {
  return w.boxers[boxer].bodies.body[w.boxer_desc.skeleton.find(bone)];
}

// The knee's flexion: the angle between the thigh's and the shank's long axes (their bone frames' z), rad.
double knee_flexion(const World& w, int boxer, int side) {
  const char* thigh[2] = {"thigh_l", "thigh_r"};
  const char* shank[2] = {"shank_l", "shank_r"};
  const Eigen::Vector3d a = w.data.x[body_of(w, boxer, thigh[side])].R.col(2);
  const Eigen::Vector3d b = w.data.x[body_of(w, boxer, shank[side])].R.col(2);
  return std::acos(std::clamp(a.dot(b), -1.0, 1.0));
}

}  // namespace

// The figure: the head pulled 0.35 m sideways for 1 s follows at least 0.2 m (the spring's force is capped
// at 450 N: the servo and the balance QP push back), and the boxer is still up 4 s after the release. Both sides,
// three stances.
TEST(Interaction, HeadDraggedSidewaysFollowsTheTargetAndTheBoxerRecovers) {
  for (int seed = 1; seed <= 3; ++seed)
    for (double side : {-1.0, 1.0}) {
      auto w = make({"--scenario", "stand", "--seed", std::to_string(seed)},
                    {drag(2.0, 0, "head", Eigen::Vector3d(0.0, 0.35 * side, 0.0), 1.0)});
      run_until(*w, 7.0);
      ASSERT_EQ(w->interaction->drag_log.size(), 1u);
      const auto& d = w->interaction->drag_log[0];
      EXPECT_GE(d.max_displacement, 0.2) << "seed " << seed << " side " << side;
      EXPECT_LE(d.peak_force, boxing::kDragNormal.max_force + 1e-6);
      EXPECT_NEAR(d.released_at, 3.0, 1e-9);
      EXPECT_FALSE(w->boxers[0].metrics.fell) << "seed " << seed << " side " << side << ": fell at "
                                              << w->boxers[0].metrics.fell_at;
    }
}

// The paper: "When pressed into the ground, the humanoid bends at the knees and then stands upright when released."
// The chest pressed 0.3 m down for 1.5 s: the knees flex by over 15 degrees more and the pelvis sinks; 3.5 s after
// the release the pelvis is back within 3 cm of its height before and the boxer never fell.
TEST(Interaction, ChestPressedDownBendsTheKneesAndTheBoxerStandsBackUp) {
  for (int seed = 1; seed <= 3; ++seed) {
    auto w = make({"--scenario", "stand", "--seed", std::to_string(seed)},
                  {drag(2.0, 0, "chest", Eigen::Vector3d(0.0, 0.0, -0.3), 1.5)});
    const int pelvis = body_of(*w, 0, "pelvis");
    run_until(*w, 2.0);
    const double z0 = w->data.x[pelvis].p.z();
    const double knee0 = knee_flexion(*w, 0, 0) + knee_flexion(*w, 0, 1);
    double zmin = z0, knee_max = knee0;
    while (w->data.time < 3.5) {
      boxing::step_world(*w);
      zmin = std::min(zmin, w->data.x[pelvis].p.z());
      knee_max = std::max(knee_max, knee_flexion(*w, 0, 0) + knee_flexion(*w, 0, 1));
    }
    run_until(*w, 7.0);
    const double z1 = w->data.x[pelvis].p.z();
    EXPECT_GT(0.5 * (knee_max - knee0), 15.0 * M_PI / 180.0) << "seed " << seed << ": knees flexed by (mean, deg) "
                                                               << 0.5 * (knee_max - knee0) * 180 / M_PI;
    EXPECT_GT(z0 - zmin, 0.08) << "seed " << seed;
    EXPECT_NEAR(z1, z0, 0.03) << "seed " << seed;
    EXPECT_FALSE(w->boxers[0].metrics.fell) << "seed " << seed;
  }
}

// The paper's Fig. 7 (--scenario impacts): five beach balls at 8 m/s hit each of the three boxers and none falls;
// then a 25 kg crate at 8 m/s floors each of them.
TEST(Interaction, BeachBallsDoNotFloorABoxerACrateAtEightMetresPerSecondDoes) {
  auto w = make({"--scenario", "impacts", "--seed", "1"});
  run_until(*w, 9.0);
  nlohmann::json r = boxing::world_report(*w);
  const auto& boxers = r["impacts"]["boxers"];
  ASSERT_EQ(boxers.size(), 3u);
  for (const auto& b : boxers) {
    EXPECT_GE(b["ball_hits"].get<int>(), 3) << b.dump();
    EXPECT_TRUE(b["stayed_up_after_balls"].get<bool>()) << b.dump();
    EXPECT_GE(b["crate_hits"].get<int>(), 1) << b.dump();  // its crate (a neighbour's may bounce into it too)
    EXPECT_FALSE(b["stayed_up"].get<bool>()) << b.dump();
  }
  // The root-spring boxer's consciousness fell with the crate's blow.
  EXPECT_LT(boxers[2]["consciousness"].get<double>(), 0.6);
  EXPECT_EQ(r["interaction"]["objects_thrown"].get<int>(), 18);
}

// Thrown balls are bouncy and settle: a ball dropped onto the floor comes back up, then lies still on it.
TEST(Interaction, AThrownBallBouncesRollsAndSettlesOnTheFloor) {
  const InputEvent t =
      throw_from(0.5, boxing::ObjectKind::Ball, Eigen::Vector3d(0.0, -2.5, 2.0), Eigen::Vector3d(0.0, -1.0, 0.0));
  auto w = make({"--scenario", "stand", "--seed", "1"}, {t});
  const int ball = w->interaction->objects[0].body;
  run_until(*w, 0.6);
  EXPECT_TRUE(w->interaction->objects[0].live);
  bool bounced = false, fell = false;
  while (w->data.time < 12.0) {
    boxing::step_world(*w);
    const double vz = w->data.v[w->model.bodies[ball].v_index + 2];
    fell = fell || vz < -3.0;
    bounced = bounced || (fell && vz > 2.0);
  }
  EXPECT_TRUE(bounced);
  EXPECT_NEAR(w->data.q[w->model.bodies[ball].q_index + 2], boxing::kBall.radius, 0.01);
  EXPECT_LT(w->data.v.segment(w->model.bodies[ball].v_index, 3).norm(), 0.05);
}

// A throw whose starting point is inside a boxer (chaos's throws start 3 m in front of their target, where the other
// boxer may lie) starts above the boxer's geoms instead: the first contacts are shallow. Started where it was asked,
// inside the chest, the ball's contacts were 36 cm deep (chaos seed 2's ball and crate, in a lying boxer: 10-17 cm).
TEST(Interaction, AThrowStartingInsideABoxerAppearsAboveIt) {
  auto probe = make({"--scenario", "stand", "--seed", "1"});
  run_until(*probe, 0.5);
  const Eigen::Vector3d chest = probe->data.com_world[body_of(*probe, 0, "chest")];
  const InputEvent t = throw_from(0.5, boxing::ObjectKind::Ball, chest, Eigen::Vector3d(0.0, 1.0, 0.0));
  auto w = make({"--scenario", "stand", "--seed", "1"}, {t});
  const int ball = w->interaction->objects[0].body;
  run_until(*w, 0.5);
  boxing::step_world(*w);  // the throw
  EXPECT_TRUE(w->interaction->objects[0].live);
  EXPECT_GT(w->data.x[ball].p.z(), chest.z() + boxing::kBall.radius);
  double deepest = 0.0;
  for (int i = 0; i < 24; ++i) {
    boxing::step_world(*w);
    for (const auto& c : w->data.contacts)
      if (c.body_a == ball || c.body_b == ball) deepest = std::max(deepest, c.point.depth);
  }
  EXPECT_LT(deepest, 0.03);
}

// 50 random violent drags (random bone, 0.5-2 m offsets, normal or strong spring, 0.15-0.5 s) per seed, seeds 1-5,
// boxers and a thrown crate: every step finite, no boxer body faster than 30 m/s, no body centre inside a crate of
// the arena or under the floor.
TEST(Interaction, ViolentRandomDragsKeepTheSimulationFiniteAndOutOfTheCrates) {
  for (int seed = 1; seed <= 5; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto w0 = make({"--scenario", "stand", "--seed", std::to_string(seed)});
    const auto& names = w0->boxer_desc.skeleton.name;
    std::vector<InputEvent> script;
    double t = 1.0;
    for (int k = 0; k < 50; ++k) {
      Eigen::Vector3d dir(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.4);
      dir = dir.normalized() * (0.5 + 1.5 * u(rng));
      const double dur = 0.15 + 0.35 * u(rng);
      script.push_back(drag(t, int(u(rng) * 2), names[size_t(u(rng) * names.size()) % names.size()].c_str(), dir, dur,
                            u(rng) < 0.5));
      t += dur + 0.1;
    }
    InputEvent crate;
    crate.kind = InputKind::Throw;
    crate.t = 3.0;
    crate.object_kind = boxing::ObjectKind::Crate;
    crate.at_boxer = 1;
    crate.speed = 8.0;
    script.push_back(crate);
    std::stable_sort(script.begin(), script.end(), [](const InputEvent& a, const InputEvent& b) { return a.t < b.t; });
    auto w = make({"--scenario", "stand", "--seed", std::to_string(seed)}, script);
    double max_speed = 0.0, worst_inside = 0.0;
    std::string fastest;
    bool finite = true;
    while (w->data.time < t + 1.0 && finite) {
      boxing::step_world(*w);
      finite = w->data.q.allFinite() && w->data.v.allFinite();
      for (int b = 1; b < int(w->model.bodies.size()); ++b) {
        const Eigen::Vector3d c = w->data.com_world[b];
        const bool pooled_object = w->interaction->owners[b].boxer < 0;
        if (!pooled_object) {
          const auto& v = w->data.v_body[b];  // [omega; v at the world origin]
          const double speed = (v.tail<3>() + v.head<3>().cross(c)).norm();
          if (speed > max_speed) max_speed = speed, fastest = w->model.bodies[b].name + " at t = " + std::to_string(w->data.time);
        }
        if (pooled_object && c.z() > 20.0) continue;  // parked
        worst_inside = std::max(worst_inside, -c.z());
        for (const boxing::Crate& cr : w->arena.crates) {
          const Eigen::Vector3d d = cr.half_extents - (c - cr.center).cwiseAbs();
          if ((d.array() > 0.0).all()) worst_inside = std::max(worst_inside, d.minCoeff());
        }
      }
    }
    std::string last_drags;
    for (const InputEvent& e : script)
      if (e.t <= w->data.time && e.t > w->data.time - 1.0)
        last_drags += boxing::input_event_json(e).dump() + "\n";
    EXPECT_TRUE(finite) << "seed " << seed << " at t = " << w->data.time << " after\n" << last_drags;
    EXPECT_LT(max_speed, 30.0) << "seed " << seed << ": " << fastest;
    EXPECT_LT(worst_inside, 0.02) << "seed " << seed << ": a body centre inside a crate / under the floor by (m)";
    EXPECT_EQ(int(w->interaction->drag_log.size()), 50) << "seed " << seed;
  }
}

// A window session as the world sees it: the mouse's grab / moves / release, a throw, a push and a panel setting
// submitted between frames (interaction_submit), recorded; the recording played as a script gives the same run, every
// coordinate bit for bit.
TEST(Interaction, RecordedSessionReplaysBitForBit) {
  auto a = make({"--scenario", "stand", "--seed", "2", "--record", "unused.json"});
  ASSERT_TRUE(a->interaction->recording);
  const int frames = 6 * 60;
  for (int f = 0; f < frames; ++f) {
    World& w = *a;
    if (f == 60) {
      InputEvent g;
      g.kind = InputKind::Grab;
      g.boxer = 1;
      g.bone = "hand_r";
      g.point = Eigen::Vector3d(0.01, 0.0, -0.02);
      boxing::interaction_submit(w, g);
    }
    if (f > 60 && f < 120) {
      InputEvent m;
      m.kind = InputKind::Move;
      m.vec = w.data.x[body_of(w, 1, "hand_r")].p + Eigen::Vector3d(0.0, 0.004 * (f - 60), 0.002);
      boxing::interaction_submit(w, m);
    }
    if (f == 120) {
      InputEvent r;
      r.kind = InputKind::Release;
      boxing::interaction_submit(w, r);
    }
    if (f == 150) {
      InputEvent t;
      t.kind = InputKind::Throw;
      t.object_kind = boxing::ObjectKind::Ball;
      t.at_boxer = 0;
      t.speed = 9.0;
      boxing::interaction_submit(w, t);
    }
    if (f == 200) {
      InputEvent s;
      s.kind = InputKind::Set;
      s.boxer = 0;
      s.servo = "person";
      s.balance = "pd";
      boxing::interaction_submit(w, s);
    }
    if (f == 230) {
      InputEvent p;
      p.kind = InputKind::Push;
      p.boxer = 0;
      p.vec = Eigen::Vector3d(0.0, 120.0, 0.0);
      p.duration = 0.1;
      boxing::interaction_submit(w, p);
    }
    for (int s = 0; s < boxing::kStepsPerFrame; ++s) boxing::step_world(w);
  }
  const auto& recorded = a->interaction->recorded;
  EXPECT_EQ(int(recorded.size()), 1 + 59 + 1 + 1 + 1 + 1);
  // Through the file form, as --record / --input do.
  const std::string path = std::string(BOXING_BINARY_DIR) + "/interaction_replay.json";
  ASSERT_TRUE(boxing::write_input_file(path, recorded).ok());
  auto loaded = boxing::load_input_file(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  auto b = make({"--scenario", "stand", "--seed", "2"}, *loaded);
  run_until(*b, a->data.time);
  EXPECT_EQ(b->steps, a->steps);
  ASSERT_EQ(b->data.q.size(), a->data.q.size());
  for (int i = 0; i < a->data.q.size(); ++i) ASSERT_EQ(b->data.q[i], a->data.q[i]) << "coordinate " << i;
  for (int i = 0; i < a->data.v.size(); ++i) ASSERT_EQ(b->data.v[i], a->data.v[i]) << "velocity " << i;
  EXPECT_EQ(boxing::interaction_report(*b).dump(), boxing::interaction_report(*a).dump());
  EXPECT_EQ(b->boxers[0].settings.space, eng::control::ServoSpace::Person);
  EXPECT_FALSE(b->boxers[0].uses_qp());
}

// The hands hold thrown objects too: a grabbed ball follows its target, and clear() lets go of it and parks it.
TEST(Interaction, AGrabbedBallFollowsTheTargetAndClearLetsGoAndParksIt) {
  const InputEvent t = throw_from(0.5, boxing::ObjectKind::Ball, Eigen::Vector3d(0.0, -2.0, 0.3), Eigen::Vector3d::Zero());
  InputEvent g;
  g.kind = InputKind::Grab;
  g.t = 2.0;
  g.object = 0;
  InputEvent m;
  m.kind = InputKind::Move;
  m.t = 2.1;
  m.vec = Eigen::Vector3d(0.5, -2.0, 1.2);
  InputEvent c;
  c.kind = InputKind::Clear;
  c.t = 4.0;
  auto w = make({"--scenario", "stand", "--seed", "1"}, {t, g, m, c});
  const int ball = w->interaction->objects[0].body;
  run_until(*w, 3.5);
  EXPECT_TRUE(w->interaction->drags[0].active);
  EXPECT_LT((w->data.com_world[ball] - m.vec).norm(), 0.05);  // held at the target against gravity
  run_until(*w, 4.1);
  EXPECT_FALSE(w->interaction->drags[0].active);
  EXPECT_FALSE(w->interaction->objects[0].live);
  EXPECT_GT(w->data.com_world[ball].z(), 3.0);  // parked, away from the arena
}

// The player's hands act through a handled boxer on the other: boxer 1's chest dragged into boxer 0 in the match hands
// boxer 0 over too (BoxerControlState::handled_until: Kudoh's priorities off, its joints under the soft speed limit,
// world.cpp mark_handled_boxers) while they touch, though no hand was ever on boxer 0; before the drag neither is.
TEST(Interaction, ABoxerStruckByADraggedBoxerIsHandledTooAndItsJointsAreSpeedLimited) {
  // (At fighting range: from the ring's marks 2.8 m apart the drag's 0.9 m never brings boxer 1 to boxer 0.)
  auto w0 = make({"--scenario", "match", "--seed", "1", "--start-apart", "1.0"});
  const Eigen::Vector3d p0 = w0->data.x[w0->boxers[0].bodies.body[0]].p, p1 = w0->data.x[w0->boxers[1].bodies.body[0]].p;
  Eigen::Vector3d toward = p0 - p1;
  toward.z() = 0.0;
  auto w = make({"--scenario", "match", "--seed", "1", "--start-apart", "1.0"},
                {drag(0.5, 1, "chest", 0.9 * toward.normalized(), 0.8, true)});
  bool handled_before = false, handled_by_contact = false, limited = false;
  while (w->data.time < 0.5 - 1e-9) {
    boxing::step_world(*w);
    handled_before = handled_before || w->data.time < w->boxers[0].ctl.handled_until || w->data.time < w->boxers[1].ctl.handled_until;
  }
  while (w->data.time < 1.5 && !handled_by_contact) {
    boxing::step_world(*w);
    handled_by_contact = w->data.time < w->boxers[0].ctl.handled_until;
  }
  if (handled_by_contact) {
    boxing::step_world(*w);  // the limits are written before the next step's first half
    limited = w->model.bodies[w->boxers[0].bodies.body[5]].max_speed == boxing::kLimpJointMaxSpeed;
  }
  EXPECT_FALSE(handled_before);
  EXPECT_TRUE(handled_by_contact) << "boxer 1 dragged into boxer 0 for 0.8 s, boxer 0 never handled";
  EXPECT_TRUE(limited);
}
