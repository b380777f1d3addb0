#version 450
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"
// Screen-space quads: one instance per point, six vertices expanded here so size is in pixels at any depth.
layout(location = 0) in vec4 in_point;  // xyz position, w size in px
layout(location = 1) in vec4 in_color;
layout(location = 0) out vec4 color;
layout(location = 1) out vec2 corner;
void main() {
  const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
  corner = corners[gl_VertexIndex];
  color = in_color;
  vec4 c = frame.view_proj * vec4(in_point.xyz, 1.0);
  c.xy += corner * in_point.w * frame.viewport.zw * c.w;
  gl_Position = c;
}
