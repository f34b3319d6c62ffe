#version 410 core
// PASS 2 of lab 09: the shadow volume of each light-facing triangle's silhouette edges (09.2),
// pushed to infinity (09.3); with u_caps (z-fail) also closed at both ends. Every face of the
// volume is counter-clockwise seen from outside it, so GL's front and back faces are the volume's.
#include "exercise.glsl"
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 18) out;
in vec3 v_world[];
uniform mat4 u_viewProj;
uniform vec4 u_light;
uniform int u_caps;

// The side of the volume along edge a -> b: a quad from the edge to infinity.
void side(vec3 a, vec3 b) {
  gl_Position = u_viewProj * vec4(a, 1.0);
  EmitVertex();
  gl_Position = u_viewProj * extrudeToInfinity(a, u_light);
  EmitVertex();
  gl_Position = u_viewProj * vec4(b, 1.0);
  EmitVertex();
  gl_Position = u_viewProj * extrudeToInfinity(b, u_light);
  EmitVertex();
  EndPrimitive();
}

void main() {
  vec3 v0 = v_world[0], v1 = v_world[2], v2 = v_world[4];
  if (facesLight(v0, v1, v2, u_light) < 0.5) return;
  if (silhouetteEdge(v0, v1, v_world[1], u_light) > 0.5) side(v0, v1);
  if (silhouetteEdge(v1, v2, v_world[3], u_light) > 0.5) side(v1, v2);
  if (silhouetteEdge(v2, v0, v_world[5], u_light) > 0.5) side(v2, v0);
  if (u_caps == 0) return;
  // The near cap is the triangle itself (09.H1); the far cap is the triangle at infinity, turned round.
  gl_Position = nearCapVertex(u_viewProj, v0);
  EmitVertex();
  gl_Position = nearCapVertex(u_viewProj, v1);
  EmitVertex();
  gl_Position = nearCapVertex(u_viewProj, v2);
  EmitVertex();
  EndPrimitive();
  gl_Position = u_viewProj * extrudeToInfinity(v0, u_light);
  EmitVertex();
  gl_Position = u_viewProj * extrudeToInfinity(v2, u_light);
  EmitVertex();
  gl_Position = u_viewProj * extrudeToInfinity(v1, u_light);
  EmitVertex();
  EndPrimitive();
}
