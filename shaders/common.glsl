// Shared declarations for the scene shaders. Layout mirrors eng::render::FrameUniforms / GpuInstance (std140/std430).

const float PI = 3.14159265;

struct InstanceData {
  mat4 model;
  vec4 color;   // linear rgb, a = opacity (ghosts)
  vec4 params;  // x roughness, y metallic
};

layout(set = 0, binding = 0, std140) uniform FrameUniforms {
  mat4 view_proj;
  mat4 inv_view_proj;
  mat4 light_view_proj;
  vec4 eye;          // xyz camera position, w = zfar
  vec4 sun_dir;      // xyz direction light travels (sun -> scene), unit length; w = intensity
  vec4 sun_color;    // rgb
  vec4 sky_zenith;   // rgb
  vec4 sky_horizon;  // rgb, also the fog colour
  vec4 ground_tint;  // rgb: ambient bounce from the ground
  vec4 fog;          // x = 1/fog distance
  vec4 viewport;     // xy size in px, zw 1/size
  vec4 shadow;       // x texel size (uv), y normal offset (m), z 1 = shadows on, w 1 = the ground's footprint drawn apart
  vec4 ground_footprint[2];  // the shadow map's footprint on the ground (z = 0): 4 corners, xy xy | xy xy
} frame;

layout(set = 0, binding = 1, std430) readonly buffer Instances { InstanceData inst[]; };
layout(set = 0, binding = 2) uniform sampler2DShadow shadow_map;

// 5x5 PCF on a hardware-compared shadow map; the receiver is pushed along its normal (normal-offset) so lit
// faces never self-shadow, on top of the slope-scaled depth bias applied when the map was rendered.
//
// The 5x5 kernel is 25 bilinear compare taps one texel apart. In texel coordinates s = uv * size - 0.5 (integer
// part i, fraction f) their sum weighs the texels i-2 .. i+3 of each axis by [1-f, 1, 1, 1, 1, f]; one bilinear tap
// weighs two neighbours by (1-t, t), so three taps an axis give the same sum: texels i-2, i-1 at t = 1/(2-f)
// (weight 2-f), i, i+1 at t = 1/2 (weight 2), i+2, i+3 at t = f/(1+f) (weight 1+f). 3 x 3 = 9 taps instead of 25,
// the same result (Castano's "optimized PCF"): on a CPU rasteriser the taps were most of a lit pixel's cost.
float shadow_tap(vec2 s, float z) { return texture(shadow_map, vec3((s + 0.5) * frame.shadow.x, z)); }

float sun_shadow(vec3 P, vec3 N) {
  if (frame.shadow.z < 0.5) return 1.0;
  vec3 L = -frame.sun_dir.xyz;
  float slope = 1.0 - clamp(dot(N, L), 0.0, 1.0);
  vec3 Po = P + N * frame.shadow.y * (0.5 + slope);
  vec4 lc = frame.light_view_proj * vec4(Po, 1.0);
  vec3 ndc = lc.xyz / lc.w;
  vec2 uv = ndc.xy * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || ndc.z >= 1.0) return 1.0;
  vec2 s = uv / frame.shadow.x - 0.5;
  vec2 i = floor(s);
  vec2 f = s - i;
  vec2 wa = 2.0 - f, wc = 1.0 + f;                                 // wb = 2
  vec2 a = i - 2.0 + 1.0 / wa, b = i + 0.5, c = i + 2.0 + f / wc;  // tap positions, in texels
  float z = ndc.z;
  float sum = wa.y * (wa.x * shadow_tap(vec2(a.x, a.y), z) + 2.0 * shadow_tap(vec2(b.x, a.y), z) + wc.x * shadow_tap(vec2(c.x, a.y), z)) +
              2.0 * (wa.x * shadow_tap(vec2(a.x, b.y), z) + 2.0 * shadow_tap(vec2(b.x, b.y), z) + wc.x * shadow_tap(vec2(c.x, b.y), z)) +
              wc.y * (wa.x * shadow_tap(vec2(a.x, c.y), z) + 2.0 * shadow_tap(vec2(b.x, c.y), z) + wc.x * shadow_tap(vec2(c.x, c.y), z));
  return sum / 25.0;
}

// Integer powers by multiplication: pow() is exp2(log2()) on a CPU rasteriser, several times the cost (and no
// more exact). pow_800 by repeated squaring: s^800 = s^512 s^256 s^32.
float pow5(float x) {
  float x2 = x * x;
  return x2 * x2 * x;
}
float pow_12_800(float s, out float s800) {
  float s2 = s * s, s4 = s2 * s2, s8 = s4 * s4, s16 = s8 * s8, s32 = s16 * s16;
  float s64 = s32 * s32, s128 = s64 * s64, s256 = s128 * s128, s512 = s256 * s256;
  s800 = s512 * s256 * s32;
  return s8 * s4;
}

// Sky radiance along a world direction: zenith-to-horizon gradient, a bright horizon band and a soft sun glow.
vec3 sky_color(vec3 dir) {
  float up = clamp(dir.z, -1.0, 1.0);
  vec3 c = mix(frame.sky_horizon.rgb, frame.sky_zenith.rgb, pow(clamp(up, 0.0, 1.0), 0.35));
  c += frame.sky_horizon.rgb * 0.30 * exp(-abs(up) * 30.0);  // brighter haze right at the horizon
  if (up < 0.0) c = mix(c, frame.sky_horizon.rgb * 0.8, clamp(-up * 4.0, 0.0, 1.0));
  vec3 L = -frame.sun_dir.xyz;  // unit length (frame_data.cpp)
  float s = max(dot(dir, L), 0.0);
  float s800;
  float s12 = pow_12_800(s, s800);
  c += frame.sun_color.rgb * (s800 * 6.0 + s12 * 0.15);
  return c;
}

// Fog grows with the square of distance so the foreground stays crisp and the far ground melts into the horizon.
vec3 apply_fog(vec3 c, vec3 P) {
  float d = length(P - frame.eye.xyz) * frame.fog.x;
  float f = 1.0 - exp(-d * d);
  return mix(c, frame.sky_horizon.rgb * 1.2, clamp(f, 0.0, 1.0));
}

// Lambert + GGX (Smith-Schlick G, Schlick F) sun, shadowed by `sh` (1 = fully lit), plus a hemispherical sky/ground
// ambient and a sky reflection. `rough_env` (a constant at each call, so it is folded away): the reflection sees the
// sky's gradient only, without the horizon haze and the sun's glow, for surfaces so rough (the ground: 0.9) that the
// reflection weighs under 0.004 and the difference is under 1/255 after tonemapping.
vec3 shade_env(vec3 albedo, float rough, float metal, vec3 N, vec3 P, float sh, bool rough_env) {
  rough = clamp(rough, 0.05, 1.0);
  vec3 V = normalize(frame.eye.xyz - P);
  vec3 L = -frame.sun_dir.xyz;
  vec3 H = normalize(V + L);
  float NdL = max(dot(N, L), 0.0);
  float NdV = max(dot(N, V), 1e-4);
  float NdH = max(dot(N, H), 0.0);
  float VdH = max(dot(V, H), 0.0);
  float a = rough * rough;
  float a2 = a * a;
  float dn = NdH * NdH * (a2 - 1.0) + 1.0;
  float D = a2 / (PI * dn * dn);
  float k = (rough + 1.0) * (rough + 1.0) / 8.0;
  float G = (NdL / (NdL * (1.0 - k) + k)) * (NdV / (NdV * (1.0 - k) + k));
  vec3 F0 = mix(vec3(0.04), albedo, metal);
  vec3 F = F0 + (1.0 - F0) * pow5(1.0 - VdH);
  vec3 spec = D * G * F / (4.0 * NdL * NdV + 1e-4);
  vec3 kd = (1.0 - F) * (1.0 - metal);
  vec3 sun = frame.sun_color.rgb * frame.sun_dir.w;
  vec3 direct = (kd * albedo / PI + spec) * sun * NdL * sh;
  float hemi = N.z * 0.5 + 0.5;
  // Sky ambient is the average sky (between zenith and horizon), scaled down: the sun carries most light.
  vec3 sky_ambient = mix(frame.sky_horizon.rgb, frame.sky_zenith.rgb, 0.5) * 0.55;
  vec3 ambient_light = mix(frame.ground_tint.rgb * 0.5, sky_ambient, hemi);
  vec3 ambient = ambient_light * albedo * (1.0 - metal);
  // Sky reflection: Fresnel-weighted, fading with roughness; reflections that point below the horizon see the
  // darker ground instead. Gives smooth capsules a readable rim without an environment map.
  vec3 R = reflect(-V, N);
  vec3 Fr = F0 + (max(vec3(1.0 - rough), F0) - F0) * pow5(1.0 - NdV);
  vec3 env = R.z <= 0.0 ? frame.ground_tint.rgb
           : rough_env ? mix(frame.sky_horizon.rgb, frame.sky_zenith.rgb, sqrt(min(R.z, 1.0)))
                       : sky_color(R);
  float gloss = (1.0 - rough) * (1.0 - rough);
  ambient += env * Fr * mix(0.05, 1.0, gloss) * 0.6;
  return direct + ambient;
}

vec3 shade_with_shadow(vec3 albedo, float rough, float metal, vec3 N, vec3 P, float sh) {
  return shade_env(albedo, rough, metal, N, P, sh, false);
}

// The same with the sun shadow looked up here (the direct term is 0 where N faces away, so no test is needed).
vec3 shade(vec3 albedo, float rough, float metal, vec3 N, vec3 P) {
  return shade_with_shadow(albedo, rough, metal, N, P, sun_shadow(P, N));
}

// Filmic curve (Narkowicz ACES fit) so bright sun highlights roll off instead of clipping; the sRGB render
// target applies the gamma encoding on write.
vec3 tonemap(vec3 x) {
  x *= 0.8;
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
