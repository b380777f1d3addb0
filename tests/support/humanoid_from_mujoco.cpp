#include "tests/support/humanoid_from_mujoco.h"

#include <stdexcept>
#include <string>

namespace bench {

using namespace eng::physics;

namespace {

Vec3 v3(const mjtNum* a) { return Vec3(a[0], a[1], a[2]); }
Mat3 rot(const mjtNum* q) { return Quat(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix(); }
Pose translate(const Vec3& t) { return Pose{Mat3::Identity(), t}; }

void copy_hinge(const mjModel* m, int j, Body& c) {
  const int dof = m->jnt_dofadr[j];
  c.joint = JointType::Hinge;
  c.axis = v3(m->jnt_axis + 3 * j).normalized();
  c.damping = m->dof_damping[dof];
  c.armature = m->dof_armature[dof];
  c.stiffness = m->jnt_stiffness[j];
  c.limited = m->jnt_limited[j] != 0;
  c.lower = m->jnt_range[2 * j];
  c.upper = m->jnt_range[2 * j + 1];
}

}  // namespace

std::vector<MappedBody> append_mujoco_bodies(const mjModel* m, Model& out, const Vec3& shift) {
  std::vector<MappedBody> map(m->nbody);
  for (int b = 1; b < m->nbody; ++b) {
    const int pb = m->body_parentid[b];
    const char* nm = mj_id2name(m, mjOBJ_BODY, b);
    const std::string name = nm ? nm : ("body" + std::to_string(b));
    // MuJoCo body frame in the frame of our body that carries the MuJoCo parent
    const Pose Xb{rot(m->body_quat + 4 * b), v3(m->body_pos + 3 * b)};
    const Pose pre = (pb == 0) ? translate(shift) * Xb : translate(map[pb].offset) * Xb;
    int parent = map[pb].body;
    const int jn = m->body_jntnum[b], ja = m->body_jntadr[b];

    Body body;
    body.name = name;
    body.parent = parent;
    Vec3 anchor = Vec3::Zero();  // our body origin in the MuJoCo body frame
    if (jn == 0) {
      body.joint = JointType::Fixed;
      body.X_tree = pre;
    } else if (m->jnt_type[ja] == mjJNT_FREE) {
      if (jn != 1) throw std::runtime_error("free joint combined with other joints: " + name);
      body.parent = 0;
      body.joint = JointType::Free;
      body.X_tree = pre;
      body.damping = m->dof_damping[m->jnt_dofadr[ja]];
      body.armature = m->dof_armature[m->jnt_dofadr[ja]];
    } else {
      Pose X = pre;  // frame the next chain body's X_tree is relative to, times the anchor step
      for (int k = 0; k < jn; ++k) {
        const int j = ja + k;
        if (m->jnt_type[j] != mjJNT_HINGE) throw std::runtime_error("only free/hinge joints supported: " + name);
        const Vec3 pj = v3(m->jnt_pos + 3 * j);
        Body c;
        c.name = (k + 1 < jn) ? name + "_j" + std::to_string(k) : name;
        c.parent = parent;
        c.X_tree = X * translate(pj - anchor);
        copy_hinge(m, j, c);
        anchor = pj;
        X = Pose{};
        if (k + 1 < jn) {
          parent = out.add_body(c);  // massless link of the chain
        } else {
          body = c;
        }
      }
    }
    body.mass = m->body_mass[b];
    body.com = v3(m->body_ipos + 3 * b) - anchor;
    const Mat3 Ri = rot(m->body_iquat + 4 * b);
    body.inertia = Ri * v3(m->body_inertia + 3 * b).asDiagonal() * Ri.transpose();
    map[b] = MappedBody{out.add_body(body), -anchor};
  }

  for (int g = 0; g < m->ngeom; ++g) {
    const int b = m->geom_bodyid[g];
    if (b == 0) continue;  // world geoms: add_mujoco_floor
    Geom geom;
    geom.body = map[b].body;
    geom.local = translate(map[b].offset) * Pose{rot(m->geom_quat + 4 * g), v3(m->geom_pos + 3 * g)};
    geom.friction = m->geom_friction[3 * g];
    geom.self_collide = false;
    const mjtNum* s = m->geom_size + 3 * g;
    switch (m->geom_type[g]) {
      case mjGEOM_SPHERE:
        geom.shape.type = ShapeType::Sphere;
        geom.shape.radius = s[0];
        break;
      case mjGEOM_CAPSULE:
        geom.shape.type = ShapeType::Capsule;
        geom.shape.radius = s[0];
        geom.shape.half_length = s[1];
        break;
      case mjGEOM_BOX:
        geom.shape.type = ShapeType::Box;
        geom.shape.half_extents = v3(s);
        break;
      default:
        throw std::runtime_error("unsupported geom type " + std::to_string(m->geom_type[g]));
    }
    out.add_geom(geom);
  }
  return map;
}

void add_mujoco_floor(const mjModel* m, Model& out) {
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_bodyid[g] != 0 || m->geom_type[g] != mjGEOM_PLANE) continue;
    Geom floor;
    floor.body = 0;
    floor.shape.type = ShapeType::Plane;
    floor.local = Pose{rot(m->geom_quat + 4 * g), v3(m->geom_pos + 3 * g)};
    floor.friction = m->geom_friction[3 * g];
    out.add_geom(floor);
  }
}

std::vector<std::vector<MappedBody>> convert_mujoco_model(const mjModel* m, Model& out, int count,
                                                          double spacing) {
  out.gravity = v3(m->opt.gravity);
  out.dt = m->opt.timestep;
  add_mujoco_floor(m, out);
  std::vector<std::vector<MappedBody>> maps;
  for (int i = 0; i < count; ++i) maps.push_back(append_mujoco_bodies(m, out, Vec3(0.0, spacing * i, 0.0)));
  out.finalize();
  return maps;
}

}  // namespace bench
