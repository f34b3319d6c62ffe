// Lab 05 GLSL exercises. Each function is one exercise; keep the signatures, replace the bodies.
// A body that still returns WB_TODO is reported as "not implemented". Check: ./workbook check 05
#include "wb/exercise.glsl"

// EXERCISE 05.1: the two moments the map stores for a depth z: (z, z^2), where the second moment
// also gets the derivative bias 1/4 (dz/dx^2 + dz/dy^2), which keeps sloped receivers from acne.
vec2 vsmMoments(float depth, float dzdx, float dzdy) {
  return vec2(WB_TODO);
}

// EXERCISE 05.2: Chebyshev's one-tailed bound. moments = the filtered (M1, M2). A receiver at or in
// front of the mean is fully lit; behind it, p_max = var / (var + (z - mean)^2), with the variance
// M2 - M1^2 clamped to at least minVariance.
float chebyshevUpperBound(vec2 moments, float receiverDepth, float minVariance) {
  return WB_TODO;
}

// EXERCISE 05.3: light-bleeding reduction: map [0, amount) to 0 and stretch [amount, 1] to [0, 1].
float reduceLightBleeding(float pMax, float amount) {
  return WB_TODO;
}

// EXERCISE 05.H1: bug hunt, "under the spot light everything is in shadow" (README.md, Bug hunt
// 05.H1).
// Not a stub: this is the lab's working code, and it has a bug of a kind that shipped in real
// projects. Find it from the symptom; the handout says how to see it and how it is measured.
// Where the map holds the answer for the point `world`: its uv in the map, and its depth as the
// light's pass stored depths (gl_FragCoord.z), for the comparison.
vec3 shadowMapCoord(mat4 lightViewProj, vec3 world) {
  vec4 clip = lightViewProj * vec4(world, 1.0);
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  float depth = clip.z * 0.5 + 0.5;
  return vec3(uv, depth);
}
