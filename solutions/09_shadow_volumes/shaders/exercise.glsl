// Lab 09 exercises: reference solution.
#include "wb/exercise.glsl"

// EXERCISE 09.2: the silhouette test.
float facesLight(vec3 a, vec3 b, vec3 c, vec4 light) {
  vec3 toLight = light.w != 0.0 ? light.xyz - a : light.xyz;
  return dot(cross(b - a, c - a), toLight) > 0.0 ? 1.0 : 0.0;
}

float silhouetteEdge(vec3 a, vec3 b, vec3 across, vec4 light) {
  return 1.0 - facesLight(a, across, b, light);
}

// EXERCISE 09.3: extrusion to infinity.
vec4 extrudeToInfinity(vec3 p, vec4 light) {
  return vec4(light.w != 0.0 ? p - light.xyz : -light.xyz, 0.0);
}
