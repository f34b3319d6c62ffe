#version 410 core
// PASS 2 of lab 08: the point light's shadow from the cube map, hard (08.4) or soft (08.5).
#include "exercise.glsl"
#include "wb/lighting.glsl"
#include "wb/outputs.glsl"
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
uniform vec3 u_color;
uniform sampler2D u_albedo;
uniform int u_hasTexture;
uniform float u_alphaCutoff;
uniform samplerCube u_cube;
uniform vec3 u_lightPos;
uniform float u_far, u_bias, u_radius;
uniform float u_slopeScale;  // cube.slope_bias: 0.5 (half a texel) or 0
uniform int u_samples;

void main() {
  vec4 texel = u_hasTexture != 0 ? texture(u_albedo, v_uv) : vec4(1.0);
  if (texel.a < u_alphaCutoff) discard;
  vec3 albedo = u_color * texel.rgb;
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 toLight = normalize(u_lightPos - v_world);
  bool facesLight = dot(n, toLight) > 0.0;
#if CUBE_FILTER == 1
  // (PCF keeps the constant bias: its exact reference, the same 3D taps ray-traced, uses it too.)
  float visibility = cubePcf(u_cube, v_world, u_lightPos, u_far, u_bias, u_radius, u_samples);
#else
  // The hard test's bias grows with the slope: a texel is about 2 d / size wide at distance d (a face
  // spans 90 degrees), and a surface at angle t to the light changes its distance by tan t across
  // it; a sample lies within half a texel of its texel's centre. A constant bias alone is too small
  // on faces nearly edge-on to the light (acne: 3% of a shadow's area at 1024 x 1024 a face).
  float cosT = clamp(dot(n, toLight), 0.1, 1.0);
  float texelWorld = 2.0 * length(u_lightPos - v_world) / float(textureSize(u_cube, 0).x);
  float slopeBias = u_slopeScale * texelWorld * sqrt(1.0 - cosT * cosT) / cosT;
  float visibility = cubeShadow(u_cube, v_world, u_lightPos, u_far, u_bias + slopeBias);
#endif
  if (wbIsTodo(visibility)) {  // a stub: show it, never fake a shadow
    wbWriteOutputs(mix(albedo * 0.5, wbTodoPattern(gl_FragCoord.xy), 0.35), WB_TODO, v_world, true);
    return;
  }
  // A lantern: light falls off with distance, gently, so the room reads as lit from one point.
  float d = length(u_lightPos - v_world), falloff = min(1.2, 1.6 / (1.0 + 0.25 * d * d));
  wbWriteOutputs(wbShade(albedo, n, toLight, vec3(falloff * wbLightReach(v_world)), visibility), visibility, v_world, facesLight);
}
