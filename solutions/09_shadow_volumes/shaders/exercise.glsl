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

// EXERCISE 09.H1: bug hunt, "z-fail shadows the tops of the casters" (README.md, Bug hunt 09.H1).
// Not a stub: this is the lab's working code, and it has a bug of a kind that shipped in real
// engines. Find it from the symptom; the handout says how to see it and how it is measured.
// A corner of a volume's near cap (z-fail's caps close the volume where it starts): the caster's
// own light-facing triangle, in clip space. Drawn through another stage than the scene, the cap
// would round to a unit of depth either way, pixel by pixel, so it is moved by 4 units of the
// 24-bit depth buffer (2^-24 each, 2^-23 in NDC) off the caster's face.
vec4 nearCapVertex(mat4 viewProj, vec3 p) {
  const float capPush = 4.0 * exp2(-23.0);
  vec4 c = viewProj * vec4(p, 1.0);
  c.z += capPush * c.w;  // behind the face: the cap fails the depth test where the caster is lit
  return c;
}
