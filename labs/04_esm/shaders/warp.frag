#version 410 core
// PASS 1 of lab 04: the light's view, storing the warped depth exp(c z) (04.1), or c z itself when
// the map is filtered in log space.
#include "exercise.glsl"
in vec2 v_uv;
uniform sampler2D u_albedo;
uniform int u_hasTexture;
uniform float u_alphaCutoff;
uniform float u_c;
uniform int u_logSpace;
layout(location = 0) out vec4 o_value;
void main() {
  if (u_hasTexture != 0 && texture(u_albedo, v_uv).a < u_alphaCutoff) discard;
  float z = gl_FragCoord.z;  // window depth in [0, 1]; linear in eye distance for an orthographic light
  o_value = vec4(u_logSpace != 0 ? u_c * z : esmWarp(z, u_c));
}
