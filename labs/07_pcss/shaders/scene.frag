#version 410 core
// PASS 2 of lab 07: soft shadows from the spot light's disk, by PCSS (or fixed-width PCF to compare).
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
uniform sampler2D u_shadowMap;
uniform mat4 u_lightViewProj;
uniform vec3 u_lightPos;
uniform vec3 u_lightDir;  // the spot's axis, the direction the light travels
uniform float u_lightSizeUV, u_minFilterUV, u_pcfWidthTexels, u_bias;
uniform vec2 u_nearFar;
uniform float u_lightSize;  // the disk's diameter, world units
uniform int u_searchSamples, u_filterSamples;


void main() {
  vec4 texel = u_hasTexture != 0 ? texture(u_albedo, v_uv) : vec4(1.0);
  if (texel.a < u_alphaCutoff) discard;
  vec3 albedo = u_color * texel.rgb;
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 toLight = wbToLight(v_world);
  vec4 clip = u_lightViewProj * vec4(v_world, 1.0);
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  float zReceiver = dot(v_world - u_lightPos, u_lightDir);  // along the light's axis
  bool facesLight = dot(n, toLight) > 0.0;
  // A receiver tilted by theta changes depth by tan(theta) per unit across the search region (at the
  // receiver, w_light (z - near) / near wide): a quarter of that keeps it from being its own blocker
  // and keeps real blockers near a contact (README, "Receivers that are their own blockers").
  float cosTheta = max(dot(n, toLight), 0.05), tanTheta = sqrt(1.0 - cosTheta * cosTheta) / cosTheta;
  float searchRadius = 0.5 * u_lightSize * (zReceiver - u_nearFar.x) / u_nearFar.x;
  float bias = u_bias + 0.25 * min(tanTheta, 3.0) * searchRadius;
  PcssSettings s = PcssSettings(u_lightSizeUV, u_nearFar, u_searchSamples, u_filterSamples, u_minFilterUV, bias);
  float cone = wbLightReach(v_world);
  if (cone == 0.0 || !facesLight) {  // no light reaches it anyway: spend no taps (a CPU renderer needs them)
    wbWriteOutputs(wbShade(albedo, n, toLight, vec3(0.0), 0.0), 0.0, v_world, facesLight);
    return;
  }
#if PCSS_METHOD == 1
  float visibility = fixedPcf(u_shadowMap, uv, zReceiver, u_pcfWidthTexels, u_bias, u_nearFar, u_filterSamples,
                              uvec2(gl_FragCoord.xy));  // (07.H1)
#else
  float visibility = pcss(u_shadowMap, uv, zReceiver, s, uvec2(gl_FragCoord.xy));
#endif
  if (wbIsTodo(visibility)) {  // a stub: show it, never fake a shadow
    wbWriteOutputs(mix(albedo * 0.5, wbTodoPattern(gl_FragCoord.xy), 0.35), WB_TODO, v_world, true);
    return;
  }
  wbWriteOutputs(wbShade(albedo, n, toLight, vec3(cone), visibility), visibility, v_world, facesLight);
}
