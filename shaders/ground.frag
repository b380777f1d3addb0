#version 450
#extension GL_GOOGLE_include_directive : require
#include "common.glsl"
layout(location = 0) in vec3 world_pos;
layout(location = 0) out vec4 out_color;

// GroundVariant (pipelines.cpp): 0 = inside the shadow map's footprint, shadowed (the 5x5 PCF); 1 = the rest of
// the ground, where no shadow can fall: unshadowed, and it leaves the footprint's inner part to variant 0 (both
// draw the thin band at its edge, where the map holds no caster and both give the same lit colour).
layout(constant_id = 0) const int kVariant = 0;

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

// sin(pi x) to within 0.001 (a parabola and one correction, after Bhaskara): the weave's 2.5% ripple does not need
// the library sine's range reduction and polynomial, which a CPU rasteriser pays per pixel.
float sin_pi(float x) {
  float t = x - 2.0 * floor(0.5 * x + 0.5);  // in [-1, 1), same phase
  float y = 4.0 * t * (1.0 - abs(t));
  return 0.225 * (y * abs(y) - y) + y;
}

void main() {
  vec2 p = world_pos.xy;
  // Canvas: warm off-white with a faint weave so large flat areas are not dead.
  vec3 base = vec3(0.36, 0.33, 0.28);
  vec2 fw = fwidth(p * 40.0);
  float weave = sin_pi(p.x * 40.0) * sin_pi(p.y * 40.0) * (1.0 - smoothstep(0.2, 0.8, max(fw.x, fw.y)));
  base *= 1.0 + 0.025 * weave;
  float major = grid(p, 1.0, 0.012);
  float minor = grid(p, 0.25, 0.005);
  base = mix(base, base * 0.85, minor * 0.4);
  base = mix(base, base * 0.65, major * 0.6);
  vec3 N = vec3(0.0, 0.0, 1.0);
  float sh = kVariant == 0 ? sun_shadow(world_pos, N) : 1.0;
  vec3 c = shade_env(base, 0.9, 0.0, N, world_pos, sh, true);
  out_color = vec4(tonemap(apply_fog(c, world_pos)), 1.0);
  if (kVariant == 1 && frame.shadow.w > 0.5) {  // (after the derivatives above, which need the whole quad)
    vec4 lc = frame.light_view_proj * vec4(world_pos, 1.0);
    vec2 uv = lc.xy / lc.w * 0.5 + 0.5;
    if (all(greaterThan(uv, vec2(0.02))) && all(lessThan(uv, vec2(0.98)))) discard;
  }
}
