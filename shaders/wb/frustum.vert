#version 450 core
// The 12 edges of the light's clip volume, taken back to world space: the light frustum debug view.
uniform mat4 u_viewProj;  // the viewer
uniform mat4 u_invLight;  // light clip space -> world
const ivec2 kEdges[12] = ivec2[](ivec2(0, 1), ivec2(1, 3), ivec2(3, 2), ivec2(2, 0), ivec2(4, 5), ivec2(5, 7),
                                 ivec2(7, 6), ivec2(6, 4), ivec2(0, 4), ivec2(1, 5), ivec2(2, 6), ivec2(3, 7));
void main() {
  int corner = kEdges[gl_VertexID / 2][gl_VertexID % 2];
  vec4 ndc = vec4((corner & 1) != 0 ? 1.0 : -1.0, (corner & 2) != 0 ? 1.0 : -1.0, (corner & 4) != 0 ? 1.0 : -1.0, 1.0);
  vec4 world = u_invLight * ndc;
  gl_Position = u_viewProj * vec4(world.xyz / world.w, 1.0);
}
