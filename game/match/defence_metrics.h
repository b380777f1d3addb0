#pragma once
// The defences as the simulated body makes them (issue 65 item 2), measured each tick after the physics step from the
// bodies alone, not from the clips: a defence is a clip tagged "defence" the boxer's walk enters; from its first tick
// to the tick it ends (played out, or cut by a hit's reaction) the head's centre of mass is followed against where it
// was at the start:
//   side_m: the head's largest move off the line to the opponent (the horizontal line from the opponent's head to this
//     boxer's head at the start, fixed in the world), to the boxer's left (+) for slip_left and to its right for
//     slip_right; for the other defences the largest either way;
//   drop_m: the head's largest drop below its starting height;
//   gloves_above_head_m / gloves_below_chest_m (blocks): at the defence's fullest (the tick the gloves were highest,
//     or lowest for block_low) the lower glove's centre height above the head's centre, and the higher glove's
//     centre below the chest's centre;
//   whole: played to its end (not cut by a hit or a fall).
// Each punch also records the defence the opponent was in before its first touch (PunchEvent::defence), so the share
// of punches that land on a blocking boxer can be set against those on a boxer that did not defend.
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace boxing {

struct World;

struct DefenceMotion {
  int boxer = 0;
  std::string clip;
  double t = 0.0;
  double side_m = 0.0, drop_m = 0.0;
  double gloves_above_head_m = -1e9, gloves_below_chest_m = -1e9;
  bool whole = false;
};

// Per boxer: the defence under way (-1: none) and where its head started.
struct DefenceTrack {
  int clip = -1;
  int record = -1;  // Match::defences index
  Eigen::Vector3d head0 = Eigen::Vector3d::Zero();
  Eigen::Vector2d left = Eigen::Vector2d::UnitY();  // the boxer's left, square to the line to the opponent
};

// One tick (match_after_step, after track_punches).
void measure_defences(World& w);

// The report's "defence" object: per defence clip the count, how many were played out, the medians of side_m,
// drop_m and the glove heights over those played out, and the punches that met each defence (thrown, landed) with
// those that met none; and every defence in order ("list").
nlohmann::json defence_report(const World& w);

}  // namespace boxing
