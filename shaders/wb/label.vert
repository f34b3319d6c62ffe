#version 410 core
// Label triangles from stb_easy_font: pixels from the label's top left.
layout(location = 0) in vec2 a_corner;
uniform vec2 u_origin;  // the label's top left, in pixels from the target's top left
uniform vec2 u_size;    // the target's size in pixels
uniform float u_scale;
void main() {
  vec2 p = u_origin + a_corner * u_scale;
  gl_Position = vec4(p.x / u_size.x * 2.0 - 1.0, 1.0 - p.y / u_size.y * 2.0, 0.0, 1.0);
}
