#include "engine/control/biped/step_planner.h"

#include <algorithm>

namespace eng::control {

double clip_sole_gap(const std::vector<Eigen::Quaterniond>& W, const std::vector<Eigen::Vector3d>& P, int foot,
                     const FootGeometry& g) {
  return std::min((P[foot] + W[foot] * g.heel).z(), (P[foot] + W[foot] * g.toe).z());
}

void start_step(StepPlan& st, const Touchdown& td, const Eigen::Vector3d& ankle_placed, double heading,
                const Eigen::Vector3d& foot_centre_now, GroundHeight ground, const FootGeometry& g,
                const StepTuning& t, double dt) {
  st.active = true;
  st.elapsed = 0.0;
  st.duration = std::max(td.ahead, dt);
  st.landing = ankle_placed.head<2>() + Eigen::Rotation2Dd(heading) * td.travel;
  const double yaw = heading + td.yaw;
  st.shift = find_foothold(ground, st.landing, yaw, heading, t.foothold).shift;
  const Eigen::Vector3d& from = foot_centre_now;
  const Eigen::Vector2d to = st.landing + st.shift + Eigen::Rotation2Dd(yaw) * g.centre.head<2>();
  st.step_up = ground(to.x(), to.y()) > ground(from.x(), from.y()) + t.step_up_tolerance;
}

void advance_step(StepPlan& st, const Eigen::Vector3d& ankle_placed, const Eigen::Quaterniond& foot_placed,
                  GroundHeight ground, const FootGeometry& g, const StepTuning& t, double dt) {
  st.elapsed += dt;
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
