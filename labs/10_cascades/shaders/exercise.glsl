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
