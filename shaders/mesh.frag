#version 450
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"
layout(location = 0) in vec3 world_pos;
layout(location = 1) in vec3 world_normal;
layout(location = 2) flat in uint instance;
layout(location = 0) out vec4 out_color;
void main() {
  InstanceData d = inst[instance];
  vec3 N = normalize(world_normal);
  vec3 c = shade(d.color.rgb, d.params.x, d.params.y, N, world_pos);
  out_color = vec4(tonemap(apply_fog(c, world_pos)), d.color.a);
}
