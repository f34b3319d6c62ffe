#version 410 core
// One level of SDSM's reduction: each texel reduces the 2x2 texels of the level before (11.5);
// a texel past that level's edge holds nothing, (0, 0).
#include "exercise.glsl"
uniform sampler2D u_source;
uniform ivec2 u_sourceSize;
out vec2 o_bounds;
vec2 at(ivec2 p) { return all(lessThan(p, u_sourceSize)) ? texelFetch(u_source, p, 0).xy : vec2(0.0); }
void main() {
  ivec2 p = 2 * ivec2(gl_FragCoord.xy);
  o_bounds = minMaxDepth(at(p), at(p + ivec2(1, 0)), at(p + ivec2(0, 1)), at(p + ivec2(1, 1)));
}
