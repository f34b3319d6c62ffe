#version 410 core
// PASS 2 fragment stage: shade each visible point, asking the shadow map whether the light reaches it.
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
uniform int u_shadowsReady;  // 0 while the light's matrix (01.1 / 01.2) is not implemented
uniform float u_bias;

void main() {
  vec4 texel = u_hasTexture != 0 ? texture(u_albedo, v_uv) : vec4(1.0);
  if (texel.a < u_alphaCutoff) discard;  // the camera sees through the leaves' holes too
  vec3 albedo = u_color * texel.rgb;
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;  // leaves are lit from both sides

  float visibility = WB_TODO;
  if (u_shadowsReady != 0) {
    vec3 coord = worldToShadowCoord(u_lightViewProj, v_world);
    if (!wbIsTodo(coord)) visibility = hardShadow(u_shadowMap, coord, u_bias);
  }
  vec3 toLight = wbToLight(v_world);
  bool facesLight = dot(n, toLight) > 0.0;
  if (wbIsTodo(visibility)) {  // an exercise is missing: show it, never fake a shadow
    wbWriteOutputs(mix(albedo * 0.5, wbTodoPattern(gl_FragCoord.xy), 0.35), WB_TODO, v_world, true);
    return;
  }
  wbWriteOutputs(wbShade(albedo, n, toLight, vec3(wbLightReach(v_world)), visibility), visibility, v_world, facesLight);
}
