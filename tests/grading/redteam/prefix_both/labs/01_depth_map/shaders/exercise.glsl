// Lab 01 GLSL exercises. Each function is one exercise; keep the signatures, replace the bodies.
#include "wb/exercise.glsl"

// EXERCISE 01.3: world position -> shadow-map coordinates.
// (nothing written here: the grader fills it in from the marker below)
#define RT_STUDENT_CHUNK_01_3
// EXERCISE Z1
#ifdef RT_STUDENT_CHUNK_01_3
// EXERCISE 01
vec3 worldToShadowCoord(mat4 lightViewProj, vec3 worldPos) { return vec3(WB_TODO); }
// EXERCISE Z2
#endif

// EXERCISE 01.4: the hard shadow test.
float hardShadow(sampler2D shadowMap, vec3 shadowCoord, float bias) {
  return WB_TODO;
}

// EXERCISE 01.5: alpha-tested casters.
float casterCoverage(sampler2D albedo, vec2 uv, float cutoff) {
  return WB_TODO;
}
