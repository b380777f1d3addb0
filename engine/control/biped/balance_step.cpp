#include "engine/control/biped/balance_step.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "engine/control/biped/support_polygon.h"

namespace eng::control {

double lip_omega(double com_height, double g) { return std::sqrt(g / std::max(0.3, com_height)); }

Eigen::Vector2d capture_point_after(const Eigen::Vector2d& xi, const Eigen::Vector2d& p, double omega, double t) {
  return p + (xi - p) * std::exp(omega * t);
}

int unloaded_foot(const Eigen::Vector2d& vcom, const Eigen::Vector2d sole[2]) {
  return vcom.dot(sole[1] - sole[0]) > 0.0 ? 0 : 1;
}

int stepping_foot(const std::vector<Eigen::Vector2d> sole_hull[2], const Eigen::Vector2d& xi) {
  return outside_distance(sole_hull[0], xi) <= outside_distance(sole_hull[1], xi) ? 1 : 0;
}

CartPoleLqr solve_cart_pole_lqr(double l, double body_mass, double cart_mass, double q) {
  // Linearised about upright (theta from vertical, com = x + l theta; Lagrange's equations):
  //   M x'' = u - m g theta,   l theta'' = g theta (M + m) / M - u / M.
  // Discrete Riccati iteration on the Euler-discretised system (dt 2 ms) until the gain settles: the continuous
  // LQR's gain to within the discretisation.
  const double g = 9.81, M = cart_mass, m = body_mass, dt = 0.002;
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  A(0, 2) = 1.0;
  A(1, 3) = 1.0;
  A(2, 1) = -m * g / M;
  A(3, 1) = g * (M + m) / (M * l);
  Eigen::Vector4d B(0.0, 0.0, 1.0 / M, -1.0 / (M * l));
  const Eigen::Matrix4d Ad = Eigen::Matrix4d::Identity() + A * dt;
  const Eigen::Vector4d Bd = B * dt;
  const Eigen::Vector4d qdiag(0.0, q, q, 0.0);
  const Eigen::Matrix4d Q = Eigen::Matrix4d(qdiag.asDiagonal()) * dt;
  const double R = 1.0 * dt;
  Eigen::Matrix4d P = Q;
  Eigen::Matrix<double, 1, 4> K = Eigen::Matrix<double, 1, 4>::Zero();
  for (int it = 0; it < 200000; ++it) {
    const double s = R + Bd.dot(P * Bd);
    const Eigen::Matrix<double, 1, 4> Kn = (Bd.transpose() * P * Ad) / s;
    P = Q + Ad.transpose() * P * Ad - Ad.transpose() * P * Bd * Kn;
    const bool done = (Kn - K).norm() < 1e-9 * (1.0 + Kn.norm());
    K = Kn;
    if (done && it > 10) break;
  }
  return CartPoleLqr{l, body_mass, cart_mass, K};
}

double cart_rest_offset(const CartPoleLqr& lqr, double offset, double v, double horizon) {
  // The cart starts at rest under the support (x = 0), the com `offset` ahead of it moving at v:
  // theta = offset / l, theta' = v / l. Closed loop u = -K s, integrated (semi-implicit Euler, 1 ms).
  const double g = 9.81, M = lqr.cart_mass, m = lqr.body_mass, l = lqr.l, dt = 0.001;
  Eigen::Vector4d s(0.0, offset / l, 0.0, v / l);
  for (double t = 0.0; t < horizon; t += dt) {
    const double u = -lqr.K.dot(s);
    const double xdd = (u - m * g * s[1]) / M;
    const double thdd = (g * s[1] * (M + m) / M - u / M) / l;
    s[2] += xdd * dt;
    s[3] += thdd * dt;
    s[0] += s[2] * dt;
    s[1] += s[3] * dt;
  }
  return s[0] - offset;
}

StepLanding place_balance_step(StepPlacement how, const Eigen::Vector2d& com, const Eigen::Vector2d& vcom, double omega,
                               const Eigen::Vector2d& from, const Eigen::Vector2d& stance,
                               const std::vector<Eigen::Vector2d>& stance_hull, double heading,
                               const CartPoleLqr* lqr, const BalanceStepTuning& t) {
  // The stance foot's centre of pressure at the hull's point nearest the capture point (the ankle pushes the
  // body back as hard as the sole allows) while the other foot swings.
  const Eigen::Vector2d xi = com + vcom / omega;
  const Eigen::Vector2d p = stance_hull.empty() ? stance : clamp_to_polygon(stance_hull, xi, 0.0);
  StepLanding out;
  double T = t.min_duration;
  for (int it = 0; it < 4; ++it) {  // the landing depends on the swing's length, the swing's length on the landing
    out.duration = T;
    Eigen::Vector2d land;
    if (how == StepPlacement::CapturePoint || lqr == nullptr) {
      land = capture_point_after(xi, p, omega, out.duration);
    } else {
      // Kwon & Hodgins: the com's state at touch-down (the LIP over p), then where the cart (the new support) comes
      // to rest under the LQR, per axis; the foot goes there.
      const double e = std::exp(omega * out.duration), c = 0.5 * (e + 1.0 / e), sh = 0.5 * (e - 1.0 / e);
      const Eigen::Vector2d x0 = com - p;
      const Eigen::Vector2d xT = p + x0 * c + vcom * (sh / omega);
      const Eigen::Vector2d vT = x0 * (omega * sh) + vcom * c;
      land = xT;
      for (int a = 0; a < 2; ++a) land[a] += cart_rest_offset(*lqr, 0.0, vT[a]);
    }
    const Eigen::Vector2d dir = land - p;
    if (dir.norm() > 1e-6) land += t.land_margin * dir.normalized();
    if (vcom.norm() > 1e-6) {
      const Eigen::Vector2d across(-vcom.y() / vcom.norm(), vcom.x() / vcom.norm());
      land += (across.dot(land - stance) >= 0.0 ? t.side_margin : -t.side_margin) * across;
    }
    // Within the leg's reach before the next iteration's swing time (a huge push's landing otherwise runs off to
    // infinity through e^{omega T}).
    if ((land - stance).norm() > t.max_reach) land = stance + (land - stance) * (t.max_reach / (land - stance).norm());
    out.to = land;
    T = std::max(t.min_duration, (out.to - from).norm() / t.swing_speed);
  }
  // Within the leg's reach of the stance foot, not on it, and not across it: a landing on the stance foot's other
  // side (a cross-over), or on its own side closer across than half min_gap, keeps ahead of or behind the stance foot
  // by cross_gap, on the side the capture point puts it (the swing passes around the stance foot, start_balance_step).
  // By the side the foot comes from instead, a step starting just behind or beside the stance foot can jump to 0.5 m
  // behind it while the body runs on forward (docs/decisions/balance-steps.md).
  const Eigen::Vector2d fwd(std::cos(heading), std::sin(heading)), left(-fwd.y(), fwd.x());
  Eigen::Vector2d d = out.to - stance;
  if (d.norm() > t.max_reach) d *= t.max_reach / d.norm();
  const double side = left.dot(from - stance) >= 0.0 ? 1.0 : -1.0;
  if (side * left.dot(d) < 0.5 * t.min_gap) {
    const double along = fwd.dot(d), sign = along >= 0.0 ? 1.0 : -1.0;
    if (sign * along < t.cross_gap) d += (sign * t.cross_gap - along) * fwd;
  }
  if (d.norm() < t.min_gap) d = (d.norm() > 1e-6 ? d.normalized() : Eigen::Vector2d(side * left)) * t.min_gap;
  if (d.norm() > t.max_reach) d *= t.max_reach / d.norm();
  out.to = stance + d;
  return out;
}

Eigen::Vector2d balance_step_path(const BalanceStep& s, double e, Eigen::Vector2d* d_de) {
  const Eigen::Vector2d via = 0.5 * (s.from + s.to) + s.bow;
  if (d_de) *d_de = 2.0 * (1.0 - e) * (via - s.from) + 2.0 * e * (s.to - via);
  return (1.0 - e) * (1.0 - e) * s.from + 2.0 * e * (1.0 - e) * via + e * e * s.to;
}

namespace {
// The path bent around the stance foot: a straight swing passing closer than pass_clearance to the stance sole's centre
// (a cross-over in front of or behind it, a foot stepping past it) would carry the leg through the stance leg. The
// middle control point moves away from the stance foot until the path's nearest sample keeps the clearance (the
// curve's midpoint moves half as far as the control point).
void bend_path(BalanceStep& s) {
  s.bow.setZero();
  if (s.pass_clearance <= 0.0) return;
  const Eigen::Vector2d seg = s.to - s.from;
  Eigen::Vector2d away = Eigen::Vector2d::Zero();
  for (int it = 0; it < 6; ++it) {
    double nearest = std::numeric_limits<double>::infinity();
    Eigen::Vector2d at = s.from;
    for (int i = 0; i <= 20; ++i) {
      const Eigen::Vector2d p = balance_step_path(s, i / 20.0);
      if ((p - s.stance).norm() < nearest) nearest = (p - s.stance).norm(), at = p;
    }
    if (nearest >= s.pass_clearance - 1e-3) return;
    if (away.isZero()) {
      // Away from the stance foot on the side the straight path passes it (across the segment; an exact hit: the
      // side the swing foot starts on).
      const Eigen::Vector2d across(-seg.y(), seg.x());
      const double side = across.dot(at - s.stance);
      const double start_side = across.dot(s.from - s.stance);
      away = across.normalized() * ((std::abs(side) > 1e-6 ? side : start_side) >= 0.0 ? 1.0 : -1.0);
    }
    s.bow += 2.0 * (s.pass_clearance - nearest) * away;
  }
}

// The landing moved onto a foothold (the smallest shift that puts the sole's core flat on one top; foothold.h
// works on the ankle), the path bent around the stance foot, its top and the highest top the sole passes over on
// the way: along the path, under the sole's whole footprint (its ends, middle and sides, each side widened by the
// foothold's side margin). Sampled along the path's line alone, a swing passing beside the stance foot's higher crate
// brushes its side with the sole's edge, and that touch reads as the landing, 20-30 cm short
// (docs/decisions/balance-steps.md).
void land_on_foothold(BalanceStep& s, const Eigen::Vector2d& to, GroundHeight ground, const FootGeometry& g,
                      const FootholdParams& fp) {
  const Eigen::Rotation2Dd R(s.yaw);
  const Foothold fh = find_foothold(ground, to - R * g.centre.head<2>(), s.yaw, s.yaw, fp);
  s.asked = to;
  s.to = to + fh.shift;
  s.to_top = ground(s.to.x(), s.to.y());
  bend_path(s);
  const Eigen::Vector2d half = R * Eigen::Vector2d(0.5 * (g.toe.x() - g.heel.x()), 0.0);
  const Eigen::Vector2d side = R * Eigen::Vector2d(0.0, fp.sole.half_width + fp.side_margin);
  s.path_top = std::max(s.from_top, s.to_top);
  for (int i = 0; i <= 10; ++i) {
    const Eigen::Vector2d c = balance_step_path(s, i / 10.0);
    for (double a : {-1.0, 0.0, 1.0})
      for (double w : {-1.0, 0.0, 1.0}) {
        const Eigen::Vector2d q = c + a * half + w * side;
        s.path_top = std::max(s.path_top, ground(q.x(), q.y()));
      }
  }
}
}  // namespace

void start_balance_step(BalanceStep& s, int foot, bool returning, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                        const Eigen::Vector2d& stance, double pass_clearance, double yaw, double duration,
                        GroundHeight ground, const FootGeometry& g, const FootholdParams& fp) {
  s.active = true;
  s.returning = returning;
  s.quick = false;
  s.foot = foot;
  s.from = from;
  s.stance = stance;
  s.pass_clearance = pass_clearance;
  s.yaw = yaw;
  s.duration = duration;
  s.elapsed = 0.0;
  s.rise_until = 0.3, s.travel_from = 0.1;
  // The top the foot stands on: the highest under its sole (heel, toe, middle; at its centre alone, a sole across a
  // seam between crates reads the floor, and the swing rises far too high over a long step).
  const Eigen::Rotation2Dd R(yaw);
  s.from_top = -std::numeric_limits<double>::infinity();
  for (double a : {-1.0, 0.0, 1.0}) {
    const Eigen::Vector2d q = from + R * Eigen::Vector2d(a * 0.5 * (g.toe.x() - g.heel.x()), 0.0);
    s.from_top = std::max(s.from_top, ground(q.x(), q.y()));
  }
  land_on_foothold(s, to, ground, g, fp);
}

void replan_balance_step(BalanceStep& s, const Eigen::Vector2d& to, GroundHeight ground, const FootGeometry& g,
                         const FootholdParams& fp, const BalanceStepTuning& t) {
  if ((to - s.asked).norm() >= t.replan_move) land_on_foothold(s, to, ground, g, fp);
}

double step_reach_drop(const Eigen::Vector3d& hip, const Eigen::Vector3d& ankle, double leg, double share,
                       double max_drop) {
  const double reach = share * leg, across = (hip - ankle).head<2>().norm();
  const double below = across < reach ? std::sqrt(reach * reach - across * across) : 0.0;  // the ankle's deepest
  return std::clamp(hip.z() - ankle.z() - below, 0.0, max_drop);
}

Eigen::Vector3d balance_step_sole_target(const BalanceStep& s, const BalanceStepTuning& t, Eigen::Vector3d* velocity,
                                         Eigen::Vector3d* acceleration) {
  const double T = std::max(s.duration, 1e-6), u = std::clamp(s.elapsed / T, 0.0, 1.0);
  // The C1 ease (smoothstep) from 0 at x = a to 1 at x = b, and its first and second derivatives in x.
  auto ease = [](double a, double b, double x) {
    const double v = std::clamp((x - a) / (b - a), 0.0, 1.0);
    return v * v * (3.0 - 2.0 * v);
  };
  auto ease_rate = [](double a, double b, double x) {
    const double v = (x - a) / (b - a);
    return v <= 0.0 || v >= 1.0 ? 0.0 : 6.0 * v * (1.0 - v) / (b - a);
  };
  auto ease_curvature = [](double a, double b, double x) {
    const double v = (x - a) / (b - a);
    return v <= 0.0 || v >= 1.0 ? 0.0 : 6.0 * (1.0 - 2.0 * v) / ((b - a) * (b - a));
  };
  // Lift first, travel, set down: the sole clears the path's highest top before it moves over it.
  const double e = ease(s.travel_from, 0.85, u);
  Eigen::Vector2d d_de;
  const Eigen::Vector2d xy = balance_step_path(s, e, &d_de);
  const double clear = s.path_top + t.lift;
  const bool rising = u < 0.5;
  const double z = rising ? s.from_top + (clear - s.from_top) * ease(0.0, s.rise_until, u)
                          : clear + (s.to_top - t.press - clear) * ease(0.7, 1.0, u);
  const bool moving = s.elapsed < T;
  const double dz = rising ? clear - s.from_top : s.to_top - t.press - clear;  // the height's change in this half
  const double za = rising ? 0.0 : 0.7, zb = rising ? s.rise_until : 1.0;
  if (velocity) {
    const Eigen::Vector2d vxy = moving ? Eigen::Vector2d(d_de * ease_rate(s.travel_from, 0.85, u) / T) : Eigen::Vector2d::Zero();
    const double vz = moving ? dz * ease_rate(za, zb, u) / T : 0.0;
    *velocity = Eigen::Vector3d(vxy.x(), vxy.y(), vz);
  }
  if (acceleration) {
    // d2/dt2 of path(e(u)): the Bezier's second derivative 2 (from - 2 via + to) times e'^2, plus its tangent times e''.
    const Eigen::Vector2d via = 0.5 * (s.from + s.to) + s.bow;
    const Eigen::Vector2d d2_de2 = 2.0 * (s.from - 2.0 * via + s.to);
    const double er = ease_rate(s.travel_from, 0.85, u), ec = ease_curvature(s.travel_from, 0.85, u);
    const Eigen::Vector2d axy = moving ? Eigen::Vector2d((d2_de2 * er * er + d_de * ec) / (T * T)) : Eigen::Vector2d::Zero();
    const double az = moving ? dz * ease_curvature(za, zb, u) / (T * T) : 0.0;
    *acceleration = Eigen::Vector3d(axy.x(), axy.y(), az);
  }
  return Eigen::Vector3d(xy.x(), xy.y(), z);
}

}  // namespace eng::control
