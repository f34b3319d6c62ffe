// Lab 09 exercises: stencil shadow volumes. Each function returns WB_TODO until you write it; a body
// that still returns WB_TODO is reported as "not implemented". Check: ./workbook check 09
// Keep the "// EXERCISE 09.x" lines: the grader finds each exercise by its line.
//
// Conventions (the tests rely on them): `light` is a point light (w = 1, xyz its position) or a
// directional light (w = 0, xyz the unit direction *towards* the light). Triangles are
// counter-clockwise seen from their front (outside).
#include "wb/exercise.glsl"

// EXERCISE 09.2: the silhouette test. facesLight: 1.0 when the front of triangle (a, b, c) faces the
// light (the light is strictly on its front side), else 0.0.
float facesLight(vec3 a, vec3 b, vec3 c, vec4 light) {
  return WB_TODO;
}

// silhouetteEdge: for the edge from a to b of a triangle that faces the light, 1.0 when the edge is
// on the silhouette: the triangle across it, (a, across, b), does not face the light. (An open
// edge's `across` is the triangle's own third corner, which makes it a silhouette.)
float silhouetteEdge(vec3 a, vec3 b, vec3 across, vec4 light) {
  return WB_TODO;
}

// EXERCISE 09.3: the point `p` pushed away from the light to infinity: a direction in homogeneous
// coordinates (w = 0), which the projection takes to the point at infinity on the light's ray.
vec4 extrudeToInfinity(vec3 p, vec4 light) {
  return vec4(WB_TODO);
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
  c.z -= capPush * c.w;
  return c;
}
