// PASS 2 of lab 10 (scene.frag; scene_esm/vsm/evsm.frag for csm.filter): each pixel picks its cascade
// (10.5), looks it up (2x2 PCF, or lab 04's ESM, 05's VSM or 06's EVSM), and in the band before a
// split blends with the next cascade (10.6). llvmpipe runs both sides of every branch, even
// one whose condition is a uniform, so the debug views and options are compiled in by #define
// (WB_SELECT_MAP, WB_SMOOTH_BLEND, WB_DENSITY, WB_TINT, WB_REGION, WB_ONE_TAP) instead of switched by
// uniforms.
#include "exercise.glsl"
#include "wb/lighting.glsl"
#include "wb/outputs.glsl"
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in vec3 v_light[4];  // the point in each cascade's light clip space (cascades.vert)
in float v_depth;    // its view distance
uniform vec3 u_color;
uniform sampler2D u_albedo;
uniform int u_hasTexture;
uniform float u_alphaCutoff;
uniform sampler2DArray u_maps;
uniform sampler2DArrayShadow u_compare;  // the same maps, through a comparing sampler
uniform mat4 u_cascades[4];
uniform float u_splits[4];     // the far end of each cascade (view distance)
uniform float u_splitNear[4];  // the near end
uniform mat4 u_view;  // (cascades.vert)
uniform int u_count, u_ready;
uniform float u_band, u_bias;
uniform int u_kernel;            // csm.kernel: PCF taps per side
uniform vec2 u_uvPerWorld[4];    // map coordinates per world unit, along the map's x and y
uniform float u_tapWorld;        // the tap spacing: cascade 0's texel, in world units
uniform int u_region;            // measure.region: 0 all, 1-4 cascade 0-3, 5 near the splits, 6 the rest

// Whether cascade i's map holds the point (the blend band may reach past the next cascade's map).
bool inMap(int i) { return all(lessThanEqual(abs(v_light[i]), vec3(1.0))); }

#if defined(WB_VSM) || defined(WB_ESM) || defined(WB_EVSM)
uniform sampler2DArray u_moments;  // each cascade's filtered warp or moments
uniform float u_minVariance, u_bleeding;               // VSM and EVSM
uniform float u_c, u_cNeg;                             // ESM's c; EVSM's positive and negative exponents

// The lit share from cascade i's filtered map through your functions of lab 04, 05 or 06, or 1
// outside its map (WB_TODO until that lab is done).
float lookup(int i) {
  if (!inMap(i)) return 1.0;
  vec3 p = v_light[i] * 0.5 + 0.5;
  vec4 m = texture(u_moments, vec3(p.xy, float(i)));
  if (wbIsTodo(m.x)) return WB_TODO;
#if defined(WB_ESM)
  return esmVisibility(log(max(m.x, 1e-37)), p.z, u_c);
#elif defined(WB_EVSM)
  return evsmVisibility(m, p.z, u_c, u_cNeg, u_minVariance, u_bleeding, 4);
#else
  float bound = chebyshevUpperBound(m.xy, p.z, u_minVariance);
  return wbIsTodo(bound) ? WB_TODO : reduceLightBleeding(bound, u_bleeding);
#endif
}
#else
// The lit share of cascade i's 2x2 texel neighbourhood (the sampler's bilinear comparison, 2x2 PCF),
// or 1 outside its map.
float lookup(int i) {
  if (!inMap(i)) return 1.0;
  vec3 p = v_light[i] * 0.5 + 0.5;
#ifdef WB_ONE_TAP  // csm.kernel=1: cascadePcf's one tap, without its loop (a fifth of the pass on llvmpipe)
  return texture(u_compare, vec4(p.xy, float(i), p.z - u_bias));
#else
  return cascadePcf(u_compare, p, i, u_bias, u_kernel, u_tapWorld, u_uvPerWorld);
#endif
}
#endif

// A pixel whose exercise is still a stub: shown as such, never a faked shadow.
void writeTodo(vec3 albedo) {
  wbWriteOutputs(mix(albedo * 0.5, wbTodoPattern(gl_FragCoord.xy), 0.35), WB_TODO, v_world, true);
}

// debug.cascades: red, green, blue, yellow.
vec3 cascadeTint(int i) {
  return i == 0 ? vec3(1.0, 0.35, 0.35) : i == 1 ? vec3(0.35, 1.0, 0.35) : i == 2 ? vec3(0.35, 0.5, 1.0) : vec3(1.0, 1.0, 0.3);
}

// measure.region: whether --metrics counts this pixel. "Near the splits" is within 10% of the
// neighbouring cascade's depth range of an inner split, on either side, whatever the blend band.
bool inRegion(int i, float depth) {
  if (u_region == 0) return true;
  if (u_region <= 4) return i == u_region - 1;
  bool near = false;
  for (int j = 0; j + 1 < u_count; ++j) {
    float split = u_splits[j], below = split - u_splitNear[j], above = u_splits[j + 1] - split;
    near = near || (depth > split - 0.1 * below && depth < split + 0.1 * above);
  }
  return near == (u_region == 5);
}

void main() {
  vec4 texel = u_hasTexture != 0 ? texture(u_albedo, v_uv) : vec4(1.0);
  if (texel.a < u_alphaCutoff) discard;
  vec3 albedo = u_color * texel.rgb;
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 toLight = wbToLight(v_world);
  bool facesLight = dot(n, toLight) > 0.0;
  float depth = v_depth;
  vec4 splits = vec4(u_splits[0], u_splits[1], u_splits[2], u_splits[3]);
#ifdef WB_SELECT_MAP
  int i = cascadeByMap(v_world, u_cascades, u_count);
#else
  int i = cascadeByInterval(depth, splits, u_count);
#endif
  // The stub's -1 is tested before i indexes anything: NVIDIA inlines the stub, folds the -1 into
  // u_splitNear[-1] and rejects the whole shader (C1068), so lab 10 would not start until 10.5 is done.
  if (u_ready == 0 || i < 0) {
    writeTodo(albedo);
    return;
  }
  // A wrong answer past the cascades is drawn shadowed, in solid magenta, never looked up out of
  // bounds. (i > 3 as well: a constant past the arrays is folded and rejected like the -1.)
  if (i >= u_count || i > 3) {
    wbWriteOutputs(vec3(1.0, 0.0, 1.0), 0.0, v_world, facesLight);
    return;
  }
  int next = min(i + 1, 3);  // i + 1 wherever it is used (w > 0), and never a constant past the arrays
  float w = i + 1 < u_count ? blendWeight(depth, u_splitNear[i], u_splits[i], u_band) : 0.0;
  if (wbIsTodo(w)) {
    writeTodo(albedo);
    return;
  }
#ifdef WB_SELECT_MAP
  if (depth >= u_splits[i]) w = 0.0;  // the map kept a finer cascade past its split: no band there
#endif
  if (w > 0.0 && !inMap(next)) w = 0.0;  // a band point outside the next map: this one alone
#ifdef WB_DENSITY  // the aliasing measure: how many texels of cascade i one pixel spans
  // The screen derivatives of the world position, carried through cascade i's (affine) matrix: the
  // derivatives of v_light[i] itself would mix cascades where a 2x2 quad straddles a split, and
  // draw a row of huge densities along it.
  vec2 texelsPerClip = 0.5 * vec2(textureSize(u_maps, 0).xy);
  vec2 tx = (u_cascades[i] * vec4(dFdx(v_world), 0.0)).xy * texelsPerClip;
  vec2 ty = (u_cascades[i] * vec4(dFdy(v_world), 0.0)).xy * texelsPerClip;
  float texels = max(length(tx), length(ty));
  // The measure (the visibility output) keeps the ground alone, where the split scheme is the only
  // cause of change with distance; a wall's or a leaf's own slope to the light and the eye would mix
  // in an aliasing no split can remove. The colour shows every surface.
  wbWriteOutputs(vec3(clamp(log2(texels) / 8.0 + 0.5, 0.0, 1.0), 0.2, 0.2), n.y > 0.99 ? texels : 0.0, v_world,
                 true);
#else
#ifdef WB_SMOOTH_BLEND  // both cascades, mixed
  float visibility = lookup(i);
  if (w > 0.0) visibility = mix(visibility, lookup(next), w);
#else  // dithered: the next cascade where w beats a per-pixel threshold (interleaved gradient noise)
  float threshold = fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
  float visibility = lookup(w > threshold ? next : i);
#endif
  if (wbIsTodo(visibility)) {  // csm.filter=esm, vsm or evsm before that lab is done
    writeTodo(albedo);
    return;
  }
  vec3 colour = wbShade(albedo, n, toLight, vec3(wbLightReach(v_world)), visibility);
#ifdef WB_TINT
  colour *= mix(cascadeTint(i), cascadeTint(next), w);
#endif
#ifdef WB_REGION
  bool counted = inRegion(i, depth);
  colour *= counted ? 1.0 : 0.25;
  facesLight = facesLight && counted;
#endif
  wbWriteOutputs(colour, visibility, v_world, facesLight);
#endif
}
