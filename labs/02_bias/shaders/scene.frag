#version 410 core
// PASS 2 of lab 02: the shadow test with the chosen bias method, over an explicit-tap PCF kernel.
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
uniform vec3 u_lightDir;       // the direction the light travels (a spot light: its axis)
uniform vec3 u_lightPos;       // a spot light's position
uniform int u_spot;            // 1: a spot light, whose rays and texels differ from pixel to pixel
uniform int u_method;          // the bias.method setting, numbered as below
uniform int u_ready;           // 0 while the C++ exercise the method needs is a stub
uniform float u_bias;          // shadow.bias: the constant part
uniform float u_slopeScale;    // bias.slope_scale
uniform float u_maxBias;       // bias.max
uniform float u_normalOffset;  // bias.normal_offset, in texels
uniform float u_texelWorld;    // one texel, in world units (a spot light: at depth 1 along its axis)
uniform int u_radius;          // PCF kernel radius: width 2r + 1
const int CONSTANT = 1, SLOPE = 2, NORMAL_OFFSET = 5, RECEIVER_PLANE = 6;

vec3 shadowCoord(vec3 p) {
  vec4 c = u_lightViewProj * vec4(p, 1.0);
  return c.xyz / c.w * 0.5 + 0.5;
}

void main() {
  vec4 texel = u_hasTexture != 0 ? texture(u_albedo, v_uv) : vec4(1.0);
  if (texel.a < u_alphaCutoff) discard;
  vec3 albedo = u_color * texel.rgb;
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  // A spot light's rays fan out: the slope and the offset use this pixel's own direction to the light.
  vec3 toLight = wbToLight(v_world);
  float texelWorld = texelWorldAt(v_world, u_texelWorld, u_spot != 0, u_lightPos, u_lightDir);  // (02.H2)
  float cosTheta = dot(n, toLight);

  vec3 coord = shadowCoord(v_world);
  // Derivatives first: dFdx is undefined inside branches that neighbouring pixels may not take.
  vec3 dx = dFdx(coord), dy = dFdy(coord);
  bool todo = u_ready == 0;
  float bias = 0.0;
  vec2 dzduv = vec2(0.0);
  // Normal offset moves nothing where the surface faces the light squarely (1 - N.L = 0): there the
  // depth comparison still needs the small constant bias.
  if (u_method == CONSTANT || u_method == NORMAL_OFFSET) bias = u_bias;
  if (u_method == SLOPE) bias = slopeScaledBias(cosTheta, u_bias, u_slopeScale, u_maxBias);
  if (u_method == NORMAL_OFFSET) {
    vec3 moved = normalOffsetPosition(v_world, n, toLight, texelWorld, u_normalOffset);
    todo = todo || wbIsTodo(moved);
    coord = shadowCoord(moved);
  }
  if (u_method == RECEIVER_PLANE) dzduv = receiverPlaneDepthBias(dx, dy);
  todo = todo || wbIsTodo(bias) || wbIsTodo(dzduv.x);

  // Explicit taps (never hardware-filtered compares), so results are the same on every GPU.
  vec2 texelSize = 1.0 / vec2(textureSize(u_shadowMap, 0));
  float sum = 0.0;
  for (int j = -u_radius; j <= u_radius && !todo; ++j)
    for (int i = -u_radius; i <= u_radius && !todo; ++i) {
      vec2 offset = vec2(i, j) * texelSize;
      float z = u_method == RECEIVER_PLANE ? receiverPlaneTapDepth(coord.z, dzduv, offset, texelSize) : coord.z;
      float lit = biasedCompare(z, texture(u_shadowMap, coord.xy + offset).r, bias);
      todo = wbIsTodo(z) || wbIsTodo(lit);
      sum += lit;
    }
  if (todo) {  // an exercise this method needs is missing: show it, never fake a shadow
    wbWriteOutputs(mix(albedo * 0.5, wbTodoPattern(gl_FragCoord.xy), 0.35), WB_TODO, v_world, true);
    return;
  }
  float visibility = sum / float((2 * u_radius + 1) * (2 * u_radius + 1));
  wbWriteOutputs(wbShade(albedo, n, toLight, vec3(wbLightReach(v_world)), visibility), visibility, v_world, cosTheta > 0.0);
}
