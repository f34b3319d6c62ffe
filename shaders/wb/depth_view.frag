#version 410 core
// Shows a depth map, or one layer of a map array (WB_ARRAY). A perspective map stores non-linear
// depth that looks all white, so it is turned back into eye distance first.
in vec2 v_uv;
#ifdef WB_ARRAY
uniform sampler2DArray u_map;
uniform int u_layer;
#else
uniform sampler2D u_map;
#endif
uniform int u_perspective;
uniform float u_near, u_far;
layout(location = 0) out vec4 o_color;
void main() {
#ifdef WB_ARRAY
  float d = texture(u_map, vec3(v_uv, float(u_layer))).r;
#else
  float d = texture(u_map, v_uv).r;
#endif
  if (u_perspective != 0) {
    float zNdc = d * 2.0 - 1.0;
    float eye = 2.0 * u_near * u_far / (u_far + u_near - zNdc * (u_far - u_near));
    d = (eye - u_near) / (u_far - u_near);
  }
  o_color = vec4(vec3(d), 1.0);
}
