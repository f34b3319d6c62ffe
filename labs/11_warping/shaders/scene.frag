#version 410 core
// PASS 2 of lab 11: each pixel finds its cascade by view distance (one cascade: the single map),
// looks it up (the sampler's 2x2 comparison), or, in a measuring view, writes the aliasing measure
// instead of visibility: texels per pixel (11.1, WB_VIEW_DENSITY) or one of its two parts (11.2,
// WB_VIEW_PERSPECTIVE, WB_VIEW_PROJECTIVE), over the ground alone (elsewhere 0: not counted).
// WB_CASCADES: more than one map.
// llvmpipe runs both sides of every branch, so each view is compiled in by #define.
#include "exercise.glsl"
#include "wb/lighting.glsl"
#include "wb/outputs.glsl"
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_light[4];
in float v_depth;
uniform vec3 u_color;
uniform sampler2D u_albedo;
uniform int u_hasTexture;
uniform float u_alphaCutoff;
uniform sampler2DArrayShadow u_compare;
uniform mat4 u_cascades[4];
uniform vec4 u_splits;  // the far end of cascades 0..3 (view distance)
uniform int u_count, u_ready;
uniform vec2 u_mapTexels;
uniform vec3 u_eye;
uniform float u_pixelAngle;
uniform float u_biasDepth;  // warp.bias_space=depth: taken off the map's depth after the warp

// Whether cascade i's map holds the point: in front of the warp's eye, inside [-1, 1] on every axis.
bool inMap(int i) {
  vec4 c = v_light[i];
  return c.w > 0.0 && all(lessThanEqual(abs(c.xyz), vec3(c.w)));
}

// The cascade of view distance `depth`: how many inner splits lie at or before it.
int cascadeAt(float depth) {
  vec4 passed = step(u_splits, vec4(depth)) * vec4(lessThan(ivec4(0, 1, 2, 3), ivec4(u_count - 1)));
  return int(dot(passed, vec4(1.0)));
}

// How the map coordinate (0..1) of cascade i moves with a world step v at this point: the
// derivative of (c.xy / c.w) / 2, with c the point's light clip coordinate.
vec2 uvAlong(int i, vec4 c, vec3 v) {
  vec4 dc = u_cascades[i] * vec4(v, 0.0);
  return 0.5 * (dc.xy * c.w - c.xy * dc.w) / (c.w * c.w);
}

// One texel's width across the light at this point (world units): the square root of the world area
// one texel covers on a plane facing the light (constant in an orthographic map, not in a warped one).
float texelWorldAt(int i, vec4 c) {
  vec3 l = normalize(wbToLight(v_world));
  vec3 a = normalize(cross(l, abs(l.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
  vec3 b = cross(l, a);
  vec2 ua = uvAlong(i, c, a) * u_mapTexels, ub = uvAlong(i, c, b) * u_mapTexels;
  return inversesqrt(max(abs(ua.x * ub.y - ua.y * ub.x), 1e-30));
}

void writeTodo(vec3 albedo) {
  wbWriteOutputs(mix(albedo * 0.5, wbTodoPattern(gl_FragCoord.xy), 0.35), WB_TODO, v_world, true);
}

// A measure as a colour on a log2 scale: 1/64 and fewer blue, 1 red, 4 and more yellow.
vec3 measureColour(float m) {
  float t = clamp((log2(max(m, 1e-6)) + 6.0) / 8.0, 0.0, 1.0);
  return vec3(min(1.0, 1.33 * t), max(0.0, 4.0 * t - 3.0) * 0.9 + 0.1, 0.7 * (1.0 - t));
}

void main() {
  vec4 texel = u_hasTexture != 0 ? texture(u_albedo, v_uv) : vec4(1.0);
  if (texel.a < u_alphaCutoff) discard;
  vec3 albedo = u_color * texel.rgb;
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 toLight = wbToLight(v_world);
  bool facesLight = dot(n, toLight) > 0.0;
  if (u_ready == 0) {
    writeTodo(albedo);
    return;
  }
  int i = cascadeAt(v_depth);
#ifdef WB_CASCADES  // a pixel outside its cascade's map reads the next cascade whose map holds it (a
                    // coarser one, never a pixel lit for want of a map); where none does, the last
  for (int k = 0; k < 3; ++k)
    if (i + 1 < u_count && !inMap(i)) i += 1;
#endif
  vec4 c = v_light[i];
#if defined(WB_VIEW_DENSITY)
  vec2 t = texelsPerPixel(uvAlong(i, c, dFdx(v_world)), uvAlong(i, c, dFdy(v_world)), u_mapTexels);
  if (wbIsTodo(t.x) || wbIsTodo(t.y)) {
    writeTodo(albedo);
    return;
  }
  float m = min(t.x, t.y);  // the axis with fewer texels per pixel: where a texel shows as a block
  wbWriteOutputs(measureColour(m), n.y > 0.99 ? m : 0.0, v_world, true);
#elif defined(WB_VIEW_PERSPECTIVE) || defined(WB_VIEW_PROJECTIVE)
  vec2 parts = aliasingParts(u_eye - v_world, n, toLight, u_pixelAngle, texelWorldAt(i, c));
  if (wbIsTodo(parts.x) || wbIsTodo(parts.y)) {
    writeTodo(albedo);
    return;
  }
#ifdef WB_VIEW_PERSPECTIVE
  float m = parts.x;
#else
  float m = parts.y;
#endif
  wbWriteOutputs(measureColour(m), n.y > 0.99 ? m : 0.0, v_world, true);
#else
  vec3 p = c.xyz / c.w * 0.5 + 0.5;
  float visibility = inMap(i) ? texture(u_compare, vec4(p.xy, float(i), p.z - u_biasDepth)) : 1.0;
  vec3 colour = wbShade(albedo, n, toLight, vec3(wbLightReach(v_world)), visibility);
  wbWriteOutputs(colour, visibility, v_world, facesLight);
#endif
}
