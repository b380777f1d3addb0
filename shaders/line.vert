#version 450
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"
layout(location = 0) in vec3 in_pos;
layout(location = 1) in vec4 in_color;
layout(location = 0) out vec4 color;
layout(location = 1) out vec2 corner;
void main() {
  color = in_color;
  corner = vec2(0.0);
  gl_Position = frame.view_proj * vec4(in_pos, 1.0);
}
