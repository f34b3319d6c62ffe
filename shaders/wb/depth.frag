#version 410 core
// Depth from the light (labs after 01): no colour; see-through texels of leaves write no depth.
in vec2 v_uv;
uniform sampler2D u_albedo;
uniform int u_hasTexture;
uniform float u_alphaCutoff;
void main() {
  if (u_hasTexture != 0 && texture(u_albedo, v_uv).a < u_alphaCutoff) discard;
}
