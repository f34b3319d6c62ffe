#version 450 core
// Label triangles from stb_easy_font, pulled from a buffer: pixels from the label's top left.
layout(std430, binding = 3) readonly buffer WbLabel { vec2 wb_label[]; };
uniform vec2 u_origin;  // the label's top left, in pixels from the target's top left
uniform vec2 u_size;    // the target's size in pixels
uniform float u_scale;
void main() {
  vec2 p = u_origin + wb_label[gl_VertexID] * u_scale;
  gl_Position = vec4(p.x / u_size.x * 2.0 - 1.0, 1.0 - p.y / u_size.y * 2.0, 0.0, 1.0);
}
