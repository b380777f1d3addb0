#include "game/match/body_parts.h"

#include "game/boxer.h"

namespace boxing {

const char* body_part_name(BodyPart p) {
  switch (p) {
    case BodyPart::None: return "none";
    case BodyPart::Glove: return "glove";
    case BodyPart::Head: return "head";
    case BodyPart::Torso: return "torso";
    case BodyPart::Arm: return "arm";
    case BodyPart::Leg: return "leg";
  }
  return "?";
}

BodyPart boxer_body_part(const std::string& n) {
  if (n == "glove_l" || n == "glove_r") return BodyPart::Glove;
  if (n == "head") return BodyPart::Head;
  if (n == "chest" || n == "abdomen" || n == "pelvis") return BodyPart::Torso;
  if (n.rfind("upper_arm", 0) == 0 || n.rfind("forearm", 0) == 0) return BodyPart::Arm;
  if (n.rfind("thigh", 0) == 0 || n.rfind("shank", 0) == 0 || n.rfind("foot", 0) == 0) return BodyPart::Leg;
  return BodyPart::None;
}

std::vector<BodyOwner> body_owners(int body_count, const std::vector<Boxer>& boxers, const eng::anim::Skeleton& skel) {
  std::vector<BodyOwner> owners(body_count);
  for (size_t k = 0; k < boxers.size(); ++k)
    for (int i = 0; i < skel.size(); ++i) {
      const int body = boxers[k].bodies.body[i];
      if (body < 0 || body >= body_count) continue;
      owners[body] = {static_cast<int>(k), i, boxer_body_part(skel.name[i])};
    }
  return owners;
}

}  // namespace boxing
