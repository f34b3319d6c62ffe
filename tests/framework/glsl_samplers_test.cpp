// The GLSL kernel harness declares each wb_texN with the sampler type of its texture: 2D, cube map
// and 2D array, each plain or with a depth comparison. Every type reads tiny textures of known
// texels, and each answer below is worked out by hand.
#include "common/base/error.hpp"
#include "common/exercise/glsl_harness.hpp"
#include "common/judge/harness.hpp"
#include "common/platform/texture_io.hpp"

#include <string>
#include <vector>

namespace {

// A texture of `target` (2D, cube map or 2D array) with `layers` layers (6 for a cube map) of w × h
// texels of one float each, nearest filtering; a depth texture compares (GL_LEQUAL) when `compare`.
wb::Texture makeTexture(GLenum target, GLenum format, int w, int h, int layers, const std::vector<float>& texels,
                        bool compare = false) {
  wb::Texture texture = wb::makeTexture(target);
  {
    wb::BoundTexture edit(target, texture.id());
    wb::allocateTexture(target, 1, format, w, h, layers);
  }
  const GLenum pixelFormat = format == GL_DEPTH_COMPONENT32F ? GL_DEPTH_COMPONENT : GL_RED;
  // (a cube map's faces are layers 0-5: +X, -X, +Y, -Y, +Z, -Z)
  wb::uploadTextureLayers(texture.id(), w, h, layers, pixelFormat, GL_FLOAT, texels.data());
  wb::setTextureParameter(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  wb::setTextureParameter(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  if (compare) {
    wb::setTextureParameter(texture.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    wb::setTextureParameter(texture.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  }
  return texture;
}

// One probe: which texture (wb_tex<which>), the coordinate handed to texture(), and the answer.
struct Probe {
  int which;
  glm::vec4 coord;
  float want;
  const char* what;
};

}  // namespace

using wb::test::GlTest;

TEST_F(GlTest, KernelTexturesAreDeclaredWithTheirSamplerType) {
  // 2D: texels 1 2 / 3 4 (row 0 at v < 0.5). Cube map: face f holds 10 (f + 1). 2D array: layer l
  // holds 100 (l + 1). Depth: a 2D map of 0.25 0.5 / 0.75 1, cube faces at 0.1 (f + 1), array layers
  // at 0.25, 0.5, 0.75. A comparison is 1 where ref <= the stored depth (GL_LEQUAL), else 0.
  const wb::Texture tex2d = makeTexture(GL_TEXTURE_2D, GL_R32F, 2, 2, 1, {1, 2, 3, 4});
  const wb::Texture shadow2d =
      makeTexture(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, 2, 2, 1, {0.25f, 0.5f, 0.75f, 1}, true);
  const wb::Texture cube = makeTexture(GL_TEXTURE_CUBE_MAP, GL_R32F, 1, 1, 6, {10, 20, 30, 40, 50, 60});
  const wb::Texture shadowCube =
      makeTexture(GL_TEXTURE_CUBE_MAP, GL_DEPTH_COMPONENT32F, 1, 1, 6, {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f}, true);
  const wb::Texture array = makeTexture(GL_TEXTURE_2D_ARRAY, GL_R32F, 1, 1, 3, {100, 200, 300});
  const wb::Texture shadowArray =
      makeTexture(GL_TEXTURE_2D_ARRAY, GL_DEPTH_COMPONENT32F, 1, 1, 3, {0.25f, 0.5f, 0.75f}, true);
  const std::vector<GLuint> textures = {tex2d.id(),      shadow2d.id(), cube.id(),
                                        shadowCube.id(), array.id(),    shadowArray.id()};
  using wb::SamplerType;
  const SamplerType types[] = {SamplerType::Sampler2D,      SamplerType::Sampler2DShadow,
                               SamplerType::SamplerCube,    SamplerType::SamplerCubeShadow,
                               SamplerType::Sampler2DArray, SamplerType::Sampler2DArrayShadow};
  const char* names[] = {"sampler2D",         "sampler2DShadow", "samplerCube",
                         "samplerCubeShadow", "sampler2DArray",  "sampler2DArrayShadow"};
  for (size_t t = 0; t < textures.size(); ++t) {
    EXPECT_EQ(wb::samplerTypeOf(textures[t]), types[t]) << names[t];
    EXPECT_STREQ(wb::glslSamplerName(types[t]), names[t]);
  }

  const Probe probes[] = {
      {0, {0.25f, 0.25f, 0, 0}, 1, "2D texel (0, 0)"},
      {0, {0.75f, 0.25f, 0, 0}, 2, "2D texel (1, 0)"},
      {0, {0.25f, 0.75f, 0, 0}, 3, "2D texel (0, 1)"},
      {0, {0.75f, 0.75f, 0, 0}, 4, "2D texel (1, 1)"},
      {1, {0.25f, 0.25f, 0.2f, 0}, 1, "2D shadow: ref 0.2 <= 0.25"},
      {1, {0.25f, 0.25f, 0.3f, 0}, 0, "2D shadow: ref 0.3 > 0.25"},
      {1, {0.75f, 0.75f, 0.9f, 0}, 1, "2D shadow: ref 0.9 <= 1"},
      {1, {0.75f, 0.25f, 0.6f, 0}, 0, "2D shadow: ref 0.6 > 0.5"},
      {2, {1, 0.3f, -0.2f, 0}, 10, "cube +X"},
      {2, {-1, 0.2f, 0.4f, 0}, 20, "cube -X"},
      {2, {0.1f, 1, -0.3f, 0}, 30, "cube +Y"},
      {2, {0.2f, -1, 0.1f, 0}, 40, "cube -Y"},
      {2, {-0.4f, 0.3f, 1, 0}, 50, "cube +Z"},
      {2, {0.3f, 0.2f, -1, 0}, 60, "cube -Z"},
      {3, {1, 0.3f, -0.2f, 0.35f}, 0, "cube shadow +X: ref 0.35 > 0.1"},
      {3, {-1, 0.2f, 0.4f, 0.35f}, 0, "cube shadow -X: ref 0.35 > 0.2"},
      {3, {0.1f, 1, -0.3f, 0.35f}, 0, "cube shadow +Y: ref 0.35 > 0.3"},
      {3, {0.2f, -1, 0.1f, 0.35f}, 1, "cube shadow -Y: ref 0.35 <= 0.4"},
      {3, {-0.4f, 0.3f, 1, 0.35f}, 1, "cube shadow +Z: ref 0.35 <= 0.5"},
      {3, {0.3f, 0.2f, -1, 0.35f}, 1, "cube shadow -Z: ref 0.35 <= 0.6"},
      {3, {1, 0, 0, 0.05f}, 1, "cube shadow +X: ref 0.05 <= 0.1"},
      {4, {0.5f, 0.5f, 0, 0}, 100, "array layer 0"},
      {4, {0.5f, 0.5f, 1, 0}, 200, "array layer 1"},
      {4, {0.5f, 0.5f, 2, 0}, 300, "array layer 2"},
      {5, {0.5f, 0.5f, 0, 0.4f}, 0, "array shadow layer 0: ref 0.4 > 0.25"},
      {5, {0.5f, 0.5f, 1, 0.4f}, 1, "array shadow layer 1: ref 0.4 <= 0.5"},
      {5, {0.5f, 0.5f, 1, 0.6f}, 0, "array shadow layer 1: ref 0.6 > 0.5"},
      {5, {0.5f, 0.5f, 2, 0.6f}, 1, "array shadow layer 2: ref 0.6 <= 0.75"},
  };
  std::vector<glm::vec4> in;
  for (const auto& p : probes) in.insert(in.end(), {p.coord, glm::vec4(float(p.which))});
  // Each call compiles only with its sampler type: texture(sampler2DShadow, vec3) returns a float,
  // texture(samplerCubeShadow, vec4) takes the reference as w, and so on.
  const std::string body =
      "int k = int(IN(1).x);\n  vec4 c = IN(0);\n"
      "  if (k == 0) result.x = texture(wb_tex0, c.xy).r;\n"
      "  else if (k == 1) result.x = texture(wb_tex1, c.xyz);\n"
      "  else if (k == 2) result.x = texture(wb_tex2, c.xyz).r;\n"
      "  else if (k == 3) result.x = texture(wb_tex3, c);\n"
      "  else if (k == 4) result.x = texture(wb_tex4, c.xyz).r;\n"
      "  else result.x = texture(wb_tex5, c);\n";
  std::vector<glm::vec4> got;
  try {
    got = wb::runGlslKernel("", "samplers.glsl", body, int(std::size(probes)), 2, in, textures);
  } catch (const wb::Error& e) {
    FAIL() << e.what();
  }
  for (size_t k = 0; k < std::size(probes); ++k) EXPECT_EQ(got[k].x, probes[k].want) << probes[k].what;
}

// A depth texture without a compare mode reads as sampler2D; declared sampler2DShadow with a
// compare sampler object, the same texture compares. The sampler is unbound afterwards, and the
// fixed wb_shadow0 (unit 7) still works beside the typed textures.
TEST_F(GlTest, KernelTexturesCanNameTheirTypeAndSampler) {
  const wb::Texture depth = makeTexture(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, 1, 1, 1, {0.5f});
  GLuint sampler = 0;
  glGenSamplers(1, &sampler);
  const wb::Sampler owner(sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  EXPECT_EQ(wb::samplerTypeOf(depth.id()), wb::SamplerType::Sampler2D);
  wb::bindTexture(7, depth.id());
  glBindSampler(7, sampler);
  const std::vector<glm::vec4> in = {{0.5f, 0.5f, 0.4f, 0}, {0.5f, 0.5f, 0.6f, 0}};
  const std::string body =
      "result = vec4(texture(wb_tex0, IN(0).xy).r, texture(wb_tex1, IN(0).xyz), "
      "texture(wb_shadow0, IN(0).xyz), 0.0);";
  std::vector<glm::vec4> got;
  try {
    got = wb::runGlslKernelWithSamplers(
        "", "samplers.glsl", body, 2, 1, in,
        {{depth.id(), wb::SamplerType::Auto, 0}, {depth.id(), wb::SamplerType::Sampler2DShadow, sampler}});
  } catch (const wb::Error& e) {
    FAIL() << e.what();
  }
  glBindSampler(7, 0);
  EXPECT_EQ(got[0], glm::vec4(0.5f, 1, 1, 0)) << "raw depth 0.5; ref 0.4 <= 0.5 twice";
  EXPECT_EQ(got[1], glm::vec4(0.5f, 0, 0, 0)) << "raw depth 0.5; ref 0.6 > 0.5 twice";
  GLint bound = -1;
  glActiveTexture(GL_TEXTURE1);
  glGetIntegerv(GL_SAMPLER_BINDING, &bound);
  glActiveTexture(GL_TEXTURE0);
  EXPECT_EQ(bound, 0) << "the kernel's sampler object must be unbound after the run";
}

TEST_F(GlTest, AKernelTextureOfAnotherTargetIsAClearError) {
  const wb::Texture volume = wb::makeTexture(GL_TEXTURE_3D);
  {
    wb::BoundTexture edit(GL_TEXTURE_3D, volume.id());
    glTexImage3D(GL_TEXTURE_3D, 0, GL_R32F, 1, 1, 1, 0, GL_RED, GL_FLOAT, nullptr);
  }
  try {
    wb::runGlslKernel("", "samplers.glsl", "result = vec4(1.0);", 1, 1, {}, {volume.id()});
    FAIL() << "a 3D texture was accepted";
  } catch (const wb::Error& e) {
    EXPECT_NE(std::string(e.what()).find("GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP or GL_TEXTURE_2D_ARRAY"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(wb::glslSamplerName(wb::SamplerType::Auto), wb::Error);
}
