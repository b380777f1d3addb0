#pragma once
// Shared model builders for the physics tests.
#include <random>

#include "engine/physics/data.h"
#include "engine/physics/dynamics.h"
#include "engine/physics/model.h"
#include "engine/physics/spatial.h"
#include "engine/physics/step.h"

namespace eng::physics::test {

inline Mat3 box_inertia(double m, const Vec3& he) {
  const Vec3 s = 2.0 * he;
  return (m / 12.0 * Vec3(s.y() * s.y() + s.z() * s.z(), s.x() * s.x() + s.z() * s.z(),
                          s.x() * s.x() + s.y() * s.y()))
      .asDiagonal();
}
inline Mat3 rod_inertia_z(double m, double len, double r = 0.02) {  // slender rod along Z
  const double t = m * (3 * r * r + len * len) / 12.0;
  return Vec3(t, t, 0.5 * m * r * r).asDiagonal();
}

inline Pose at(const Vec3& p) { return Pose{Mat3::Identity(), p}; }

// Shapes for the collision and ray tests.
inline Shape sphere_shape(double r) {
  Shape s;
  s.type = ShapeType::Sphere;
  s.radius = r;
  return s;
}
inline Shape capsule_shape(double r, double half_length) {
  Shape s;
  s.type = ShapeType::Capsule;
  s.radius = r;
  s.half_length = half_length;
  return s;
}
inline Shape box_shape(const Vec3& half_extents) {
  Shape s;
  s.type = ShapeType::Box;
  s.half_extents = half_extents;
  return s;
}
inline Shape plane_shape() {
  Shape s;
  s.type = ShapeType::Plane;
  return s;
}

inline Body make_body(const char* name, int parent, JointType j, const Pose& X, double mass, const Vec3& com,
                      const Mat3& I, const Vec3& axis = Vec3::UnitY()) {
  Body b;
  b.name = name;
  b.parent = parent;
  b.joint = j;
  b.X_tree = X;
  b.mass = mass;
  b.com = com;
  b.inertia = I;
  b.axis = axis;
  return b;
}

// A free solid sphere (uniform density: I = 2/5 m r^2) at p with its geom; returns the body.
inline int add_free_sphere(Model& m, const Vec3& p, double r, double mass) {
  const int b = m.add_body(make_body("ball", 0, JointType::Free, at(p), mass, Vec3::Zero(),
                                     Mat3::Identity() * (0.4 * mass * r * r)));
  Geom g;
  g.body = b;
  g.shape = sphere_shape(r);
  m.add_geom(g);
  return b;
}

// Humanoid-sized tree: free torso + 15 links (ball/hinge/fixed), 36 DoF.
inline Model humanoid_tree() {
  Model m;
  const Vec3 dz(0, 0, -0.2);
  auto I = [](double mass) { return box_inertia(mass, Vec3(0.06, 0.05, 0.15)); };
  int torso = m.add_body(make_body("torso", 0, JointType::Free, at({0, 0, 1.2}), 12, {0, 0, 0.1}, I(12)));
  int chest = m.add_body(make_body("chest", torso, JointType::Ball, at({0, 0, 0.25}), 10, {0, 0, 0.1}, I(10)));
  m.add_body(make_body("head", chest, JointType::Ball, at({0, 0, 0.3}), 4, {0, 0, 0.1}, I(4)));
  for (int s = -1; s <= 1; s += 2) {
    int th = m.add_body(make_body("thigh", torso, JointType::Ball, at({0, 0.1 * s, -0.1}), 7, dz, I(7)));
    int sh = m.add_body(make_body("shin", th, JointType::Hinge, at({0, 0, -0.42}), 4, dz, I(4)));
    m.add_body(make_body("foot", sh, JointType::Ball, at({0, 0, -0.4}), 1, {0.05, 0, -0.03}, I(1)));
    int ua = m.add_body(make_body("upper_arm", chest, JointType::Ball, at({0, 0.2 * s, 0.2}), 2, dz, I(2)));
    int fa = m.add_body(make_body("forearm", ua, JointType::Hinge, at({0, 0, -0.3}), 1.5, dz, I(1.5)));
    int hand = m.add_body(make_body("hand", fa, JointType::Hinge, at({0, 0, -0.28}), 0.5, dz, I(0.5),
                                    Vec3(1, 0, 0)));
    m.add_body(make_body("glove", hand, JointType::Fixed, at({0, 0, -0.05}), 0.3, Vec3::Zero(), I(0.3)));
  }
  m.finalize();
  return m;
}

// humanoid_tree() with damping, armature, stiffness (per DoF; 0: none), limits, capsule limbs, a floor plane and a
// crate: exercises every stage of the step (contacts, limits, implicit terms).
inline Model humanoid_on_floor(double stiffness = 20.0) {
  Model m = humanoid_tree();
  for (size_t i = 1; i < m.bodies.size(); ++i) {
    Body& b = m.bodies[i];
    b.damping = 0.5;
    b.armature = 0.01;
    if (b.joint != JointType::Free) b.stiffness = stiffness;
    if (b.joint == JointType::Hinge) {
      b.limited = true;
      b.lower = -1.0;
      b.upper = 1.0;
    }
    if (b.joint == JointType::Ball) b.swing_limit = 0.8, b.twist_limit = 0.5;
    Geom g;
    g.body = static_cast<int>(i);
    g.shape.type = ShapeType::Capsule;
    g.shape.radius = 0.05;
    g.shape.half_length = 0.1;
    g.local = at({0, 0, -0.15});
    m.add_geom(g);
  }
  Geom floor;
  floor.body = 0;
  floor.shape.type = ShapeType::Plane;
  m.add_geom(floor);
  Geom crate;
  crate.body = 0;
  crate.shape.type = ShapeType::Box;
  crate.shape.half_extents = Vec3(0.3, 0.3, 0.3);
  crate.local = at({0.5, 0, 0.3});
  m.add_geom(crate);
  m.finalize();
  return m;
}

// Random state: random unit quaternions, angles, velocities, torques, applied forces.
inline void randomize(const Model& m, Data& d, std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  // The components are drawn last to first in statements of their own: the order in which the arguments of one
  // call are evaluated is unspecified (GCC goes right to left, clang left to right), and the tests must see the
  // same state from every compiler (the sanitizer build uses clang). Last to first keeps GCC's states.
  auto quat = [&] {
    const double z = n(rng), y = n(rng), x = n(rng), w = n(rng);
    return Quat(w, x, y, z);
  };
  auto vec3 = [&] {
    const double z = n(rng), y = n(rng), x = n(rng);
    return Vec3(x, y, z);
  };
  for (size_t i = 1; i < m.bodies.size(); ++i) {
    const Body& b = m.bodies[i];
    double* q = d.q.data() + b.q_index;
    if (b.joint == JointType::Free) {
      for (int k = 0; k < 3; ++k) q[k] = n(rng);
      quat_store(quat().normalized(), q + 3);
    } else if (b.joint == JointType::Ball) {
      quat_store(quat().normalized(), q);
    } else if (b.joint == JointType::Hinge) {
      q[0] = n(rng);
    }
    d.applied_force[i] = vec3();
    d.applied_torque[i] = vec3();
  }
  for (int k = 0; k < m.nv; ++k) d.v[k] = n(rng);
}

// q <- q (+) eps * dv on the joint manifolds (same rules as integrate()).
inline VecX q_plus(const Model& m, const VecX& q0, const VecX& dv, double eps) {
  Model mm = m;
  mm.dt = eps;
  Data d = make_data(m);
  d.q = q0;
  d.v = dv;
  integrate(mm, d);
  return d.q;
}

}  // namespace eng::physics::test
