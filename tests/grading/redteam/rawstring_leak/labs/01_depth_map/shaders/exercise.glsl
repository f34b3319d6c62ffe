// Lab 01 GLSL exercises. Each function is one exercise; keep the signatures, replace the bodies.
// A body that still returns WB_TODO is reported as "not implemented". Check: ./workbook check 01
#include "wb/exercise.glsl"

// EXERCISE 01.3: world position -> shadow-map coordinates.
// Returns (u, v, depth), each in [0, 1] for points inside the light's frustum.
vec3 worldToShadowCoord(mat4 lightViewProj, vec3 worldPos) {
  return vec3(WB_TODO);
  // Hints: transform to clip space, divide by w (it is not 1 for a spot light), then map
  // OpenGL's NDC range [-1, 1] to texture range [0, 1] for x, y and z.
}

// EXERCISE 01.4: the hard shadow test.
// Returns 1.0 when the point is lit, 0.0 when something nearer to the light covers it.
// `bias` is subtracted from the point's depth before comparing (lab 02 explains why).
float hardShadow(sampler2D shadowMap, vec3 shadowCoord, float bias) {
  return WB_TODO;
  // Hints: the map's red channel holds the nearest depth the light saw at shadowCoord.xy.
  // A point exactly at the stored depth is lit.
}

// EXERCISE 01.5: alpha-tested casters.
// Returns 1.0 when the caster's fragment at `uv` is solid enough to write depth (alpha >= cutoff),
// 0.0 when the depth pass must discard it.
float casterCoverage(sampler2D albedo, vec2 uv, float cutoff) {
  return WB_TODO;
  // Hint: the alpha channel of the albedo texture says how solid a leaf is.
}
