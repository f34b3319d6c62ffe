// Lab 10 exercises: reference solution.
#include "wb/exercise.glsl"

// EXERCISE 10.5: cascade selection.
int cascadeByInterval(float viewDepth, vec4 splits, int count) {
  for (int i = 0; i < count - 1; ++i)
    if (viewDepth < splits[i]) return i;
  return count - 1;
}
int cascadeByMap(vec3 world, mat4 cascades[4], int count) {
  for (int i = 0; i < count - 1; ++i) {
    vec4 c = cascades[i] * vec4(world, 1.0);
    if (all(lessThanEqual(abs(c.xyz / c.w), vec3(1.0)))) return i;
  }
  return count - 1;
}

// EXERCISE 10.6: the blend band.
float blendWeight(float viewDepth, float splitNear, float splitFar, float band) {
  float start = splitFar - band * (splitFar - splitNear);
  return clamp((viewDepth - start) / max(splitFar - start, 1e-6), 0.0, 1.0);
}
