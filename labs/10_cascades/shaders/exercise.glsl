// Lab 10 exercises: choosing and blending cascades. Each function returns WB_TODO until you write
// it. Check: ./workbook check 10. Keep the "// EXERCISE 10.x" lines: the grader finds them by it.
//
// Conventions: `splits` holds C_1 .. C_4 (the far end of each cascade, view distances); `count` is
// the number of cascades (1 to 4); cascade 0 is the nearest.
#include "wb/exercise.glsl"

// EXERCISE 10.5: cascade selection. By interval: the first cascade i whose far end C_(i+1) is beyond
// the pixel's view distance (the last cascade when none is). By map: the first cascade whose map
// holds the point, its light-clip xy inside [-1, 1] and depth inside [-1, 1] (the last when none does).
// (An int cannot hold WB_TODO: until you write them they return -1, which means the same.)
int cascadeByInterval(float viewDepth, vec4 splits, int count) {
  return -1;
}
int cascadeByMap(vec3 world, mat4 cascades[4], int count) {
  return -1;
}

// EXERCISE 10.6: the blend band. Within `band` (a fraction of the cascade's depth range) before the
// far end of cascade i, the next cascade's weight rises from 0 to 1: 0 at splitFar - band * (splitFar
// - splitNear), 1 at splitFar, linear between; 0 before the band.
float blendWeight(float viewDepth, float splitNear, float splitFar, float band) {
  return WB_TODO;
}

// EXERCISE 10.H1: bug hunt, "soft shadows grow blurrier at every split" (README.md, Bug hunt 10.H1).
// Not a stub: this is the lab's working code, and it has a bug that shipped in a real engine. Find
// it from the symptom; the handout says how to see it and how it is measured.
// PCF in cascade `cascade` at map coordinate p (uv, depth): kernel x kernel comparisons (each the
// sampler's 2x2), spaced by `tapWorld` world units, so that the shadow is as soft in every cascade.
// uvPerWorld[k]: cascade k's map coordinates per world unit, along the map's x and y.
float cascadePcf(sampler2DArrayShadow maps, vec3 p, int cascade, float bias, int kernel, float tapWorld,
                 vec2 uvPerWorld[4]) {
  vec2 step = tapWorld * uvPerWorld[0];
  float lit = 0.0;
  int r = kernel / 2;
  for (int y = -r; y <= r; ++y)
    for (int x = -r; x <= r; ++x) lit += texture(maps, vec4(p.xy + vec2(x, y) * step, float(cascade), p.z - bias));
  return lit / float(kernel * kernel);
}
