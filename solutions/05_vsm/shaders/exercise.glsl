// Lab 05 GLSL exercises: reference solution.
#include "wb/exercise.glsl"

// EXERCISE 05.1: the moments, with the derivative bias.
vec2 vsmMoments(float depth, float dzdx, float dzdy) {
  return vec2(depth, depth * depth + 0.25 * (dzdx * dzdx + dzdy * dzdy));
}

// EXERCISE 05.2: Chebyshev's one-tailed bound.
float chebyshevUpperBound(vec2 moments, float receiverDepth, float minVariance) {
  if (receiverDepth <= moments.x) return 1.0;
  float variance = max(moments.y - moments.x * moments.x, minVariance);
  float d = receiverDepth - moments.x;
  return variance / (variance + d * d);
}

// EXERCISE 05.3: light-bleeding reduction.
float reduceLightBleeding(float pMax, float amount) {
  return clamp((pMax - amount) / (1.0 - amount), 0.0, 1.0);
}

// EXERCISE 05.H1: bug hunt, "under the spot light everything is in shadow" (README.md, Bug hunt
// 05.H1).
// Where the map holds the answer for the point `world`: its uv in the map, and its depth as the
// light's pass stored depths (gl_FragCoord.z), for the comparison.
vec3 shadowMapCoord(mat4 lightViewProj, vec3 world) {
  vec4 clip = lightViewProj * vec4(world, 1.0);
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  float depth = clip.z / clip.w * 0.5 + 0.5;
  return vec3(uv, depth);
}
