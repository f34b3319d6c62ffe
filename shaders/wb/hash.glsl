// An integer hash for per-pixel randomness. Integer arithmetic gives the same bits on every GPU,
// unlike the fract(sin(x) * 43758.5) idiom, whose precision differs between implementations.
#ifndef WB_HASH_GLSL
#define WB_HASH_GLSL
uint wbHash(uvec2 p) {
  uint h = p.x * 0x8da6b343u ^ p.y * 0xd8163841u;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h;
}
// A value in [0, 1) from the hash of a pixel.
float wbHash01(uvec2 p) { return float(wbHash(p) >> 8) / 16777216.0; }
#endif
