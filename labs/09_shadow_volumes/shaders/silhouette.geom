#version 410 core
// Debug view of lab 09: the silhouette edges as lines (debug.silhouettes).
#include "exercise.glsl"
layout(triangles_adjacency) in;
layout(line_strip, max_vertices = 6) out;
in vec3 v_world[];
uniform mat4 u_viewProj;
uniform vec4 u_light;

void edge(vec3 a, vec3 b) {
  gl_Position = u_viewProj * vec4(a, 1.0);
  EmitVertex();
  gl_Position = u_viewProj * vec4(b, 1.0);
  EmitVertex();
  EndPrimitive();
}

void main() {
  vec3 v0 = v_world[0], v1 = v_world[2], v2 = v_world[4];
  if (facesLight(v0, v1, v2, u_light) < 0.5) return;
  if (silhouetteEdge(v0, v1, v_world[1], u_light) > 0.5) edge(v0, v1);
  if (silhouetteEdge(v1, v2, v_world[3], u_light) > 0.5) edge(v1, v2);
  if (silhouetteEdge(v2, v0, v_world[5], u_light) > 0.5) edge(v2, v0);
}
