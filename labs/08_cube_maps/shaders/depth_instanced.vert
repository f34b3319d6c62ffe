#version 410 core
// PASS 1 of lab 08 in one instanced pass: instance k is face k. The vertex shader picks the layer
// itself, which core GL 4.5 allows only with GL_ARB_shader_viewport_layer_array (the lab checks
// for it before it loads this file).
#extension GL_ARB_shader_viewport_layer_array : require
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_model;
uniform mat4 u_faceViewProj[6];
out vec2 v_uv;
out vec3 v_world;
void main() {
  v_uv = a_uv;
  v_world = vec3(u_model * vec4(a_position, 1.0));
  gl_Layer = gl_InstanceID;
  gl_Position = u_faceViewProj[gl_InstanceID] * vec4(v_world, 1.0);
}
