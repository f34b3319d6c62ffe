#version 410 core
// A label's box (solid) or a glyph of the signed-distance atlas (0.5 on the outline), antialiased
// over about one pixel whatever the size it is drawn at.
uniform vec4 u_color;
uniform sampler2D u_atlas;
in vec2 v_uv;
layout(location = 0) out vec4 o_color;
void main() {
  if (v_uv.x < 0.0) {
    o_color = u_color;
    return;
  }
  float d = texture(u_atlas, v_uv).r;
  float w = max(fwidth(d) * 0.7, 1e-3);
  o_color = vec4(u_color.rgb, u_color.a * smoothstep(0.5 - w, 0.5 + w, d));
}
