// Lab 08 GLSL exercises: reference solution.
#include "wb/exercise.glsl"
#include "cube_common.glsl"

// EXERCISE 08.2: the linear distance write.
float cubeDepth(vec3 world, vec3 lightPos, float far) {
  return length(world - lightPos) / far;
}

// EXERCISE 08.4: the cube lookup and test.
float cubeShadow(samplerCube map, vec3 world, vec3 lightPos, float far, float bias) {
  vec3 d = world - lightPos;
  return length(d) - bias <= texture(map, d).r * far ? 1.0 : 0.0;
}

// EXERCISE 08.5: PCF with 3D offsets.
float cubePcf(samplerCube map, vec3 world, vec3 lightPos, float far, float bias, float radius, int samples) {
  vec3 d = world - lightPos;
  float distance = length(d), lit = 0.0;
  for (int k = 0; k < samples; ++k)
    lit += distance - bias <= texture(map, d + cubeOffsetDir(k, samples) * radius).r * far ? 1.0 : 0.0;
  return lit / float(samples);
}
