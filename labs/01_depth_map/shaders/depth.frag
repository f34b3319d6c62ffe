#version 410 core
// PASS 1 fragment stage: no colour is written; the depth buffer is the shadow map. Leaves are quads
// with holes in their texture, so their see-through texels must not write depth (exercise 01.5).
#include "exercise.glsl"
in vec2 v_uv;
uniform sampler2D u_albedo;
uniform int u_hasTexture;
uniform float u_alphaCutoff;
void main() {
  if (u_hasTexture != 0) {
    float coverage = casterCoverage(u_albedo, v_uv, u_alphaCutoff);
    // A stub (WB_TODO) keeps every fragment: the quads then cast solid shadows, as without the test.
    if (!wbIsTodo(coverage) && coverage < 0.5) discard;
  }
}
