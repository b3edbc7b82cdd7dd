#include "viz/shaders.hpp"

namespace firn::viz::shaders {

const char* const kSphereVertex = R"(#version 330 core
layout(location = 0) in float x0;
layout(location = 1) in float x1;
layout(location = 2) in float x2;
layout(location = 3) in float scalar;
uniform mat4 view, projection;
uniform float radius;
uniform int perspective;
uniform float pixels_per_unit;  // point size of one view-space unit at distance 1 (perspective) or anywhere
out vec3 center_view;
out float value;
void main() {
  vec4 c = view * vec4(x0, x1, x2, 1.0);
  center_view = c.xyz;
  value = scalar;
  if (perspective == 1) {
    // A square sprite around the sphere's silhouette: the sphere subtends the half-angle
    // asin(r / d) and, seen at theta off the view axis, projects to an ellipse whose long axis,
    // on the image plane at distance 1, is tan(asin(r / d)) / cos^2(theta), centred (to second
    // order in r / d) on the projected centre. Plus a pixel for rasterization.
    float d = length(c.xyz), cos_theta = -c.z / d;
    gl_Position = projection * c;
    gl_PointSize = 2.0 * pixels_per_unit * radius / sqrt(max(d * d - radius * radius, 1e-12)) /
                   max(cos_theta * cos_theta, 0.05) + 2.0;
  } else {
    // Orthographic (the shadow pass): the sphere's shadow is exactly a disc of radius r.
    gl_Position = projection * c;
    gl_PointSize = 2.0 * radius * pixels_per_unit;
  }
}
)";

const char* const kSphereFragment = R"(#version 330 core
in vec3 center_view;
in float value;
uniform mat4 projection;
uniform float radius;
uniform vec2 inverse_viewport;
uniform int use_scalar;
uniform vec3 base_color;
uniform vec2 scalar_range;
uniform sampler2D color_map;
layout(location = 0) out vec4 albedo_gloss;
layout(location = 1) out vec4 normal_fade;
void main() {
  // The eye ray through this pixel against the sphere (Real-Time Rendering, 4th ed., 22.6.2).
  vec2 ndc = 2.0 * gl_FragCoord.xy * inverse_viewport - 1.0;
  vec3 dir = normalize(vec3(ndc.x / projection[0][0], ndc.y / projection[1][1], -1.0));
  float b = dot(center_view, dir);
  float h = b * b - (dot(center_view, center_view) - radius * radius);
  if (h < 0.0) discard;
  vec3 hit = (b - sqrt(h)) * dir;
  // Window depth of the hit: the projection's z and w rows applied to it (w = -z).
  gl_FragDepth = 0.5 * (projection[2][2] * hit.z + projection[3][2]) / -hit.z + 0.5;
  vec3 albedo = base_color;
  if (use_scalar == 1) {
    float u = clamp((value - scalar_range.x) / max(scalar_range.y - scalar_range.x, 1e-30), 0.0, 1.0);
    albedo = texture(color_map, vec2(u, 0.5)).rgb;
  }
  albedo_gloss = vec4(albedo, 0.12);
  normal_fade = vec4(0.5 * (hit - center_view) / radius + 0.5, 0.0);
}
)";

const char* const kSphereShadowFragment = R"(#version 330 core
void main() {
  vec2 q = 2.0 * gl_PointCoord - 1.0;
  if (dot(q, q) > 1.0) discard;
}
)";

const char* const kMeshVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 rest_position;  // the snow surface's material coordinates; 0 elsewhere
uniform mat4 view, projection;
out vec3 p_view;
out vec3 n_view;
out vec3 p_world;
out vec3 x0;
void main() {
  vec4 p = view * vec4(position, 1.0);
  p_view = p.xyz;
  n_view = mat3(view) * normal;
  p_world = position;
  x0 = rest_position;
  gl_Position = projection * p;
}
)";

const char* const kMeshFragment = R"(#version 330 core
in vec3 p_view;
in vec3 n_view;
in vec3 p_world;
uniform vec3 base_color;
uniform float checker;       // ground tile size (m); 0: plain
uniform vec3 fade_center;    // the ground fades into the background away from here
uniform float fade_radius;   // 0: no fade
uniform float gloss;         // weight of the specular highlight (below 0.5: not snow)
layout(location = 0) out vec4 albedo_gloss;
layout(location = 1) out vec4 normal_fade;
void main() {
  vec3 n = normalize(n_view);
  if (dot(n, p_view) > 0.0) n = -n;  // the side facing the eye
  vec3 albedo = base_color;
  if (checker > 0.0) {
    vec2 cell = floor(p_world.xz / checker);
    albedo *= mod(cell.x + cell.y, 2.0) < 0.5 ? 1.0 : 0.92;
  }
  float fade = fade_radius > 0.0 ? smoothstep(0.4 * fade_radius, fade_radius, length(p_world - fade_center)) : 0.0;
  albedo_gloss = vec4(albedo, gloss);
  normal_fade = vec4(0.5 * n + 0.5, fade);
}
)";

const char* const kSnowFragment = R"(#version 330 core
in vec3 p_view;
in vec3 n_view;
in vec3 x0;
uniform int facets;   // 1: hoar crystals, flat per facet and sparkling; 0: the snow surface
uniform float grain;  // snow grain size in material coordinates (m)
layout(location = 0) out vec4 albedo_gloss;
layout(location = 1) out vec4 normal_fade;
// PCG3D (Jarzynski and Olano 2020, "Hash functions for GPU rendering"): 3 uints -> 3 in [0, 1).
vec3 random3(ivec3 c) {
  uvec3 v = uvec3(c) * 1664525u + 1013904223u;
  v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
  return vec3(v) * (1.0 / 4294967296.0);
}
void main() {
  vec3 n;
  float sparkle;
  if (facets == 1) {
    // A crystal's facets are flat: the normal of the triangle itself, from the screen-space
    // derivatives of the position, not the prism's vertex normals (shared between facets).
    n = normalize(cross(dFdx(p_view), dFdy(p_view)));
    sparkle = 1.0;
  } else {
    // Grains: the cells of Worley's cellular texture (Worley 1996; one jittered feature point
    // per cube of side `grain`, the nearest of the 27 around wins) in material coordinates, so a
    // grain stays on its piece of snow from frame to frame and its edges follow no grid. Each
    // grain tilts the normal by a hashed vector (a facet of its own); one in five is a facet
    // that sparkles.
    vec3 q = x0 / grain;
    ivec3 base = ivec3(floor(q)), nearest = base;
    float best = 1e9;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          ivec3 c = base + ivec3(dx, dy, dz);
          vec3 f = vec3(c) + random3(c) - q;
          float d = dot(f, f);
          if (d < best) best = d, nearest = c;
        }
    vec3 r = random3(nearest + ivec3(7919, 104729, 1299709));
    n = normalize(n_view);
    vec3 tilt = 2.0 * r - 1.0;
    n = normalize(n + 0.15 * (tilt - dot(tilt, n) * n));
    sparkle = r.x < 0.2 ? 0.5 : 0.0;
  }
  if (dot(n, p_view) > 0.0) n = -n;  // the side facing the eye
  // The thesis' snow albedo (0.9, 0.95, 1.0), stored as its square root (the lighting pass
  // squares colours into linear light); alpha = 0.5 + sparkle / 2 marks snow.
  albedo_gloss = vec4(sqrt(vec3(0.9, 0.95, 1.0)), 0.5 + 0.5 * sparkle);
  normal_fade = vec4(0.5 * n + 0.5, 0.0);
}
)";

const char* const kDepthOnlyFragment = R"(#version 330 core
void main() {}
)";

const char* const kCompositeVertex = R"(#version 330 core
out vec2 uv;
void main() {
  vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  uv = 0.5 * p + 0.5;
  gl_Position = vec4(p, 0.0, 1.0);
}
)";

// Declarations and functions both full-screen passes use (inserted after their #version line):
// view-space positions rebuilt from the depth buffer.
const char* const kScreenFunctions = R"(
uniform sampler2D depth_tex;
uniform ivec2 viewport;          // pixels of the depth buffer
uniform float near_plane, far_plane;
uniform vec2 projection_scale;   // projection[0][0], projection[1][1]
// Exact texel reads (texelFetch): no filtering, and far cheaper than texture() on llvmpipe.
float depth_at(ivec2 at) { return texelFetch(depth_tex, clamp(at, ivec2(0), viewport - 1), 0).r; }
float eye_depth(ivec2 at) {
  float z = 2.0 * depth_at(at) - 1.0;
  return 2.0 * near_plane * far_plane / (far_plane + near_plane - z * (far_plane - near_plane));
}
vec3 view_position(ivec2 at, float z) {
  return vec3((2.0 * (vec2(at) + 0.5) / vec2(viewport) - 1.0) * z / projection_scale, -z);
}
vec3 view_normal(vec4 stored) { return normalize(2.0 * stored.xyz - 1.0); }
)";

// Ambient occlusion at half resolution: the Alchemy screen-space obscurance (McGuire et al.
// 2011). For neighbours p_i rebuilt from the depth buffer on a golden-angle spiral,
// A = 1 - s / N sum max(0, v_i . n - bias) / (v_i . v_i + eps), v_i = p_i - p, with a falloff at
// `ao_range`; points in the pixel's own tangent plane (a flat ground) never occlude. Writes A
// (1 where nothing is drawn); the lighting pass reads it back bilinearly.
const char* const kOcclusionFragment = R"(#version 330 core
uniform sampler2D normal_tex;
uniform float ao_radius_px;      // in full-resolution pixels
uniform float ao_range;          // m
out float visibility;
// Sample i at radius sqrt((i + 1/2) / 8) and angle 2.39996 i (the golden angle), precomputed.
const vec2 kSpiral[8] = vec2[](vec2(0.2500, 0.0000), vec2(-0.3193, 0.2925), vec2(0.0489, -0.5569),
                               vec2(0.4024, 0.5249), vec2(-0.7385, -0.1306), vec2(0.6996, -0.4450),
                               vec2(-0.2340, 0.8705), vec2(-0.4463, -0.8593));
void main() {
  ivec2 pixel = 2 * ivec2(gl_FragCoord.xy);
  vec4 nf = texelFetch(normal_tex, pixel, 0);
  if (depth_at(pixel) >= 1.0 || nf.w >= 1.0) {
    visibility = 1.0;
    return;
  }
  vec3 p = view_position(pixel, eye_depth(pixel)), n = view_normal(nf);
  float sum = 0.0, r2 = ao_range * ao_range;
  for (int i = 0; i < 8; ++i) {
    ivec2 at = pixel + ivec2(round(kSpiral[i] * ao_radius_px));
    vec3 v = view_position(at, eye_depth(at)) - p;
    float vv = dot(v, v);
    sum += max(0.0, dot(v, n) - 0.05 * ao_range) * ao_range / (vv + 0.01 * r2) * max(0.0, 1.0 - vv / (4.0 * r2));
  }
  visibility = 1.0 - 0.8 * clamp(sum / 8.0, 0.0, 1.0);
}
)";

// Lighting in view space: a key light with a shadow map looked up with percentage-closer
// filtering (Reeves et al. 1987; one bilinear comparison) and a normal-offset bias, a hemisphere ambient term, a
// Blinn-Phong highlight and the occlusion pass's result. Then a mild Reinhard-style tone curve.
// Colours go to linear light and back with gamma 2 (squares and square roots: far cheaper than
// pow on llvmpipe, and close to sRGB's 2.2).
//
// Snow (albedo alpha >= 0.5; DESIGN.md section 7, thesis sections 4.2 and 5.3) replaces the
// Lambert and Blinn-Phong terms by an approximate subsurface model, with a = (0.9, 0.95, 1.0):
// - multiple scattering as wrap lighting (Green 2004, "Real-time approximations to subsurface
//   scattering", GPU Gems ch. 16): a max(0, (n.l + w) / (1 + w)), w = 0.5, so light bleeds past
//   the terminator and the snow's shading stays soft; the shadow map is faded out over the
//   wrapped band (where the surface shadows itself) so the terminator shows no step;
// - single scattering of a semi-infinite layer (Hanrahan and Krueger 1993, first-order term):
//   a p_HG(cos t) pi n.l / (n.l + n.v) with the Henyey-Greenstein phase function
//   p_HG = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos t)^(3/2)), g = 0.5 (the thesis' value), t the
//   angle between the light's and the eye ray's directions of travel: snow lit from behind glows
//   at its rim;
// - sparkle s (alpha = 0.5 + s / 2: 1 on hoar crystal facets, 0.5 on one grain in five): the
//   key light reflected in a tight Blinn-Phong lobe 4 s (n.h)^128 on the facet's own normal
//   (Blinn 1977), so single grains flash; a crystal is a thin plate of ice that light crosses, so
//   sparkling facets also take a wider wrap, w = 0.5 + s / 2 (Green's full wrap for crystals).
// With SUBSURFACE 0 snow is plain Lambertian with the same albedo (for comparison). Snow is
// exposed at 0.75 so that lit snow reads white without clipping to the tone curve's top.
const char* const kCompositeFragment = R"(#version 330 core
in vec2 uv;
uniform sampler2D albedo_tex, normal_tex, occlusion_tex;
uniform sampler2DShadow shadow_map;
uniform vec3 light_dir_view;     // towards the light
uniform vec3 up_view;
uniform mat4 view_to_shadow;     // view space -> shadow map [0,1]^3
uniform float shadow_bias;       // normal offset (m)
uniform vec3 background_top, background_bottom;
out vec4 color;
float lit_fraction(vec3 p, vec3 n) {
#if !SHADOWS
  return 1.0;
#endif
  vec4 s = view_to_shadow * vec4(p + n * shadow_bias, 1.0);
  if (any(lessThan(s.xyz, vec3(0.0))) || any(greaterThan(s.xyz, vec3(1.0)))) return 1.0;
  // One bilinear comparison: the 2x2 texels around the point, weighted.
  return texture(shadow_map, vec3(s.xy, s.z - 2e-4));
}
vec3 snow_radiance(vec3 a, vec3 n, vec3 v, float lit, float sparkle, float nh, vec3 ambient) {
  vec3 light = vec3(1.0, 0.97, 0.92) * 1.05;
  float nl = dot(n, light_dir_view), nv = max(dot(n, v), 0.0);
#if SUBSURFACE
  const float g = 0.5;
  float w = 0.5 + 0.5 * sparkle;
  float wrapped = max(0.0, (nl + w) / (1.0 + w)) * mix(1.0, lit, smoothstep(-w, 0.25, nl));
  float cos_t = dot(-light_dir_view, v), phase = (1.0 - g * g) / (4.0 * pow(1.0 + g * g - 2.0 * g * cos_t, 1.5));
  float single = phase * max(nl, 0.0) / (max(nl, 0.0) + nv + 1e-4) * lit;
  vec3 c = a * light * wrapped + a * light * single + a * ambient;
#else
  vec3 c = a * (light * max(nl, 0.0) * lit + ambient);
#endif
  c += vec3(4.0 * sparkle * pow(nh, 128.0) * lit * step(0.0, nl));
  return c;
}
void main() {
  vec3 background = mix(background_bottom, background_top, uv.y);
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 ag = texelFetch(albedo_tex, pixel, 0), nf = texelFetch(normal_tex, pixel, 0);
  if (depth_at(pixel) >= 1.0 || nf.w >= 1.0) {  // nothing drawn, or the ground faded out
    color = vec4(background, 1.0);
    return;
  }
  vec3 n = view_normal(nf);
  vec3 p = view_position(pixel, eye_depth(pixel));
  vec3 albedo = ag.rgb * ag.rgb;
  float lit = lit_fraction(p, n);
  float diffuse = max(dot(n, light_dir_view), 0.0) * lit;
  vec3 ambient = mix(vec3(0.16, 0.15, 0.14), vec3(0.30, 0.34, 0.42), 0.5 + 0.5 * dot(n, up_view));
  vec3 h = normalize(light_dir_view + normalize(-p));
  float s1 = max(dot(n, h), 0.0), s3 = s1 * s1 * s1, s6 = s3 * s3, s12 = s6 * s6, s24 = s12 * s12;
  vec3 c;
  if (ag.a < 0.5) {
    float spec = ag.a * s24 * s24 * lit;  // (n . h)^48 by multiplications, cheaper than pow()
    c = albedo * (vec3(1.0, 0.97, 0.92) * 1.05 * diffuse + ambient) + vec3(spec);
  } else {
    c = 0.75 * snow_radiance(albedo, n, normalize(-p), lit, 2.0 * ag.a - 1.0, s1, ambient);
  }
#if AMBIENT_OCCLUSION
  c *= texture(occlusion_tex, uv).r;
#endif
  c = c / (1.0 + 0.15 * c);
  c = sqrt(c);
  color = vec4(mix(c, background, nf.w), 1.0);
}
)";

}  // namespace firn::viz::shaders
