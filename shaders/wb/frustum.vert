#version 410 core
// The 12 edges of the light's clip volume, taken back to world space: the light frustum debug view.
uniform mat4 u_viewProj;  // the viewer
uniform mat4 u_invLight;  // light clip space -> world
uniform int u_useCorners;  // 1: the box is u_corners (near face (-x,-y), (+x,-y), (+x,+y), (-x,+y), then far)
uniform vec3 u_corners[8];
const ivec2 kEdges[12] = ivec2[](ivec2(0, 1), ivec2(1, 3), ivec2(3, 2), ivec2(2, 0), ivec2(4, 5), ivec2(5, 7),
                                 ivec2(7, 6), ivec2(6, 4), ivec2(0, 4), ivec2(1, 5), ivec2(2, 6), ivec2(3, 7));
void main() {
  int corner = kEdges[gl_VertexID / 2][gl_VertexID % 2];
  vec4 ndc = vec4((corner & 1) != 0 ? 1.0 : -1.0, (corner & 2) != 0 ? 1.0 : -1.0, (corner & 4) != 0 ? 1.0 : -1.0, 1.0);
  int face = (corner & 4) != 0 ? 4 : 0, x = corner & 1, y = (corner & 2) >> 1;
  vec4 world = u_useCorners != 0 ? vec4(u_corners[face + (y != 0 ? 3 - x : x)], 1.0) : u_invLight * ndc;
  gl_Position = u_viewProj * vec4(world.xyz / world.w, 1.0);
}
