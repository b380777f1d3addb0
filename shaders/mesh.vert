#version 450
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"
layout(location = 0) in vec3 in_pos;
layout(location = 1) in vec3 in_normal;
layout(location = 0) out vec3 world_pos;
layout(location = 1) out vec3 world_normal;
layout(location = 2) flat out uint instance;
void main() {
  InstanceData d = inst[gl_InstanceIndex];
  vec4 wp = d.model * vec4(in_pos, 1.0);
  world_pos = wp.xyz;
  // Inverse-transpose keeps normals perpendicular under non-uniform scale.
  world_normal = transpose(inverse(mat3(d.model))) * in_normal;
  instance = gl_InstanceIndex;
  gl_Position = frame.view_proj * wp;
}
