// Lab 11 exercises: reference solution.
#include "wb/exercise.glsl"

// EXERCISE 11.1: texels per pixel.
vec2 texelsPerPixel(vec2 uvDx, vec2 uvDy, vec2 mapTexels) {
  return vec2(length(uvDx * mapTexels), length(uvDy * mapTexels));
}

// EXERCISE 11.2: the two parts of aliasing.
vec2 aliasingParts(vec3 toEye, vec3 normal, vec3 toLight, float pixelAngle, float texelWorld) {
  vec3 n = normalize(normal);
  float perspective = length(toEye) * pixelAngle / texelWorld;
  float projective = max(dot(n, normalize(toLight)), 0.0) / max(dot(n, normalize(toEye)), 1e-4);
  return vec2(perspective, projective);
}

// EXERCISE 11.5: one step of the min/max reduction.
vec2 minMaxDepth(vec2 a, vec2 b, vec2 c, vec2 d) {
  vec2 parts[4] = vec2[4](a, b, c, d);
  vec2 r = vec2(3.0e38, 0.0);
  for (int k = 0; k < 4; ++k)
    if (parts[k].y > 0.0) r = vec2(min(r.x, parts[k].x), max(r.y, parts[k].y));
  return r.y > 0.0 ? r : vec2(0.0);
}
