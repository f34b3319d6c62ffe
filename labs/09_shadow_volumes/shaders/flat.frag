#version 410 core
// Debug views of lab 09: one colour, with alpha (the translucent volumes, the stencil count).
uniform vec4 u_rgba;
layout(location = 0) out vec4 o_color;
void main() { o_color = u_rgba; }
