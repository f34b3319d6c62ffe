#version 410 core
// PASSES 1 and 3 of lab 09: the scene, ambient only with visibility 0 (pass 1, which also lays down
// the depth), or fully lit with visibility 1 where the stencil count is 0 (pass 3). u_todo: the
// volumes cannot be drawn yet (a stub), so the frame shows the not-implemented pattern instead.
// The techniques it is compared with light pass 3 their own way (u_technique): a shadow map with
// hardware 2x2 PCF, or the visibility the CPU ray-traced per pixel.
#include "wb/exercise.glsl"
#include "wb/lighting.glsl"
#include "wb/outputs.glsl"
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
uniform vec3 u_color;
uniform sampler2D u_albedo;
uniform int u_hasTexture;
uniform float u_alphaCutoff;
uniform int u_lit;
uniform int u_todo;
uniform int u_technique;  // 0 volumes, 1 shadow map, 2 ray traced
uniform mat4 u_lightViewProj;
uniform sampler2DShadow u_shadowMap;
uniform sampler2D u_rayTraced;

void main() {
  vec4 texel = u_hasTexture != 0 ? texture(u_albedo, v_uv) : vec4(1.0);
  if (texel.a < u_alphaCutoff) discard;
  vec3 albedo = u_color * texel.rgb;
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 toLight = wbToLight(v_world);
  bool facesLight = dot(n, toLight) > 0.0;
  if (u_todo != 0) {
    wbWriteOutputs(mix(albedo * 0.5, wbTodoPattern(gl_FragCoord.xy), 0.35), WB_TODO, v_world, true);
    return;
  }
  float visibility = u_lit != 0 ? 1.0 : 0.0;
  if (u_lit != 0 && u_technique == 1) {
    vec4 c = u_lightViewProj * vec4(v_world, 1.0);
    vec3 uvz = c.xyz / c.w * 0.5 + 0.5;
    visibility = c.w > 0.0 ? texture(u_shadowMap, uvz) : 1.0;
  }
  if (u_lit != 0 && u_technique == 2) visibility = texelFetch(u_rayTraced, ivec2(gl_FragCoord.xy), 0).r;
  wbWriteOutputs(wbShade(albedo, n, toLight, vec3(wbLightReach(v_world)), visibility), visibility, v_world, facesLight);
}
