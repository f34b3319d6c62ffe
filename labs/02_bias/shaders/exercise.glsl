// Lab 02 GLSL exercises. Each function is one exercise; keep the signatures, replace the bodies.
// A body that still returns WB_TODO is reported as "not implemented". Check: ./workbook check 02
#include "wb/exercise.glsl"

// EXERCISE 02.1: the shadow comparison with a constant depth bias.
// Returns 1.0 (lit) when the receiver, moved `bias` towards the light, is not behind the stored depth.
float biasedCompare(float receiverDepth, float storedDepth, float bias) {
  return WB_TODO;
  // Hint: a positive bias must make the test more lenient (fewer shadowed pixels), never stricter.
}

// EXERCISE 02.2: slope-scaled bias, clamped.
// cosTheta = dot(normal, toLight). Returns constantBias + slopeScale * tan(theta), at most maxBias.
float slopeScaledBias(float cosTheta, float constantBias, float slopeScale, float maxBias) {
  return WB_TODO;
  // Hints: tan(theta) = sqrt(1 - cos^2) / cos grows without bound at grazing angles, which is why
  // the clamp exists. Keep cosTheta away from 0 before dividing.
}

// EXERCISE 02.5: normal-offset bias.
// Returns the position to look up in the shadow map: worldPos moved along the normal by
// scale * texelWorld, scaled by (1 - N.L) so that surfaces facing the light barely move.
vec3 normalOffsetPosition(vec3 worldPos, vec3 normal, vec3 toLight, float texelWorld, float scale) {
  return vec3(WB_TODO);
  // Hint: clamp N.L to [0, 1] first.
}

// EXERCISE 02.6: receiver-plane depth bias.
// dCoordDx, dCoordDy: screen-space derivatives of the shadow coordinate (u, v, depth). Returns the
// depth change per unit of u and of v (dz/du, dz/dv) of the receiver's plane.
vec2 receiverPlaneDepthBias(vec3 dCoordDx, vec3 dCoordDy) {
  return vec2(WB_TODO);
  // Hints: the chain rule gives dz/dx = dz/du du/dx + dz/dv dv/dx (and the same for y). That is a
  // 2x2 linear system with the Jacobian [du/dx du/dy; dv/dx dv/dy]: invert it. Return vec2(0) when
  // the determinant is (nearly) zero.
}

// The receiver's depth at a filter tap `tapOffset` (in uv) away from the pixel's own lookup, minus
// the largest depth change within one texel (the map stores depth at texel centres, not at the tap).
float receiverPlaneTapDepth(float receiverDepth, vec2 dzduv, vec2 tapOffset, vec2 texelSize) {
  return WB_TODO;
}

// EXERCISE 02.H2: bug hunt, "normal offset cannot clear the acne under the lamp" (README.md, Bug hunt
// 02.H2). Not a stub: this is the lab's working code, and it has a bug of a kind that shipped in real
// engines (and in this workbook). Find it from the symptom; the handout says how to see it.
// The width in world units of the map's texel at `worldPos`: what normal offset (02.5) moves by.
// texelWorld is the map's texel size as the lab measures it: for a directional light the same
// everywhere; for a spot light (spot true, at lightPos, along lightDir) the size at depth 1.
float texelWorldAt(vec3 worldPos, float texelWorld, bool spot, vec3 lightPos, vec3 lightDir) {
  return texelWorld;
}
