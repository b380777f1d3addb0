#include "game/character_builder.h"

#include <cmath>

namespace boxing {

using eng::physics::Body;
using eng::physics::Geom;
using eng::physics::JointType;

CharacterBodies add_character(eng::physics::Model& model, const eng::assets::CharacterDesc& desc,
                              const std::string& prefix, uint32_t group, uint32_t mask, bool self_collide) {
  CharacterBodies out;
  const auto& skel = desc.skeleton;
  for (int i = 0; i < skel.size(); ++i) {
    const auto& bp = desc.bones[i];
    Body b;
    b.name = prefix + skel.name[i];
    b.parent = i == 0 ? 0 : out.body[skel.parent[i]];
    b.joint = bp.joint == "free" ? JointType::Free
              : bp.joint == "ball" ? JointType::Ball
              : bp.joint == "hinge" ? JointType::Hinge
                                   : JointType::Fixed;
    b.X_tree.R.setIdentity();
    b.X_tree.p = i == 0 ? Eigen::Vector3d::Zero() : skel.offset[i];
    b.axis = bp.axis.normalized();
    b.mass = bp.mass;
    b.com = bp.com;
    b.inertia = bp.inertia_diag.asDiagonal();
    b.damping = bp.damping;
    b.armature = bp.armature;
    if (b.joint == JointType::Hinge) {
      b.limited = bp.upper > bp.lower;
      b.lower = bp.lower;
      b.upper = bp.upper;
    }
    b.swing_limit = bp.swing_limit;
    b.twist_limit = bp.twist_limit;
    out.body.push_back(model.add_body(b));
    out.first_geom.push_back(static_cast<int>(model.geoms.size()));
    for (const auto& s : bp.shapes) {
      Geom g;
      g.shape = s.shape;
      g.body = out.body.back();
      g.local.R = s.quat.normalized().toRotationMatrix();
      g.local.p = s.pos;
      // Feet grip the crates; cloth and gloves slide more.
      g.friction = skel.name[i].rfind("foot", 0) == 0 ? 1.0 : 0.6;
      g.group = group;
      g.mask = mask;
      g.self_collide = self_collide;
      model.add_geom(g);
    }
    out.geom_count.push_back(static_cast<int>(model.geoms.size()) - out.first_geom.back());
  }
  return out;
}

void set_self_colliding(eng::physics::Model& model, const CharacterBodies& c, std::initializer_list<int> bones,
                        bool on) {
  for (int bone : bones)
    for (int g = c.first_geom[bone]; g < c.first_geom[bone] + c.geom_count[bone]; ++g)
      model.geoms[g].self_collide = on;
}

void set_character_pose(const eng::physics::Model& model, eng::physics::Data& data, const CharacterBodies& c,
                        const eng::assets::CharacterDesc& desc, const Eigen::Vector3d& root_position,
                        const std::vector<Eigen::Quaterniond>& rotation) {
  for (size_t i = 0; i < c.body.size(); ++i) {
    const Body& b = model.bodies[c.body[i]];
    double* q = data.q.data() + b.q_index;
    const Eigen::Quaterniond r = rotation[i].normalized();
    switch (b.joint) {
      case JointType::Free:
        q[0] = root_position.x(), q[1] = root_position.y(), q[2] = root_position.z();
        q[3] = r.w(), q[4] = r.x(), q[5] = r.y(), q[6] = r.z();
        break;
      case JointType::Ball:
        q[0] = r.w(), q[1] = r.x(), q[2] = r.y(), q[3] = r.z();
        break;
      case JointType::Hinge: {
        // Angle of the rotation's component about the hinge axis (swing-twist decomposition).
        const Eigen::Vector3d v(r.x(), r.y(), r.z());
        const double proj = v.dot(b.axis);
        q[0] = 2.0 * std::atan2(proj, r.w());
        if (q[0] > M_PI) q[0] -= 2 * M_PI;
        break;
      }
      case JointType::Fixed:
        break;
    }
  }
  for (size_t i = 0; i < c.body.size(); ++i) {
    const Body& b = model.bodies[c.body[i]];
    for (int k = 0; k < b.nv; ++k) data.v[b.v_index + k] = 0.0;
  }
}

}  // namespace boxing
