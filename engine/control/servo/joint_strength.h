#pragma once
// A joint's strength falls with its speed: Hill's force-velocity relation (a muscle shortening faster pulls with less
// force, none at its maximum shortening speed; A. V. Hill 1938), at the joint as a torque-velocity limit, as
// biomechanical torque-actuated models use (e.g. Anderson & Pandy 1999). Only the part of a torque that drives the
// joint FASTER (positive power, tau . v > 0) is weakened; a torque that brakes it keeps its full size.
//
// Why the boxer needs it: a balance QP that cannot get its com and momentum targets from the ground (a boxer
// falling in guard, struck by a thrown crate) spins the light arms as reaction wheels; without a limit the gloves
// whip round far faster than any punch. Punches stay inside the full-strength band.
#include <Eigen/Core>

namespace eng::control {

struct TorqueVelocityLimit {
  double full_speed = 20.0;  // rad/s: at or below this joint speed, full strength
  double zero_speed = 30.0;  // rad/s: at or above it, no torque that drives the joint faster (linear between)
};

// tau, v: one joint's generalised torque and velocity (a hinge: 1, a ball: 3, in the same coordinates, so tau . v
// is its power). The component of tau along v, when positive, is scaled by the strength left at |v|.
void limit_torque_by_speed(Eigen::Ref<Eigen::VectorXd> tau, const Eigen::Ref<const Eigen::VectorXd>& v,
                           const TorqueVelocityLimit& limit);

// The strength left at joint speed s, in [0, 1].
double strength_at_speed(double s, const TorqueVelocityLimit& limit);

}  // namespace eng::control
