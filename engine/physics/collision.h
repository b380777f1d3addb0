#pragma once
// Collision detection: shapes, the contact-point record, narrowphase pair tests and the broadphase.
// CONTRACT shared by the collision code (shapes/narrowphase/broadphase) and the step pipeline.
// Conventions: world frame is Z-up; gravity is -Z. Capsules are along their local Z axis.
#include <cstdint>
#include "engine/physics/types.h"

namespace eng::physics {

enum class ShapeType : uint8_t { Sphere, Capsule, Box, Plane };

struct Shape {
  ShapeType type = ShapeType::Sphere;
  double radius = 0.0;           // sphere, capsule
  double half_length = 0.0;      // capsule: half the distance between the two cap centres (local Z)
  Vec3 half_extents = Vec3::Zero();  // box
  // plane: the local XY plane, normal +Z (infinite); use only on static geoms
};

// One contact point between geom a and geom b.
struct ContactPoint {
  int geom_a = -1;
  int geom_b = -1;
  Vec3 position = Vec3::Zero();  // world point, midway between the two surfaces
  Vec3 normal = Vec3::UnitZ();   // world unit normal, pointing from a to b
  double depth = 0.0;            // penetration (> 0 overlapping, < 0 separated within margin)
  uint32_t feature = 0;          // stable id of the feature pair, for matching points across steps
};

}  // namespace eng::physics
