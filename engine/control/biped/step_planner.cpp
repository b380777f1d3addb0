#include "engine/control/biped/step_planner.h"

#include <algorithm>
#include <cmath>

namespace eng::control {

double clip_sole_gap(const std::vector<Eigen::Quaterniond>& W, const std::vector<Eigen::Vector3d>& P, int foot,
                     const FootGeometry& g) {
  return std::min((P[foot] + W[foot] * g.heel).z(), (P[foot] + W[foot] * g.toe).z());
}

void start_step(StepPlan& st, const Touchdown& td, const Eigen::Vector3d& ankle_placed, double heading,
                const Eigen::Vector3d& foot_centre_now, GroundHeight ground, const FootGeometry& g,
                const StepTuning& t, double dt, const Eigen::Vector2d& stance_ankle,
                const Eigen::Vector2d& stance_centre) {
  st.active = true;
  st.landed = false;
  st.elapsed = 0.0;
  st.duration = std::max(td.ahead, dt);
  const Eigen::Rotation2Dd heading_R(heading);
  st.landing = ankle_placed.head<2>() + heading_R * td.travel;
  const double yaw = heading + td.yaw;
  const Eigen::Vector2d centre = Eigen::Rotation2Dd(yaw) * g.centre.head<2>();  // ankle to sole centre
  const Eigen::Vector3d& from = foot_centre_now;
  st.carried = t.carry && td.travel.norm() >= t.carry_min_travel;
  if (!st.carried) {
    st.shift = find_foothold(ground, st.landing, yaw, heading, t.foothold).shift;
    const Eigen::Vector2d to = st.landing + st.shift + centre;
    st.step_up = ground(to.x(), to.y()) > ground(from.x(), from.y()) + t.step_up_tolerance;
    return;
  }
  // Carried: landed where the clip has it relative to the stance foot (the anchored placement puts it relative to
  // both feet as they stand, so a stretched stance stays stretched), unless the body has turned off the heading.
  const Eigen::Vector2d relative = stance_ankle + heading_R * td.apart;
  const Eigen::Vector2d from_ankle = from.head<2>() - centre;
  if ((relative - from_ankle).norm() < td.travel.norm() + t.carry_max_extra) st.landing = relative;
  // The foothold nearest it, a shift toward the stance foot preferred (along frame_yaw: toward it).
  const Eigen::Vector2d toward = stance_centre - (st.landing + centre);
  st.shift = find_foothold(ground, st.landing, yaw, std::atan2(toward.y(), toward.x()), t.carry_foothold).shift;
  start_balance_step(st.path, 0, false, from.head<2>(), st.landing + st.shift + centre, stance_centre,
                     t.carry_pass_clearance, yaw, st.duration, ground, g, t.carry_foothold);
  const double rise = st.path.path_top + t.carry_lift - st.path.from_top, rise_time = rise / t.carry_rise_speed;
  st.duration = std::max(st.duration, rise_time);
  if (st.path.path_top > st.path.from_top + t.step_up_tolerance) {
    // Past a higher top's edge: the sole rises at carry_rise_speed and travels only once it is carry_edge_clearance
    // above that top (the smoothstep rise's inverse, v = 1/2 - sin(asin(1 - 2 f) / 3)), then in the clip's time.
    // Travelling from the swing's start, a heel near a higher crate's side catches on its edge, the foot pivots on it
    // and the body falls over the stance foot (docs/decisions/footwork.md).
    const double f = std::clamp((st.path.path_top + t.carry_edge_clearance - st.path.from_top) / rise, 0.0, 1.0);
    const double v = 0.5 - std::sin(std::asin(1.0 - 2.0 * f) / 3.0);
    st.duration = std::max({st.duration, rise_time / 0.5, (v * rise_time + 0.75 * td.ahead) / 0.85});
    st.path.rise_until = rise_time / st.duration;
    st.path.travel_from = v * rise_time / st.duration;
  }
  st.path.duration = st.duration;
  st.step_up = st.path.to_top > st.path.from_top + t.step_up_tolerance;
}

void advance_step(StepPlan& st, const Eigen::Vector3d& ankle_placed, const Eigen::Quaterniond& foot_placed,
                  GroundHeight ground, const FootGeometry& g, const StepTuning& t, double dt) {
  st.elapsed += dt;
  if (st.carried) {  // the sole centre on its path, and the path's velocity as the swing's feed-forward
    st.path.elapsed = st.elapsed;
    BalanceStepTuning swing;
    swing.lift = t.carry_lift;
    swing.press = t.carry_press;
    const Eigen::Vector3d c = balance_step_sole_target(st.path, swing, &st.velocity, &st.acceleration);
    st.target = c - Eigen::AngleAxisd(st.path.yaw, Eigen::Vector3d::UnitZ()) * g.sole_offset();
    st.clip_z = st.target.z();
    st.has_velocity = true;
    return;
  }
  const double u = std::clamp(st.elapsed / st.duration, 0.0, 1.0);
  const Eigen::Vector2d s = (3.0 * u * u - 2.0 * u * u * u) * st.shift;
  const Eigen::Vector3d mid = ankle_placed + foot_placed * g.centre;
  st.clip_z = ankle_placed.z() - ground(mid.x(), mid.y());  // the fit put the ankle over the top under mid
  const Eigen::Vector2d land_mid = st.landing + st.shift + (mid - ankle_placed).head<2>();
  const double top = std::max(ground(mid.x() + s.x(), mid.y() + s.y()), ground(land_mid.x(), land_mid.y()));
  // The shuffle: the sole stays pressed to its top, except up onto a higher one (it has to clear the edge).
  const double press = st.step_up ? 0.0 : t.swing_press;
  st.target = Eigen::Vector3d(ankle_placed.x() + s.x(), ankle_placed.y() + s.y(), st.clip_z + top - press);
}

}  // namespace eng::control
