#version 410 core
// Lays a picture (the artifact heatmap) over the frame, mostly opaque so the scene still shows.
in vec2 v_uv;
uniform sampler2D u_image;
layout(location = 0) out vec4 o_color;
void main() { o_color = vec4(texture(u_image, v_uv).rgb, 0.8); }
