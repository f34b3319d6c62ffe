#version 410 core
// SDSM's depth pre-pass: level 0 of the reduction holds (d, d) where a surface is seen, and the
// clear value (0, 0) where nothing is (the sky). See-through texels of leaves write nothing.
in vec2 v_uv;
in float v_depth;
uniform sampler2D u_albedo;
uniform int u_hasTexture;
uniform float u_alphaCutoff;
out vec2 o_bounds;
void main() {
  if (u_hasTexture != 0 && texture(u_albedo, v_uv).a < u_alphaCutoff) discard;
  o_bounds = vec2(v_depth);
}
