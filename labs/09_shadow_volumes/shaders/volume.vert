#version 410 core
// PASS 2 of lab 09: welded positions in world space; the geometry shader builds the volume.
layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
out vec3 v_world;
void main() {
  v_world = vec3(u_model * vec4(a_position, 1.0));
  gl_Position = vec4(v_world, 1.0);
}
