// Lab 01 GLSL exercises: reference solution.
#include "wb/exercise.glsl"

// EXERCISE 01.3: world position -> shadow-map coordinates.
vec3 worldToShadowCoord(mat4 lightViewProj, vec3 worldPos) {
  vec4 clip = lightViewProj * vec4(worldPos, 1.0);
  vec3 ndc = clip.xyz / clip.w;
  return ndc * 0.5 + 0.5;
}

// EXERCISE 01.4: the hard shadow test.
float hardShadow(sampler2D shadowMap, vec3 shadowCoord, float bias) {
  float nearest = texture(shadowMap, shadowCoord.xy).r;
  return shadowCoord.z - bias <= nearest ? 1.0 : 0.0;
}

// EXERCISE 01.5: alpha-tested casters.
float casterCoverage(sampler2D albedo, vec2 uv, float cutoff) {
  return texture(albedo, uv).a >= cutoff ? 1.0 : 0.0;
}
