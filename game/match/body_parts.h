#pragma once
// What a physics body is in the fight: whose it is and which part of the boxer (a glove, the head, the torso, an
// arm, a leg). The match reads the solver's hit events through this map (hits.h).
#include <cstdint>
#include <string>
#include <vector>

#include "engine/anim/skeleton.h"

namespace boxing {

struct Boxer;

enum class BodyPart : uint8_t { None, Glove, Head, Torso, Arm, Leg };

const char* body_part_name(BodyPart p);
// The part a bone of the boxer (content/boxer/boxer.gltf's names) belongs to.
BodyPart boxer_body_part(const std::string& bone_name);

struct BodyOwner {
  int boxer = -1;  // index into World::boxers, -1 = not a boxer's (crates, floor, loose bodies)
  int bone = -1;
  BodyPart part = BodyPart::None;
};

// One entry per physics body of the model (body_count), filled from every boxer's bodies.
std::vector<BodyOwner> body_owners(int body_count, const std::vector<Boxer>& boxers, const eng::anim::Skeleton& skel);

}  // namespace boxing
