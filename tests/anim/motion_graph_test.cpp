// Motion graph construction, pruning, steering and the random walk.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <queue>
#include <random>
#include <set>

#include "anim/anim_test_util.h"
#include "engine/anim/motion_graph.h"
#include "game/boxing_motion.h"
#include "test_paths.h"

using namespace eng::anim;
using Eigen::Quaterniond;
using Eigen::Vector3d;

namespace {

const MotionGraph& graph() {
  static const MotionGraph g = [] {
    MotionGraph m;
    const Skeleton sk = anim_test::boxer_skeleton();
    m.build(anim_test::content_clips(), GraphOptions{}, boxing::boxing_graph_options(sk), sk);
    return m;
  }();
  return g;
}

double angle_between(const Quaterniond& a, const Quaterniond& b) { return quat_log(a.conjugate() * b).norm(); }

// Largest per-frame (30 Hz) joint rotation change inside the clips themselves.
double clip_max_step() {
  double m = 0;
  for (const Clip& c : anim_test::content_clips())
    for (double t = 0; t + 1.0 / 30 <= c.duration() + 1e-9; t += 1.0 / 30) {
      const Pose a = sample_clip_pose(c, t), b = sample_clip_pose(c, t + 1.0 / 30);
      for (int i = 1; i < 16; ++i) m = std::max(m, angle_between(a.rotation[i], b.rotation[i]));
    }
  return m;
}

}  // namespace

TEST(Align2D, RecoversKnownRigidMotion) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<Vector3d> b, a;
  Align2D T;
  T.theta = 0.83;
  T.tx = 1.7;
  T.ty = -0.4;
  for (int i = 0; i < 40; ++i) {
    b.emplace_back(U(rng), U(rng), 1 + U(rng));
    a.push_back(T.apply(b.back()));
  }
  const Align2D r = align_2d(a, b);
  EXPECT_NEAR(r.theta, 0.83, 1e-9);
  EXPECT_NEAR(r.tx, 1.7, 1e-9);
  EXPECT_NEAR(r.ty, -0.4, 1e-9);
  // noisy heights do not disturb the floor alignment
  for (auto& p : a) p.z() += 0.3;
  const Align2D r2 = align_2d(a, b);
  EXPECT_NEAR(r2.theta, 0.83, 1e-9);
  // composition
  Align2D S;
  S.theta = -0.3;
  S.tx = 0.2;
  const Vector3d p(0.3, -0.7, 0.5);
  EXPECT_LT((T.then(S).apply(p) - T.apply(S.apply(p))).norm(), 1e-12);
}

TEST(MotionGraph, BuildsAndReports) {
  const MotionGraph& g = graph();
  ASSERT_GE(g.clips.size(), 16u);
  EXPECT_GT(g.transitions, 20);
  EXPECT_GT(g.scc_size, static_cast<int>(g.nodes.size()) / 2);
  const auto r = graph_report(g);
  EXPECT_EQ(r["frames"].get<int>(), static_cast<int>(g.nodes.size()));
  EXPECT_TRUE(r["scc"]["tags_missing"].empty()) << r.dump(1);
  const std::string dot = graph_dot(g);
  EXPECT_NE(dot.find("digraph"), std::string::npos);
  EXPECT_NE(dot.find("\"guard\" -> \"jab\""), std::string::npos) << dot;
  std::printf("graph: %d frames, %d transitions (%d before pruning), SCC %d frames, mean window rms %.3f m\n",
              static_cast<int>(g.nodes.size()), g.transitions, g.transitions_before_prune, g.scc_size, g.mean_rms);
}

TEST(MotionGraph, PunchesGuardAndGetupsInScc) {
  const MotionGraph& g = graph();
  for (size_t c = 0; c < g.clips.size(); ++c) {
    const Clip& clip = g.clips[c];
    if (!(clip.has_tag("punch") || clip.has_tag("getup") || clip.has_tag("guard"))) continue;
    for (int f = 0; f < g.frame_count[c]; ++f)
      EXPECT_TRUE(g.alive[g.node(static_cast<int>(c), f)]) << clip.name << " frame " << f;
  }
  for (const char* n : {"getup_back", "getup_front", "guard", "jab", "cross"}) EXPECT_GE(g.clip_index(n), 0) << n;
}

TEST(MotionGraph, NoDeadEnds) {
  const MotionGraph& g = graph();
  for (size_t v = 0; v < g.nodes.size(); ++v) {
    if (!g.alive[v]) continue;
    bool out = false;
    for (const auto& e : g.edges[v]) {
      EXPECT_TRUE(g.alive[e.to]);
      out |= e.kind != EdgeKind::Knockdown;
    }
    EXPECT_TRUE(out) << g.clips[g.nodes[v].clip].name << " " << g.nodes[v].frame;
  }
}

TEST(MotionGraph, DownFramesReachGuardOnlyThroughGetup) {
  const MotionGraph& g = graph();
  const int guard = g.clip_index("guard");
  ASSERT_GE(guard, 0);
  const int N = static_cast<int>(g.nodes.size());
  int down_clips = 0;
  for (size_t c = 0; c < g.clips.size(); ++c) {
    if (!g.clips[c].has_tag("down")) continue;
    ++down_clips;
    for (int f = 0; f < g.frame_count[c]; ++f) {
      // BFS over (node, visited a getup clip) without knockdown edges
      std::vector<char> seen(2 * N, 0);
      std::queue<std::pair<int, int>> q;
      q.push({g.node(static_cast<int>(c), f), 0});
      bool via_getup = false, bypass = false;
      while (!q.empty()) {
        auto [v, got] = q.front();
        q.pop();
        if (seen[2 * v + got]) continue;
        seen[2 * v + got] = 1;
        const int vc = g.nodes[v].clip;
        got |= g.clips[vc].has_tag("getup");
        if (vc == guard) {
          (got ? via_getup : bypass) = true;
          continue;
        }
        for (const auto& e : g.edges[v])
          if (e.kind != EdgeKind::Knockdown) q.push({e.to, got});
      }
      EXPECT_TRUE(via_getup) << g.clips[c].name << " frame " << f;
      EXPECT_FALSE(bypass) << g.clips[c].name << " frame " << f;
    }
  }
  EXPECT_EQ(down_clips, 2);
}

// Bound for the no-pop test: a 30 Hz step of any joint may not exceed the largest step found inside
// the authored clips by more than 25% + 0.05 rad (the transitions and knockdown blends add no pops),
// and never more than 0.8 rad (46 deg per frame = 24 rad/s, faster than any punch).
TEST(GraphWalker, TenMinuteWalkHasNoPops) {
  const MotionGraph& g = graph();
  const double own = clip_max_step();
  const double bound = std::min(0.8, 1.25 * own + 0.05);
  std::printf("largest per-frame joint step in the clips %.3f rad, bound %.3f rad\n", own, bound);
  GraphWalker w(g, 12345);
  const double dt = 1.0 / 30;
  PoseSample prev = w.tick(dt);
  double worst = 0, worst_root = 0;
  std::map<std::string, int> seen;
  int transitions_taken = 0;
  std::string last = w.current_clip();
  for (int i = 1; i < 30 * 600; ++i) {
    if (i % 1500 == 700) w.force_clip(i % 3000 == 700 ? "fall_back" : "fall_forward");
    if (i % 600 == 300) w.force_clip(i % 1800 == 300 ? "hit_head" : i % 1800 == 900 ? "hit_body" : "stagger");
    if (i % 400 == 100) w.request_tag("punch");
    if (i % 900 == 450) w.request_clip("block_high");
    const PoseSample s = w.tick(dt);
    ASSERT_TRUE(g.alive[w.current_node()]) << "left the graph at " << w.current_clip();
    for (int b = 1; b < 16; ++b) worst = std::max(worst, angle_between(prev.pose.rotation[b], s.pose.rotation[b]));
    worst_root = std::max(worst_root, angle_between(prev.pose.rotation[0], s.pose.rotation[0]));
    EXPECT_LT((s.pose.root_position - prev.pose.root_position).norm(), 0.2) << i;
    for (const auto& v : s.angular_velocity) ASSERT_TRUE(v.allFinite());
    ++seen[w.current_clip()];
    if (w.current_clip() != last) ++transitions_taken;
    last = w.current_clip();
    prev = s;
  }
  std::printf("walk: worst joint step %.3f rad, worst root step %.3f rad, %d clip changes, %zu clips seen\n", worst,
              worst_root, transitions_taken, seen.size());
  EXPECT_LE(worst, bound);
  EXPECT_LE(worst_root, bound);
  EXPECT_GE(seen.size(), 20u);
  EXPECT_GT(seen["getup_back"], 0);
  EXPECT_GT(seen["getup_front"], 0);
}

TEST(GraphWalker, SameSeedSameWalk) {
  const MotionGraph& g = graph();
  GraphWalker a(g, 99), b(g, 99), c(g, 100);
  bool differs = false;
  for (int i = 0; i < 30 * 60; ++i) {
    if (i == 500) {
      a.force_clip("fall_back");
      b.force_clip("fall_back");
      c.force_clip("fall_back");
    }
    const PoseSample x = a.tick(1.0 / 30), y = b.tick(1.0 / 30), z = c.tick(1.0 / 30);
    ASSERT_EQ(a.current_clip(), b.current_clip());
    ASSERT_EQ(0, std::memcmp(x.pose.root_position.data(), y.pose.root_position.data(), 3 * sizeof(double)));
    for (int k = 0; k < 16; ++k) {
      ASSERT_EQ(0, std::memcmp(x.pose.rotation[k].coeffs().data(), y.pose.rotation[k].coeffs().data(), 4 * sizeof(double)));
      ASSERT_EQ(0, std::memcmp(x.angular_velocity[k].data(), y.angular_velocity[k].data(), 3 * sizeof(double)));
    }
    differs |= (x.pose.root_position - z.pose.root_position).norm() > 1e-6;
  }
  EXPECT_TRUE(differs);
}

TEST(GraphWalker, RequestReachesTaggedClip) {
  const MotionGraph& g = graph();
  for (const char* tag : {"punch", "defence", "footwork"}) {
    GraphWalker w(g, 5);
    w.transition_probability = 0.0;
    for (int i = 0; i < 20; ++i) w.tick(1.0 / 30);
    ASSERT_TRUE(w.request_tag(tag)) << tag;
    bool reached = false;
    for (int i = 0; i < 90 && !reached; ++i) {
      w.tick(1.0 / 30);
      reached = g.clips[g.clip_index(w.current_clip())].has_tag(tag);
    }
    EXPECT_TRUE(reached) << tag;
  }
  GraphWalker w(g, 6);
  ASSERT_TRUE(w.request_clip("rear_uppercut"));
  bool reached = false;
  for (int i = 0; i < 120 && !reached; ++i) {
    w.tick(1.0 / 30);
    reached = w.current_clip() == "rear_uppercut";
  }
  EXPECT_TRUE(reached);
  EXPECT_FALSE(w.request_clip("no_such_clip"));
}

// A request is done once the walk is in the requested clip: with no random transitions and guard looping, the clip is
// played once and the walk stays in guard after it (the target kept, every continuation went back to the clip: a
// requested punch thrown again and again).
TEST(GraphWalker, RequestedClipIsPlayedOnceNotAgainAndAgain) {
  const MotionGraph& g = graph();
  GraphWalker w(g, 9, "guard");
  w.transition_probability = 0.0;
  w.loop_probability = 1.0;
  for (int i = 0; i < 10; ++i) w.tick(1.0 / 30);
  ASSERT_TRUE(w.request_clip("jab"));
  int entries = 0;
  std::string last = w.current_clip();
  PoseSample s;
  for (int i = 0; i < 30 * 8; ++i) {
    w.tick(1.0 / 30, &s);
    if (w.current_clip() != last && w.current_clip() == "jab") ++entries;
    last = w.current_clip();
  }
  EXPECT_EQ(entries, 1);
  EXPECT_EQ(w.current_clip(), "guard");
  EXPECT_FALSE(w.has_plan());
}

// The per-tick form (into kept storage) walks the same walk as the value form, bit for bit.
TEST(GraphWalker, TickIntoStorageEqualsTickByValue) {
  const MotionGraph& g = graph();
  GraphWalker a(g, 4), b(g, 4);
  PoseSample into;
  for (int i = 0; i < 30 * 20; ++i) {
    const PoseSample v = a.tick(1.0 / 60);
    b.tick(1.0 / 60, &into);
    ASSERT_EQ(v.pose.root_position, into.pose.root_position) << "tick " << i;
    for (size_t k = 0; k < v.pose.rotation.size(); ++k) {
      ASSERT_EQ(v.pose.rotation[k].coeffs(), into.pose.rotation[k].coeffs());
      ASSERT_EQ(v.angular_velocity[k], into.angular_velocity[k]);
    }
    ASSERT_EQ(a.preview(0.05).root_position, b.preview(0.05).root_position);
  }
}

TEST(GraphWalker, KnockdownGoesDownAndGetsUp) {
  const MotionGraph& g = graph();
  GraphWalker w(g, 8);
  for (int i = 0; i < 40; ++i) w.tick(1.0 / 30);
  ASSERT_TRUE(w.force_clip("fall_back"));
  EXPECT_EQ(w.current_clip(), "fall_back");
  std::vector<std::string> order;
  for (int i = 0; i < 30 * 30; ++i) {
    w.tick(1.0 / 30);
    if (order.empty() || order.back() != w.current_clip()) order.push_back(w.current_clip());
    if (w.current_clip() == "guard" && order.size() > 2) break;
  }
  ASSERT_GE(order.size(), 4u);
  EXPECT_EQ(order[0], "fall_back");
  EXPECT_EQ(order[1], "down_back");
  EXPECT_EQ(order[order.size() - 2], "getup_back");
  EXPECT_EQ(order.back(), "guard");
}

TEST(GraphWalker, AngularVelocityMatchesPoseDifference) {
  const MotionGraph& g = graph();
  GraphWalker w(g, 21);
  const double dt = 1.0 / 240;
  PoseSample prev = w.tick(dt);
  int checked = 0;
  for (int i = 0; i < 240 * 20; ++i) {
    const PoseSample s = w.tick(dt);
    for (int b = 0; b < 16; ++b) {
      const Vector3d fd = angular_velocity_between(prev.pose.rotation[b], s.pose.rotation[b], dt);
      const Vector3d mid = 0.5 * (prev.angular_velocity[b] + s.angular_velocity[b]);
      // a transition or clip change inside the step can make the two differ; they must mostly agree
      if ((fd - mid).norm() < 0.05 * (1 + fd.norm())) ++checked;
    }
    prev = s;
  }
  EXPECT_GT(checked, static_cast<int>(0.995 * 16 * 240 * 20)) << checked;
}


TEST(MotionGraph, WritesReportAndDot) {
  // For people: the graph figures and a clip-level picture (dot -Tsvg motion_graph.dot).
  const std::string dir = BOXING_BINARY_DIR;
  std::ofstream(dir + "/motion_graph_report.json") << graph_report(graph()).dump(1) << "\n";
  std::ofstream(dir + "/motion_graph.dot") << graph_dot(graph());
  std::ifstream in(dir + "/motion_graph.dot");
  EXPECT_TRUE(in.good());
}

TEST(GraphWalker, HitReactionFromMidPunchReturnsToGuard) {
  const MotionGraph& g = graph();
  GraphWalker w(g, 31);
  w.transition_probability = 0.0;
  ASSERT_TRUE(w.request_clip("cross"));
  for (int i = 0; i < 120 && w.current_clip() != "cross"; ++i) w.tick(1.0 / 30);
  ASSERT_EQ(w.current_clip(), "cross");
  for (int i = 0; i < 4; ++i) w.tick(1.0 / 30);  // arm out
  PoseSample prev = w.tick(1.0 / 30);
  ASSERT_TRUE(w.force_clip("hit_head"));
  EXPECT_TRUE(w.blending());
  bool back = false;
  for (int i = 0; i < 60 && !back; ++i) {
    const PoseSample s = w.tick(1.0 / 30);
    for (int b = 1; b < 16; ++b) EXPECT_LT(angle_between(prev.pose.rotation[b], s.pose.rotation[b]), 0.8);  // the walk bound
    prev = s;
    back = w.current_clip() == "guard";
  }
  EXPECT_TRUE(back);
  EXPECT_FALSE(w.force_clip("no_such_clip"));
}

TEST(GraphWalker, PreviewIsTheNextTicksPoseWhileTheWalkStaysInItsClip) {
  // preview(0) is the pose tick() returned; preview(dt) is the next tick's pose unless the next tick crosses a frame
  // where the walk decides (a transition, a clip's end): those ticks are skipped.
  const MotionGraph& g = graph();
  GraphWalker w(g, 77);
  const double dt = 1.0 / 240;
  PoseSample s = w.tick(dt);
  int compared = 0;
  for (int i = 0; i < 240 * 20; ++i) {
    const Pose now = w.preview(0.0), next = w.preview(dt);
    ASSERT_LT((now.root_position - s.pose.root_position).norm(), 1e-12);
    const int node = w.current_node();
    const bool blending = w.blending();
    s = w.tick(dt);
    if (w.current_node() != node && !blending) continue;  // a frame boundary: the walk may have jumped
    if (w.blending() != blending) continue;
    double err = (next.root_position - s.pose.root_position).norm();
    for (int b = 0; b < 16; ++b) err = std::max(err, next.rotation[b].angularDistance(s.pose.rotation[b]));
    EXPECT_LT(err, 1e-9) << "tick " << i;
    ++compared;
  }
  EXPECT_GT(compared, 240 * 10);
}

TEST(GraphWalker, RestartPlaysTheClipsFirstFrameAtTheWalksOrigin) {
  // After a walk through falls and get-ups (root motion accumulated, turned), restart("guard") gives the pose a new
  // walker starting in guard gives: frame 0 of the clip, unaligned (the referee's reset sets the body on it).
  const MotionGraph& g = graph();
  GraphWalker w(g, 8), fresh(g, 8, "guard");
  for (int i = 0; i < 40; ++i) w.tick(1.0 / 30);
  ASSERT_TRUE(w.force_clip("fall_back"));
  for (int i = 0; i < 30 * 6; ++i) w.tick(1.0 / 30);
  const Pose before = w.preview(0.0), start = fresh.preview(0.0);
  ASSERT_GT((before.root_position - start.root_position).head<2>().norm() + angle_between(before.rotation[0], start.rotation[0]), 1e-3)
      << "the walk should have moved off its origin";
  ASSERT_TRUE(w.restart("guard"));
  EXPECT_EQ(w.current_clip(), "guard");
  EXPECT_FALSE(w.blending());
  EXPECT_FALSE(w.has_plan());
  const Pose now = w.preview(0.0);
  EXPECT_LT((now.root_position - start.root_position).norm(), 1e-12);
  for (size_t b = 0; b < now.rotation.size(); ++b) EXPECT_LT(angle_between(now.rotation[b], start.rotation[b]), 1e-12) << b;
  EXPECT_FALSE(w.restart("no_such_clip"));
}

// Heading hold: the transitions' 2D alignments turn a walk's frame a little each time (Kovar's walk: a random walk of
// the heading); with GraphWalker::heading_hold the frame is turned back toward the clips' own facing. Measured on the
// root's heading averaged over each 20 s (a punch turns the pelvis for a moment), over ten minutes, the same seed:
// the held walk stays near its start's facing, plays the same clips (the hold only turns the frame), and turns its
// frame about the root, so the root never jumps.
TEST(GraphWalker, HeadingHoldKeepsTheWalkFacingItsStartWithTheSameClipsAndNoJumps) {
  const MotionGraph& g = graph();
  GraphWalker free_walk(g, 4242, "guard"), held(g, 4242, "guard");
  held.heading_hold = 0.2;
  const double dt = 1.0 / 60;
  auto heading = [](const PoseSample& s) {
    const Vector3d x = s.pose.rotation[0] * Vector3d::UnitX();
    return std::atan2(x.y(), x.x());
  };
  PoseSample a = free_walk.tick(dt), b = held.tick(dt);
  const double h0 = heading(b);
  // Window means of the heading (unwrapped against the start): the worst |mean - start| of each walk.
  double sum_free = 0.0, sum_held = 0.0, worst_free = 0.0, worst_held = 0.0, worst_root_step = 0.0;
  Vector3d prev_root = b.pose.root_position;
  const int window = static_cast<int>(20.0 / dt);
  for (int i = 1; i <= static_cast<int>(600.0 / dt); ++i) {
    free_walk.tick(dt, &a);
    held.tick(dt, &b);
    ASSERT_EQ(free_walk.current_clip(), held.current_clip()) << "tick " << i;
    sum_free += std::remainder(heading(a) - h0, 2.0 * M_PI);
    sum_held += std::remainder(heading(b) - h0, 2.0 * M_PI);
    worst_root_step = std::max(worst_root_step, (b.pose.root_position - prev_root).norm());
    prev_root = b.pose.root_position;
    if (i % window == 0) {
      worst_free = std::max(worst_free, std::abs(sum_free / window));
      worst_held = std::max(worst_held, std::abs(sum_held / window));
      sum_free = sum_held = 0.0;
    }
  }
  std::printf("20 s mean heading off the start, worst: free walk %.1f deg, held %.1f deg; largest root step %.4f m\n",
              worst_free * 180 / M_PI, worst_held * 180 / M_PI, worst_root_step);
  EXPECT_GT(worst_free, 20.0 * M_PI / 180.0);   // the free walk wanders (this seed: see the print)
  EXPECT_LT(worst_held, 0.5 * worst_free);
  EXPECT_LT(worst_root_step, 0.05);  // 3 m/s at 60 Hz: no jump (a step's root moves ~1 m/s)
}

// GraphWalker::hold_transitions (the game's, while a carried step's foot is in the air): a held walk draws no random
// transition and takes no planned one (the plan waits, and is taken once the hold is off); at a clip's end it goes on
// into the home clip. The same seed without the hold leaves its clip.
TEST(GraphWalker, AHeldWalkStaysInItsClipAndTakesItsPlanOnceLetGo) {
  const MotionGraph& g = graph();
  auto clips_visited = [&](bool hold) {
    GraphWalker w(g, 5, "guard");
    w.transition_probability = 0.5;  // a transition drawn on almost every frame ...
    w.loop_probability = 1.0;        // ... and guard loops back into itself at its end
    w.hold_transitions = hold;
    std::set<std::string> seen;
    for (int i = 0; i < 30 * 10; ++i) {
      w.tick(1.0 / 30);
      seen.insert(w.current_clip());
    }
    return seen;
  };
  EXPECT_EQ(clips_visited(true), std::set<std::string>{"guard"});
  EXPECT_GT(clips_visited(false).size(), 1u);
  // A requested punch waits while held, then is thrown.
  GraphWalker w(g, 9, "guard");
  w.transition_probability = 0.0;
  w.loop_probability = 1.0;
  ASSERT_TRUE(w.request_clip("jab"));
  w.hold_transitions = true;
  for (int i = 0; i < 30 * 3; ++i) {
    w.tick(1.0 / 30);
    ASSERT_EQ(w.current_clip(), "guard") << "tick " << i;
  }
  w.hold_transitions = false;
  bool jabbed = false;
  for (int i = 0; i < 30 * 3 && !jabbed; ++i) {
    w.tick(1.0 / 30);
    jabbed = w.current_clip() == "jab";
  }
  EXPECT_TRUE(jabbed);
}
