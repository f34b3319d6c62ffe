// Lab 08 exercises: point lights and cube shadow maps. Each function returns WB_TODO until you write
// it; a body that still returns WB_TODO is reported as "not implemented". Check: ./workbook check 08
// Keep the "// EXERCISE 08.x" lines: the grader finds each exercise by its line.
//
// Conventions (the tests rely on them): `far` is the light's far plane; the map stores, per
// direction from the light, the distance to the nearest surface divided by far (08.2); a point is
// lit when its distance from the light minus `bias` is at most the stored distance times far.
#include "wb/exercise.glsl"
#include "cube_common.glsl"

// EXERCISE 08.2: what the depth pass writes for a surface point `world`: its distance from the
// light over far, in [0, 1].
float cubeDepth(vec3 world, vec3 lightPos, float far) {
  return WB_TODO;
}

// EXERCISE 08.4: the hard shadow test. Look the map up in the direction from the light to the point
// (texture(map, direction).r is the stored value) and compare distances: 1.0 lit, 0.0 shadowed.
float cubeShadow(samplerCube map, vec3 world, vec3 lightPos, float far, float bias) {
  return WB_TODO;
}

// EXERCISE 08.5: soft point shadows. Average the tests of `samples` directions around the point's:
// direction k is (world - lightPos) + cubeOffsetDir(k, samples) * radius (radius in world units).
float cubePcf(samplerCube map, vec3 world, vec3 lightPos, float far, float bias, float radius, int samples) {
  return WB_TODO;
}
