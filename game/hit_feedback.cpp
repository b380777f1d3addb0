#include "game/hit_feedback.h"

#include <algorithm>
#include <cmath>

namespace boxing {

double hit_weight(const Interaction::Flash& fl, const HitFeedbackTuning& t) {
  return std::max(fl.impulse / t.heavy_impulse, fl.speed / t.heavy_speed);
}

double hit_stop_seconds(const Interaction::Flash& fl, const HitFeedbackTuning& t) {
  const double w = hit_weight(fl, t);
  if (w < 1.0) return 0.0;
  return std::min(t.max_stop_s, t.min_stop_s + t.stop_per_weight * (w - 1.0));
}

glm::vec3 camera_shake(const Interaction& in, double now, const HitFeedbackTuning& t) {
  glm::vec3 offset(0.0f);
  for (const Interaction::Flash& fl : in.flashes) {
    const double age = now - fl.t;
    const double w = hit_weight(fl, t);
    if (age < 0.0 || age > t.shake_s || w < 1.0) continue;
    const double amp = std::min(t.max_shake_m, t.shake_per_weight * w) * (1.0 - age / t.shake_s);
    // Three incommensurate frequencies (23, 29, 31 Hz): a rattle, not a sway; phased by the hit's time.
    const double p = 2.0 * M_PI * age;
    offset += float(amp) * glm::vec3(float(std::sin(23.0 * p + fl.t)), float(std::sin(29.0 * p + 2.0 * fl.t)),
                                     float(0.5 * std::sin(31.0 * p + 3.0 * fl.t)));
  }
  return offset;
}

void hit_sparks(const Interaction::Flash& fl, double now, eng::render::FrameDesc& f, const HitFeedbackTuning& t) {
  const double age = now - fl.t;
  if (age < 0.0 || age > t.spark_s || fl.impulse < t.min_impulse) return;
  const double life = age / t.spark_s;  // 0 .. 1
  const double reach = std::min(t.spark_reach_max_m, t.spark_reach_per_impulse * fl.impulse);
  const double r0 = t.spark_inner_m + reach * life, r1 = r0 + 0.35 * reach * (1.0 - life) + 0.01;
  const int n = std::clamp(t.sparks_min + int(fl.impulse), t.sparks_min, t.sparks_max);
  // The ring lies across the hit's normal: the plane the punch's force spreads in.
  const Eigen::Vector3d nrm = fl.normal.norm() > 1e-9 ? fl.normal.normalized() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d u = nrm.unitOrthogonal(), v = nrm.cross(u);
  const float fade = float(1.0 - life);
  const bool heavy = hit_weight(fl, t) >= 1.0;
  const float dot = float(std::min(t.spark_dot_max_px, t.spark_dot_px + t.spark_dot_px_per_impulse * fl.impulse));
  const glm::vec4 color = heavy ? glm::vec4(1.0f, 0.55f, 0.15f, fade) : glm::vec4(1.0f, 0.95f, 0.6f, fade);
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * M_PI * (k + 0.5 * (k % 2)) / n;
    const Eigen::Vector3d dir = std::cos(a) * u + std::sin(a) * v;
    const Eigen::Vector3d p0 = fl.point + r0 * dir, p1 = fl.point + r1 * dir;
    const glm::vec3 head(float(p1.x()), float(p1.y()), float(p1.z()));
    f.lines.push_back({glm::vec3(float(p0.x()), float(p0.y()), float(p0.z())), head, color});
    f.points.push_back({head, dot * fade, color});
  }
}

}  // namespace boxing
