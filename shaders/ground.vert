#version 450
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"
// The ground plane z = 0, two quads. Instance 0: a square that follows the camera, so the ground looks endless
// (fog hides its edge). Instance 1: the shadow map's footprint (frame.ground_footprint), drawn first with the
// shadowed variant of ground.frag; the square's variant then skips what the footprint covered.
layout(location = 0) out vec3 world_pos;
void main() {
  const int quad[6] = int[](0, 1, 2, 0, 2, 3);
  const vec2 corners[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, 1));
  int k = quad[gl_VertexIndex];
  vec3 p;
  if (gl_InstanceIndex == 1) {
    vec4 f = frame.ground_footprint[k >> 1];
    p = vec3((k & 1) == 0 ? f.xy : f.zw, 0.0);
  } else {
    float r = frame.eye.w * 0.98;
    p = vec3(floor(frame.eye.xy) + corners[k] * r, 0.0);
  }
  world_pos = p;
  gl_Position = frame.view_proj * vec4(p, 1.0);
}
