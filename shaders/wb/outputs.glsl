// The frame target every lab's camera pass writes (see Lab::render): colour, the light visibility
// that --dump-visibility saves, and the world position that exact visibility is cast from.
#ifndef WB_OUTPUTS_GLSL
#define WB_OUTPUTS_GLSL
layout(location = 0) out vec4 o_color;
layout(location = 1) out float o_visibility;  // 1 lit, 0 shadowed
layout(location = 2) out vec4 o_position;     // world xyz; w = +1 facing the light, -1 facing away

// present.* (the app compiles them in: WB_PRESENT_SRGB, WB_PRESENT_GRID): lecture pictures, never
// the visibility.

// How much of a grid line covers this pixel, faded out where the lines are closer than pixels.
float wbGridLine(vec2 p) {
  vec2 w = max(fwidth(p), vec2(1e-5));
  vec2 g = abs(fract(p - 0.5) - 0.5) / w;
  return (1.0 - min(min(g.x, g.y), 1.0)) * clamp(1.5 - 3.0 * max(w.x, w.y), 0.0, 1.0);
}

vec3 wbPresent(vec3 color, vec3 worldPos) {
#ifdef WB_PRESENT_GRID  // a faint one-unit grid on upward-facing surfaces
  vec3 n = normalize(cross(dFdx(worldPos), dFdy(worldPos)));
  if (n.y > 0.9) color *= 1.0 - 0.3 * wbGridLine(worldPos.xz);  // (n faces the eye: ground, not ceiling)
#endif
#ifdef WB_PRESENT_SRGB  // encode the linear colour for an sRGB screen
  vec3 c = clamp(color, 0.0, 1.0);
  color = mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
#endif
  return color;
}

void wbWriteOutputs(vec3 color, float visibility, vec3 worldPos, bool facesLight) {
  o_color = vec4(wbPresent(color, worldPos), 1.0);
  o_visibility = facesLight ? visibility : 0.0;  // facing away is an attached shadow, whatever the map says
  o_position = vec4(worldPos, facesLight ? 1.0 : -1.0);
}
#endif
