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

// EXERCISE 10.H1: bug hunt, "soft shadows grow blurrier at every split" (README.md, Bug hunt 10.H1).
// Not a stub: this is the lab's working code, and it has a bug that shipped in a real engine. Find
// it from the symptom; the handout says how to see it and how it is measured.
// PCF in cascade `cascade` at map coordinate p (uv, depth): kernel x kernel comparisons (each the
// sampler's 2x2), spaced by `tapWorld` world units, so that the shadow is as soft in every cascade.
// uvPerWorld[k]: cascade k's map coordinates per world unit, along the map's x and y.
float cascadePcf(sampler2DArrayShadow maps, vec3 p, int cascade, float bias, int kernel, float tapWorld,
                 vec2 uvPerWorld[4]) {
  vec2 step = tapWorld * uvPerWorld[cascade];
  float lit = 0.0;
  int r = kernel / 2;
  for (int y = -r; y <= r; ++y)
    for (int x = -r; x <= r; ++x) lit += texture(maps, vec4(p.xy + vec2(x, y) * step, float(cascade), p.z - bias));
  return lit / float(kernel * kernel);
}
