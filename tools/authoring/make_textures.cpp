// Generates the procedural textures under scenes/textures/ (committed; rerun to regenerate):
//   build/tools/wb_make_textures scenes/textures
// leaves.png: clusters of opaque leaf shapes on a fully transparent background, for alpha-tested
// shadow casters. The pattern comes from an integer hash, so it is the same on every machine.
#include "common/platform/image.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace {
uint32_t hash(uint32_t x) {
  x ^= x >> 16, x *= 0x7feb352dU, x ^= x >> 15, x *= 0x846ca68bU, x ^= x >> 16;
  return x;
}
float unit(uint32_t seed) { return float(hash(seed) & 0xffffff) / float(0x1000000); }
}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "scenes/textures";
  const int n = 128;
  std::vector<uint8_t> rgba(size_t(n) * n * 4, 0);
  // Each leaf is an ellipse with a random centre, size and orientation; the borders wrap around.
  for (uint32_t leaf = 0; leaf < 70; ++leaf) {
    const float cx = unit(leaf * 5) * n, cy = unit(leaf * 5 + 1) * n, a = unit(leaf * 5 + 2) * 3.14159f;
    const float len = 7 + unit(leaf * 5 + 3) * 6, wid = len * 0.45f, shade = 0.6f + 0.4f * unit(leaf * 5 + 4);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        float dx = std::remainder(x - cx, float(n)), dy = std::remainder(y - cy, float(n));
        float u = dx * std::cos(a) + dy * std::sin(a), v = -dx * std::sin(a) + dy * std::cos(a);
        if ((u * u) / (len * len) + (v * v) / (wid * wid) > 1) continue;
        uint8_t* p = &rgba[(size_t(y) * n + x) * 4];
        p[0] = uint8_t(60 * shade), p[1] = uint8_t(150 * shade), p[2] = uint8_t(50 * shade), p[3] = 255;
      }
  }
  wb::writePng(dir / "leaves.png", n, n, rgba);
  std::printf("wrote %s\n", (dir / "leaves.png").string().c_str());
}
