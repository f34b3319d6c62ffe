// The frame target every lab's camera pass writes (see Lab::render): colour, the light visibility
// that --dump-visibility saves, and the world position that exact visibility is cast from.
#ifndef WB_OUTPUTS_GLSL
#define WB_OUTPUTS_GLSL
layout(location = 0) out vec4 o_color;
layout(location = 1) out float o_visibility;  // 1 lit, 0 shadowed
layout(location = 2) out vec4 o_position;     // world xyz; w = +1 facing the light, -1 facing away

void wbWriteOutputs(vec3 color, float visibility, vec3 worldPos, bool facesLight) {
  o_color = vec4(color, 1.0);
  o_visibility = facesLight ? visibility : 0.0;  // facing away is an attached shadow, whatever the map says
  o_position = vec4(worldPos, facesLight ? 1.0 : -1.0);
}
#endif
