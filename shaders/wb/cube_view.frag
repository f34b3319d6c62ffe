#version 410 core
// A cube shadow map unfolded as a cross, in the viewport the debug views give it (4 x 3 cells):
//          +Y
//     +X   +Z   -X   -Z
//          -Y
// Each cell shows what the light sees looking along that axis with +Y up (so the cross is not
// mirrored against the scene), and every seam between neighbouring cells lines up. The lookup
// direction follows GL's cube-map rules (face, s, t), so a seam that lines up here lines up in the map. Shown as linear distance: stored directly when the
// lab writes |p - light| / far, otherwise a face's window depth made linear again.
in vec2 v_uv;
uniform samplerCube u_map;
uniform int u_linear;
uniform float u_near, u_far;
layout(location = 0) out vec4 o_color;

// The direction through (s, t) in [-1, 1] of face f (GL order +X -X +Y -Y +Z -Z), with t growing
// downwards in the picture as in the cube-map convention.
vec3 faceDirection(int f, float s, float t) {
  if (f == 0) return vec3(1.0, -t, -s);
  if (f == 1) return vec3(-1.0, -t, s);
  if (f == 2) return vec3(s, 1.0, t);
  if (f == 3) return vec3(s, -1.0, -t);
  if (f == 4) return vec3(s, -t, 1.0);
  return vec3(-s, -t, -1.0);
}

void main() {
  vec2 cell = floor(v_uv * vec2(4.0, 3.0));
  vec2 local = fract(v_uv * vec2(4.0, 3.0)) * 2.0 - 1.0;
  int face = -1;
  if (cell.y == 1.0) face = int[4](0, 4, 1, 5)[int(cell.x)];
  else if (cell.x == 1.0) face = cell.y == 2.0 ? 2 : 3;
  if (face < 0) discard;  // the corners of the cross show the scene
  vec3 dir = faceDirection(face, -local.x, -local.y);  // s grows to the left as seen from the light
  float d = texture(u_map, dir).r;
  if (u_linear == 0) {
    float zNdc = d * 2.0 - 1.0;
    float eye = 2.0 * u_near * u_far / (u_far + u_near - zNdc * (u_far - u_near));
    d = (eye - u_near) / (u_far - u_near);
  }
  // A thin dark frame around every face shows where the seams are.
  float edge = max(abs(local.x), abs(local.y));
  o_color = vec4(vec3(edge > 0.97 ? 0.1 : d), 1.0);
}
