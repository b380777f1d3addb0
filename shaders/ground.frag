#version 450
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"
layout(location = 0) in vec3 world_pos;
layout(location = 0) out vec4 out_color;

// Anti-aliased grid line coverage for a given cell size: line width in metres, widened to at least ~1px
// (via fwidth) and faded as the cells shrink below a few pixels so distant ground does not shimmer.
float grid(vec2 p, float cell, float width) {
  vec2 q = p / cell;
  vec2 fw = fwidth(q);
  vec2 d = abs(fract(q - 0.5) - 0.5);
  vec2 w = max(vec2(width / cell), fw);
  vec2 l = 1.0 - smoothstep(w - fw, w + fw, d);
  float fade = 1.0 - smoothstep(0.15, 0.5, max(fw.x, fw.y));
  return max(l.x, l.y) * fade;
}

void main() {
  vec2 p = world_pos.xy;
  // Canvas: warm off-white with a faint weave so large flat areas are not dead.
  vec3 base = vec3(0.36, 0.33, 0.28);
  vec2 fw = fwidth(p * 40.0);
  float weave = (sin(p.x * 40.0 * PI) * sin(p.y * 40.0 * PI)) * (1.0 - smoothstep(0.2, 0.8, max(fw.x, fw.y)));
  base *= 1.0 + 0.025 * weave;
  float major = grid(p, 1.0, 0.012);
  float minor = grid(p, 0.25, 0.005);
  base = mix(base, base * 0.85, minor * 0.4);
  base = mix(base, base * 0.65, major * 0.6);
  vec3 N = vec3(0.0, 0.0, 1.0);
  vec3 c = shade(base, 0.9, 0.0, N, world_pos);
  out_color = vec4(tonemap(apply_fog(c, world_pos)), 1.0);
}
