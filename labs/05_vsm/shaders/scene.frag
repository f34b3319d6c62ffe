#version 410 core
// PASS 2 of lab 05: one filtered lookup of the moments, Chebyshev's bound (05.2) and the
// light-bleeding reduction (05.3).
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
uniform sampler2D u_shadowMap;  // filtered (M1, M2)
uniform mat4 u_lightViewProj;
uniform float u_minVariance;
uniform float u_bleeding;

void main() {
  vec4 texel = u_hasTexture != 0 ? texture(u_albedo, v_uv) : vec4(1.0);
  if (texel.a < u_alphaCutoff) discard;
  vec3 albedo = u_color * texel.rgb;
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 toLight = wbToLight(v_world);
  vec3 coord = shadowMapCoord(u_lightViewProj, v_world);  // (05.H1)

  vec2 moments = texture(u_shadowMap, coord.xy).rg;
  float visibility = chebyshevUpperBound(moments, coord.z, u_minVariance);
  if (!wbIsTodo(visibility)) visibility = reduceLightBleeding(visibility, u_bleeding);
  if (wbIsTodo(visibility) || wbIsTodo(moments.x)) {
    wbWriteOutputs(mix(albedo * 0.5, wbTodoPattern(gl_FragCoord.xy), 0.35), WB_TODO, v_world, true);
    return;
  }
  bool facesLight = dot(n, toLight) > 0.0;
  wbWriteOutputs(wbShade(albedo, n, toLight, vec3(wbLightReach(v_world)), visibility), visibility, v_world, facesLight);
}
