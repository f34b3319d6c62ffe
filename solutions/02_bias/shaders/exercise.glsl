// Lab 02 GLSL exercises: reference solution.
#include "wb/exercise.glsl"

// EXERCISE 02.1: the shadow comparison with a constant depth bias.
float biasedCompare(float receiverDepth, float storedDepth, float bias) {
  return receiverDepth - bias <= storedDepth ? 1.0 : 0.0;
}

// EXERCISE 02.2: slope-scaled bias, clamped.
float slopeScaledBias(float cosTheta, float constantBias, float slopeScale, float maxBias) {
  float c = clamp(cosTheta, 1e-4, 1.0);
  float tanTheta = sqrt(1.0 - c * c) / c;
  return min(constantBias + slopeScale * tanTheta, maxBias);
}

// EXERCISE 02.5: normal-offset bias.
vec3 normalOffsetPosition(vec3 worldPos, vec3 normal, vec3 toLight, float texelWorld, float scale) {
  float slope = 1.0 - clamp(dot(normal, toLight), 0.0, 1.0);
  return worldPos + normal * (scale * texelWorld * slope);
}

// EXERCISE 02.6: receiver-plane depth bias.
vec2 receiverPlaneDepthBias(vec3 dCoordDx, vec3 dCoordDy) {
  float det = dCoordDx.x * dCoordDy.y - dCoordDx.y * dCoordDy.x;
  if (abs(det) < 1e-20) return vec2(0.0);
  return vec2(dCoordDy.y * dCoordDx.z - dCoordDx.y * dCoordDy.z,
              dCoordDx.x * dCoordDy.z - dCoordDy.x * dCoordDx.z) / det;
}

float receiverPlaneTapDepth(float receiverDepth, vec2 dzduv, vec2 tapOffset, vec2 texelSize) {
  return receiverDepth + dot(tapOffset, dzduv) - dot(abs(dzduv), texelSize);
}

// EXERCISE 02.H2: bug hunt, "normal offset cannot clear the acne under the lamp".
// The width in world units of the map's texel at `worldPos`: what normal offset (02.5) moves by.
// texelWorld is the map's texel size as the lab measures it: for a directional light the same
// everywhere; for a spot light (spot true, at lightPos, along lightDir) the size at depth 1.
float texelWorldAt(vec3 worldPos, float texelWorld, bool spot, vec3 lightPos, vec3 lightDir) {
  return spot ? texelWorld * dot(worldPos - lightPos, lightDir) : texelWorld;
}
