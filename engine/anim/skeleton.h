#pragma once
// Skeleton and Pose: the data shared by animation (clips, motion graph) and control (servos).
// CONTRACT: anim produces Poses, control consumes them; neither depends on physics.
// Bone 0 is the root. parent[i] < i for every i > 0 (topological order), parent[0] == -1.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace eng::anim {

struct Skeleton {
  std::vector<std::string> name;
  std::vector<int> parent;
  std::vector<Eigen::Vector3d> offset;  // joint position in the parent bone's frame at rest (metres)
  int size() const { return static_cast<int>(parent.size()); }
  int find(const std::string& n) const {
    for (int i = 0; i < size(); ++i)
      if (name[i] == n) return i;
    return -1;
  }
};

// A pose in parent space: rotation[0] is the root's world orientation, rotation[i>0] the bone's
// rotation relative to its parent (identity = rest pose). Z-up world, metres.
struct Pose {
  Eigen::Vector3d root_position = Eigen::Vector3d::Zero();
  std::vector<Eigen::Quaterniond> rotation;
};

// Pose plus its time derivative, what a pose source hands the servo each tick.
struct PoseSample {
  Pose pose;
  Eigen::Vector3d root_velocity = Eigen::Vector3d::Zero();          // world, m/s
  std::vector<Eigen::Vector3d> angular_velocity;  // per bone, parent-space relative rate, expressed in
                                                  // the parent frame (rad/s); [0] is the root's, world
};

}  // namespace eng::anim

namespace eng::anim {

// Forward kinematics: world joint positions and world bone orientations of a parent-space pose.
void forward_kinematics(const Skeleton& s, const Pose& p, std::vector<Eigen::Vector3d>* world_pos,
                        std::vector<Eigen::Quaterniond>* world_rot);

// Rotation vector <-> unit quaternion (angle * axis; Log takes the shortest arc, |Log| <= pi).
Eigen::Quaterniond quat_exp(const Eigen::Vector3d& v);
Eigen::Vector3d quat_log(const Eigen::Quaterniond& q);

}  // namespace eng::anim
