#version 450
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"
// A square at z=0 that follows the camera, so the ground looks endless; fog hides its edge.
layout(location = 0) out vec3 world_pos;
void main() {
  const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
  float r = frame.eye.w * 0.98;
  vec3 p = vec3(floor(frame.eye.xy) + corners[gl_VertexIndex] * r, 0.0);
  world_pos = p;
  gl_Position = frame.view_proj * vec4(p, 1.0);
}
