// Lab 11 exercises: the aliasing measure and SDSM's reduction. Each function returns WB_TODO until
// you write it. Check: ./workbook check 11. Keep the "// EXERCISE 11.x" lines: the grader finds them by it.
#include "wb/exercise.glsl"

// EXERCISE 11.1: texels per pixel. uvDx and uvDy: how far the map coordinate (0..1 across the map)
// moves from this pixel to the next one along the screen's x and y; mapTexels: the map's size in
// texels along its u and v. Returns how many texels one pixel step spans: along screen x, along screen y.
vec2 texelsPerPixel(vec2 uvDx, vec2 uvDy, vec2 mapTexels) {
  return vec2(WB_TODO);
}

// EXERCISE 11.2: the two parts of aliasing (README.md derives them), in the plane that holds the
// normal, the eye and the light. toEye: from the point to the eye (not unit: its length is the
// distance); normal: the surface's (any length); toLight: towards the light (any length);
// pixelAngle: the angle one pixel spans (radians); texelWorld: one texel's width across the light
// (world units). Returns (perspective, projective): the distance a pixel spans across the view
// over a texel's width; and cos(to the light) / cos(to the eye) from the normal, the light's cosine
// taken as 0 behind the surface and the eye's no smaller than 1e-4.
vec2 aliasingParts(vec3 toEye, vec3 normal, vec3 toLight, float pixelAngle, float texelWorld) {
  return vec2(WB_TODO);
}

// EXERCISE 11.5: one step of SDSM's min/max reduction. Each of a, b, c, d holds (the smallest, the
// largest) view distance of its part of the frame, or (0, 0) where that part holds nothing (the
// sky: the clear value). Returns the same for all four together: (0, 0) when none holds anything.
vec2 minMaxDepth(vec2 a, vec2 b, vec2 c, vec2 d) {
  return vec2(WB_TODO);
}
