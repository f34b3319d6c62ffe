#include "common/platform/image.hpp"

#include "common/base/error.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <cctype>
#include <fstream>

namespace wb {

void writePng(const std::filesystem::path& file, int w, int h, const std::vector<uint8_t>& rgba) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  stbi_flip_vertically_on_write(1);  // GL rows run bottom to top, image rows top to bottom
  std::string ext = file.extension().string();
  for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  const bool jpg = ext == ".jpg" || ext == ".jpeg";  // what the name says is what is written
  if (!jpg && ext != ".png") throw UsageError("cannot write '" + file.string() + "': images are .png or .jpg");
  const int ok = jpg ? stbi_write_jpg(file.string().c_str(), w, h, 4, rgba.data(), 92)
                     : stbi_write_png(file.string().c_str(), w, h, 4, rgba.data(), w * 4);
  if (!ok) throw Error("cannot write " + file.string() + " (is the folder writable?)");
}

void writePfm(const std::filesystem::path& file, const FloatImage& img) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  if (!out) throw Error("cannot write " + file.string() + " (is the folder writable?)");
  out << "Pf\n" << img.width << " " << img.height << "\n-1.0\n";  // negative scale: little-endian
  out.write(reinterpret_cast<const char*>(img.pixels.data()), std::streamsize(img.pixels.size() * sizeof(float)));
}

FloatImage readPfm(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error("cannot read " + file.string());
  std::string magic;
  FloatImage img;
  float scale = 0;
  in >> magic >> img.width >> img.height >> scale;
  in.get();  // the single whitespace byte before the data
  if (magic != "Pf" || img.width <= 0 || img.height <= 0 || scale >= 0)
    throw Error(file.string() + ": not a little-endian greyscale PFM");
  img.pixels.resize(size_t(img.width) * img.height);
  in.read(reinterpret_cast<char*>(img.pixels.data()), std::streamsize(img.pixels.size() * sizeof(float)));
  if (!in) throw Error(file.string() + ": truncated PFM");
  return img;
}

std::vector<uint8_t> toGrey(const FloatImage& img, float lo, float hi) {
  std::vector<uint8_t> rgba(img.pixels.size() * 4, 255);
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    float t = std::clamp((img.pixels[i] - lo) / (hi - lo), 0.0f, 1.0f);
    rgba[4 * i] = rgba[4 * i + 1] = rgba[4 * i + 2] = static_cast<uint8_t>(t * 255 + 0.5f);
  }
  return rgba;
}

}  // namespace wb
