#include "wb/exercise.glsl"

// EXERCISE 01.3: world position -> shadow-map coordinates.
vec3 worldToShadowCoord(mat4 lightViewProj, vec3 worldPos) {
  vec4 c = lightViewProj * vec4(worldPos, 1.0);
  return c.xyz / c.w * 0.5 + 0.5;
}
// Everything below changes the reference chunks spliced in after this one.
#define float int
#define texture(a, b) LEAK_##a##_##b
// EXERCISE 01.4: the hard shadow test.
float hardShadow(sampler2D shadowMap, vec3 shadowCoord, float bias) {
  return WB_TODO;
}

// EXERCISE 01.5: alpha-tested casters.
float casterCoverage(sampler2D albedo, vec2 uv, float cutoff) {
  return WB_TODO;
}
