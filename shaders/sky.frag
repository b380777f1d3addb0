#version 450
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"
layout(location = 0) in vec2 ndc;
layout(location = 0) out vec4 out_color;
void main() {
  vec4 a = frame.inv_view_proj * vec4(ndc, 0.0, 1.0);
  vec4 b = frame.inv_view_proj * vec4(ndc, 1.0, 1.0);
  vec3 dir = normalize(b.xyz / b.w - a.xyz / a.w);
  out_color = vec4(tonemap(sky_color(dir)), 1.0);
}
