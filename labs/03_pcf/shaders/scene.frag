#version 410 core
// PASS 2 of lab 03: the shadow test, filtered by the chosen PCF kernel.
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
uniform sampler2D u_shadowMap;              // explicit taps read raw depths
uniform sampler2DShadow u_shadowCompare;  // the same map, compared by the hardware
uniform mat4 u_lightViewProj;
uniform float u_bias;
uniform int u_radius;   // pcf.kernel: width 2r + 1
uniform float u_spacing, u_sigma, u_poissonRadius;
uniform int u_poissonCount;

void main() {
  vec4 texel = u_hasTexture != 0 ? texture(u_albedo, v_uv) : vec4(1.0);
  if (texel.a < u_alphaCutoff) discard;
  vec3 albedo = u_color * texel.rgb;
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 toLight = wbToLight(v_world);

  vec4 clip = u_lightViewProj * vec4(v_world, 1.0);
  vec3 coord = clip.xyz / clip.w * 0.5 + 0.5;
  // One program per filter (the lab injects PCF_METHOD), so no pixel pays for the branches it skips.
  // Each filter's bias grows with how far its taps reach from the point, in texels along an axis
  // (03.H2): the hardware's 2 x 2 reaches one texel, a grid radius * spacing.
#if PCF_METHOD == 1
  float visibility = pcfHardware(u_shadowCompare, coord, filterBias(u_bias, 1.0));
#elif PCF_METHOD == 2
  float bias = filterBias(u_bias, float(u_radius) * u_spacing);
  float visibility = pcfGaussian(u_shadowMap, coord, u_radius, u_spacing, u_sigma, bias);
#elif PCF_METHOD == 3
  float bias = filterBias(u_bias, u_poissonRadius);
  float visibility = pcfPoisson(u_shadowMap, coord, u_poissonCount, u_poissonRadius, uvec2(gl_FragCoord.xy), bias);
#elif PCF_METHOD == 4
  float visibility = pcfGather(u_shadowMap, coord, u_radius, filterBias(u_bias, float(u_radius)));
#else
  float visibility = pcfGrid(u_shadowMap, coord, u_radius, u_spacing, filterBias(u_bias, float(u_radius) * u_spacing));
#endif
  // Beyond the map (its uv square, or past the light's near and far planes) nothing is known: lit.
  if (!wbIsTodo(visibility) && !insideShadowMap(coord)) visibility = 1.0;
  if (wbIsTodo(visibility)) {  // the chosen filter is a stub: show it, never fake a shadow
    wbWriteOutputs(mix(albedo * 0.5, wbTodoPattern(gl_FragCoord.xy), 0.35), WB_TODO, v_world, true);
    return;
  }
  bool facesLight = dot(n, toLight) > 0.0;
  wbWriteOutputs(wbShade(albedo, n, toLight, vec3(wbLightReach(v_world)), visibility), visibility, v_world, facesLight);
}
