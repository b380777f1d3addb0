#version 450
// Debug lines and points are drawn unlit in their exact colour (sRGB target encodes; colours are given in sRGB
// so convert to linear first, so a requested (1,0,0) stays pure red and (0.5,0.5,0.5) reads back as ~128).
layout(location = 0) in vec4 color;
layout(location = 1) in vec2 corner;
layout(location = 0) out vec4 out_color;
vec3 to_linear(vec3 c) { return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(0.04045, c)); }
void main() {
  if (dot(corner, corner) > 1.0) discard;  // round points; lines pass corner = 0
  out_color = vec4(to_linear(color.rgb), color.a);
}
