#version 450
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"
// Depth-only pass from the sun; no fragment shader is needed.
layout(location = 0) in vec3 in_pos;
void main() {
  gl_Position = frame.light_view_proj * (inst[gl_InstanceIndex].model * vec4(in_pos, 1.0));
}
