#version 410 core
// render.scale: the frame, stretched over the window's scene area with linear filtering.
uniform sampler2D u_frame;
in vec2 v_uv;
layout(location = 0) out vec4 o_color;
void main() { o_color = vec4(texture(u_frame, v_uv).rgb, 1.0); }
