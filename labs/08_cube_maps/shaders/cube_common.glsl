// What lab 08's exercises share (not an exercise): directions spread evenly over the sphere, for
// the 3D offsets of 08.5.
#ifndef CUBE_COMMON_GLSL
#define CUBE_COMMON_GLSL
// Direction k of n on a Fibonacci spiral over the unit sphere (k = 0 .. n - 1): evenly spread for
// any n, so 16, 32 and 64 offsets are all good kernels.
vec3 cubeOffsetDir(int k, int n) {
  float y = 1.0 - 2.0 * (float(k) + 0.5) / float(n);
  float r = sqrt(max(0.0, 1.0 - y * y));
  float phi = 2.39996323 * float(k);  // the golden angle
  return vec3(r * cos(phi), y, r * sin(phi));
}
#endif
