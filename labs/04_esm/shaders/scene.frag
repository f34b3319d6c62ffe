#version 410 core
// PASS 2 of lab 04: ESM visibility from the filtered map (04.3), with the PCF fallback where the
// filter broke ESM's assumption (04.5).
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
uniform sampler2D u_shadowMap;  // the filtered exp(c z), or c z in log space
uniform sampler2D u_depthMap;   // the unfiltered depth of the same render, for the fallback
uniform mat4 u_lightViewProj;
uniform float u_c;
uniform int u_logSpace;
uniform int u_fallback;
uniform float u_epsilon;
uniform float u_bias;

void main() {
  vec4 texel = u_hasTexture != 0 ? texture(u_albedo, v_uv) : vec4(1.0);
  if (texel.a < u_alphaCutoff) discard;
  vec3 albedo = u_color * texel.rgb;
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 toLight = wbToLight(v_world);
  vec4 clip = u_lightViewProj * vec4(v_world, 1.0);
  vec3 coord = clip.xyz / clip.w * 0.5 + 0.5;

  float stored = texture(u_shadowMap, coord.xy).r;
  float logFiltered = u_logSpace != 0 ? stored : log(max(stored, 1e-37));
  float visibility = esmVisibility(logFiltered, coord.z, u_c);
  if (u_fallback != 0 && !wbIsTodo(visibility)) {
    float fallback = esmNeedsFallback(logFiltered, coord.z, u_c, u_epsilon);
    if (wbIsTodo(fallback)) visibility = WB_TODO;
    else if (fallback > 0.5) {  // 3x3 PCF on the unfiltered depth
      vec2 texelSize = 1.0 / vec2(textureSize(u_depthMap, 0));
      float sum = 0.0;
      for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) sum += step(coord.z - u_bias, texture(u_depthMap, coord.xy + vec2(i, j) * texelSize).r);
      visibility = sum / 9.0;
    }
  }
  if (wbIsTodo(visibility) || wbIsTodo(logFiltered)) {
    wbWriteOutputs(mix(albedo * 0.5, wbTodoPattern(gl_FragCoord.xy), 0.35), WB_TODO, v_world, true);
    return;
  }
  bool facesLight = dot(n, toLight) > 0.0;
  wbWriteOutputs(wbShade(albedo, n, toLight, vec3(wbLightReach(v_world)), visibility), visibility, v_world, facesLight);
}
