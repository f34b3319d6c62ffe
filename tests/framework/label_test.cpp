// Text burnt into frames (labels, presenter captions): DejaVu Sans through a signed-distance atlas,
// with the symbols captions use, and captions large enough for a lecture hall.
#include "common/platform/label.hpp"
#include "common/judge/harness.hpp"
#include "common/platform/font.hpp"
#include "common/platform/texture_io.hpp"
#include "common/shell/presenter.hpp"

#include <string>
#include <vector>

TEST(Font, DecodesUtf8AndMarksWhatIsMalformed) {
  EXPECT_EQ(wb::decodeUtf8("a\xC2\xB1\xC3\x97\xC2\xB5\xE2\x89\xA4"), std::u32string(U"a\u00B1\u00D7\u00B5\u2264"));
  EXPECT_EQ(wb::decodeUtf8("x\xC3"), std::u32string(U"x\uFFFD")) << "a sequence cut short";
  EXPECT_EQ(wb::decodeUtf8("\xE2\x89y"), std::u32string(U"\uFFFD\uFFFDy")) << "a continuation byte missing";
  EXPECT_EQ(wb::decodeUtf8("\xFF"), std::u32string(U"\uFFFD"));
}

TEST(Presenter, CaptionsAreAtLeast28PixelsAt1080p) {
  EXPECT_GE(wb::Presenter::captionPixels({1920, 1080}), 28.0f);
  EXPECT_GE(wb::Presenter::captionPixels({1280, 720}), 18.0f);
}

namespace {
// Draws `text` at `scale` into a w x h target cleared to black; returns the red channel, row by row.
std::vector<unsigned char> drawn(wb::Label& label, const std::string& text, float scale, int w = 160, int h = 48) {
  const wb::Texture color = wb::makeTexture2D(GL_RGBA8, w, h);
  const wb::Framebuffer fbo = wb::makeFramebuffer({color.id()}, 0);
  wb::BoundFramebuffer into(fbo.id());
  glViewport(0, 0, w, h);
  const float black[4] = {0, 0, 0, 1};
  glClearBufferfv(GL_COLOR, 0, black);
  label.draw(text, {4, 4}, {w, h}, scale);
  std::vector<unsigned char> rgba(size_t(w) * size_t(h) * 4), red;
  wb::readTexture(color.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  for (size_t k = 0; k < rgba.size(); k += 4) red.push_back(rgba[k]);
  return red;
}
int bright(const std::vector<unsigned char>& v) {
  int n = 0;
  for (unsigned char c : v) n += c > 128;
  return n;
}
}  // namespace

using wb::test::GlTest;
// Every symbol the captions use has a glyph of its own (not the '?' of a missing one), and 0 and 8
// are told apart (stb_easy_font's were nearly one shape).
TEST_F(GlTest, LabelsDrawTheCaptionsSymbolsInDejaVuSans) {
  wb::Label label;
  if (!label.hasFont()) GTEST_SKIP() << "no DejaVu Sans here (fonts-dejavu-core)";
  const std::vector<unsigned char> question = drawn(label, "?", 3);
  for (const char* symbol : {"\xC2\xB1", "\xC3\x97", "\xC2\xB5", "\xE2\x89\xA4", "\xC2\xB2", "\xCF\x83"}) {
    const std::vector<unsigned char> got = drawn(label, symbol, 3);
    EXPECT_GT(bright(got), 20) << symbol << " drew nothing";
    EXPECT_NE(got, question) << symbol << " was drawn as the glyph for a missing character";
  }
  const std::vector<unsigned char> zero = drawn(label, "0", 3), eight = drawn(label, "8", 3);
  int differ = 0;
  for (size_t k = 0; k < zero.size(); ++k) differ += (zero[k] > 128) != (eight[k] > 128);
  EXPECT_GT(differ, 15) << "0 and 8 look alike";
  EXPECT_GT(label.width("WWW"), label.width("iii")) << "a proportional font";
}
