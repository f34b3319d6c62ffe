#version 410 core
// Label quads: pixels from the label's top left (x, y) and atlas coordinates (z, w; negative: solid).
layout(location = 0) in vec4 a_vertex;
uniform vec2 u_origin;  // the label's top left, in pixels from the target's top left
uniform vec2 u_size;    // the target's size in pixels
uniform float u_scale;
out vec2 v_uv;
void main() {
  vec2 p = u_origin + a_vertex.xy * u_scale;
  v_uv = a_vertex.zw;
  gl_Position = vec4(p.x / u_size.x * 2.0 - 1.0, 1.0 - p.y / u_size.y * 2.0, 0.0, 1.0);
}
