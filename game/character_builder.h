#pragma once
// Turns a character described as content (glTF skeleton + per-bone physics extras) into one articulation of the
// physics model: a free-floating pelvis and a tree of ball / hinge / fixed joints, with the bones' shapes as geoms.
#include <Eigen/Geometry>
#include <initializer_list>
#include <string>
#include <vector>

#include "engine/assets/character.h"
#include "engine/physics/data.h"
#include "engine/physics/model.h"

namespace boxing {

struct CharacterBodies {
  std::vector<int> body;  // physics body index per bone
  std::vector<int> first_geom, geom_count;  // per bone
};

// Adds the character; geoms get `group`/`mask` (so two characters can collide with each other but not with
// themselves when self_collide is false). `friction_scale` multiplies every geom's friction.
CharacterBodies add_character(eng::physics::Model& model, const eng::assets::CharacterDesc& desc,
                              const std::string& prefix, uint32_t group, uint32_t mask, bool self_collide);

// The geoms of `bones` (skeleton indices) collide with each other; the character's other geoms still collide with none
// of its own (Geom::self_collide: a pair within one articulation collides only if both geoms have it; a parent and
// its child never do).
void set_self_colliding(eng::physics::Model& model, const CharacterBodies& c, std::initializer_list<int> bones,
                        bool on = true);

// Sets the articulation's coordinates to a pose: root world position/orientation and per-bone parent-space
// rotations (ball joints take the rotation, hinges its angle about the axis, fixed joints nothing).
void set_character_pose(const eng::physics::Model& model, eng::physics::Data& data, const CharacterBodies& c,
                        const eng::assets::CharacterDesc& desc, const Eigen::Vector3d& root_position,
                        const std::vector<Eigen::Quaterniond>& rotation);

}  // namespace boxing
