// Shading shared by the labs: simple diffuse + ambient, so the shadow term is what the eye sees.
#ifndef WB_LIGHTING_GLSL
#define WB_LIGHTING_GLSL
// The scene's light, the same for every technique (Lab::beginCameraPass sets it): the direction
// towards it per pixel, and its reach, the spot's cone with a soft outer tenth.
uniform int u_wbLightType;  // 0 directional, 1 spot, 2 point (wb::LightType)
uniform vec3 u_wbLightPos;
uniform vec3 u_wbLightDir;  // the direction the light travels (a spot: its axis)
uniform float u_wbSpotCos;  // a spot: the cosine of its cone's half-angle
vec3 wbToLight(vec3 world) { return u_wbLightType == 0 ? -u_wbLightDir : normalize(u_wbLightPos - world); }
float wbLightReach(vec3 world) {
  if (u_wbLightType != 1) return 1.0;
  return smoothstep(u_wbSpotCos, mix(u_wbSpotCos, 1.0, 0.1), dot(normalize(world - u_wbLightPos), u_wbLightDir));
}
// Diffuse light scaled by visibility, over a constant ambient term that keeps shadows readable.
// Encoded for the screen (present.srgb), the ambient is darker in linear terms, so that shadows keep
// the contrast they have on screen without it.
#ifdef WB_PRESENT_SRGB
const float kWbAmbient = 0.06;
#else
const float kWbAmbient = 0.25;
#endif
vec3 wbShade(vec3 albedo, vec3 n, vec3 toLight, vec3 lightColor, float visibility) {
  float diffuse = max(dot(n, toLight), 0.0);
  return albedo * (kWbAmbient + (1.0 - kWbAmbient) * diffuse * visibility * lightColor);
}
// Magenta/black stripes mark pixels whose exercise is not implemented yet: visible, never mistaken
// for a shadow.
vec3 wbTodoPattern(vec2 fragCoord) {
  return mod(floor((fragCoord.x + fragCoord.y) / 12.0), 2.0) < 1.0 ? vec3(0.85, 0.1, 0.75) : vec3(0.1);
}
#endif
