#include "common/base/value_codec.hpp"

#include "common/base/error.hpp"

#include <cstdint>
#include <cstring>
#include <string>

using nlohmann::json;

namespace wb {
namespace {

uint32_t bits(float v) {
  uint32_t b;
  std::memcpy(&b, &v, 4);
  return b;
}
float fromBits(uint32_t b) {
  float v;
  std::memcpy(&v, &b, 4);
  return v;
}
std::vector<float> floatsOf(const json& j, size_t n) {
  if (!j.is_array() || (n && j.size() != n)) throw Error("a recorded value has the wrong shape");
  std::vector<float> v;
  for (const auto& e : j) v.push_back(fromBits(e.get<uint32_t>()));
  return v;
}

}  // namespace

json encode(float v) { return bits(v); }
json encode(double v) {
  uint64_t b;
  std::memcpy(&b, &v, 8);
  return std::to_string(b);
}
json encode(bool v) { return v; }
json encode(int v) { return v; }
json encode(const glm::vec2& v) { return {bits(v.x), bits(v.y)}; }
json encode(const glm::vec3& v) { return {bits(v.x), bits(v.y), bits(v.z)}; }
json encode(const glm::vec4& v) { return {bits(v.x), bits(v.y), bits(v.z), bits(v.w)}; }
json encode(const glm::dvec2& v) { return {encode(v.x), encode(v.y)}; }
json encode(const glm::mat4& m) {
  json j = json::array();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) j.push_back(bits(m[c][r]));
  return j;
}
json encode(const std::vector<glm::vec4>& v) {
  json j = json::array();
  for (const auto& e : v)
    for (int k = 0; k < 4; ++k) j.push_back(bits(e[k]));
  return j;
}

json encode(const std::vector<glm::vec3>& v) {
  json j = json::array();
  for (const auto& e : v)
    for (int k = 0; k < 3; ++k) j.push_back(bits(e[k]));
  return j;
}

json encode(const std::vector<uint32_t>& v) { return json(v); }

json encode(const std::vector<float>& v) {
  json j = json::array();
  for (float f : v) j.push_back(bits(f));
  return j;
}

namespace {
template <size_t N>
json corners(const std::array<glm::vec3, N>& v) {
  json j = json::array();
  for (const auto& e : v)
    for (int k = 0; k < 3; ++k) j.push_back(bits(e[k]));
  return j;
}
template <size_t N>
std::array<glm::vec3, N> cornersOf(const json& j) {
  const auto f = floatsOf(j, 3 * N);
  std::array<glm::vec3, N> v;
  for (size_t k = 0; k < N; ++k) v[k] = {f[3 * k], f[3 * k + 1], f[3 * k + 2]};
  return v;
}
}  // namespace

json encode(const std::array<glm::vec3, 8>& v) { return corners(v); }
json encode(const std::array<glm::vec3, 4>& v) { return corners(v); }
json encode(const std::array<glm::mat4, 2>& v) { return json::array({encode(v[0]), encode(v[1])}); }

template <>
float decode<float>(const json& j) {
  return fromBits(j.get<uint32_t>());
}
template <>
double decode<double>(const json& j) {
  const uint64_t b = std::stoull(j.get<std::string>());
  double v;
  std::memcpy(&v, &b, 8);
  return v;
}
template <>
bool decode<bool>(const json& j) {
  return j.get<bool>();
}
template <>
int decode<int>(const json& j) {
  return j.get<int>();
}
template <>
glm::vec2 decode<glm::vec2>(const json& j) {
  const auto f = floatsOf(j, 2);
  return {f[0], f[1]};
}
template <>
glm::vec3 decode<glm::vec3>(const json& j) {
  const auto f = floatsOf(j, 3);
  return {f[0], f[1], f[2]};
}
template <>
glm::vec4 decode<glm::vec4>(const json& j) {
  const auto f = floatsOf(j, 4);
  return {f[0], f[1], f[2], f[3]};
}
template <>
glm::dvec2 decode<glm::dvec2>(const json& j) {
  if (!j.is_array() || j.size() != 2) throw Error("a recorded value has the wrong shape");
  return {decode<double>(j[0]), decode<double>(j[1])};
}
template <>
glm::mat4 decode<glm::mat4>(const json& j) {
  const auto f = floatsOf(j, 16);
  glm::mat4 m;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[c][r] = f[size_t(c * 4 + r)];
  return m;
}
template <>
std::vector<glm::vec4> decode<std::vector<glm::vec4>>(const json& j) {
  const auto f = floatsOf(j, 0);
  if (f.size() % 4) throw Error("a recorded kernel output has the wrong shape");
  std::vector<glm::vec4> v;
  for (size_t k = 0; k + 3 < f.size(); k += 4) v.emplace_back(f[k], f[k + 1], f[k + 2], f[k + 3]);
  return v;
}

template <>
std::vector<glm::vec3> decode<std::vector<glm::vec3>>(const json& j) {
  const auto f = floatsOf(j, 0);
  if (f.size() % 3) throw Error("a recorded list of points has the wrong shape");
  std::vector<glm::vec3> v;
  for (size_t k = 0; k + 2 < f.size(); k += 3) v.emplace_back(f[k], f[k + 1], f[k + 2]);
  return v;
}

template <>
std::vector<uint32_t> decode<std::vector<uint32_t>>(const json& j) {
  if (!j.is_array()) throw Error("a recorded index list is not a list");
  std::vector<uint32_t> v;
  v.reserve(j.size());
  for (const auto& e : j) {
    if (!e.is_number_unsigned()) throw Error("a recorded index list holds something that is not an index");
    v.push_back(e.get<uint32_t>());
  }
  return v;
}

template <>
std::vector<float> decode<std::vector<float>>(const json& j) {
  return floatsOf(j, 0);
}

template <>
std::array<glm::vec3, 8> decode<std::array<glm::vec3, 8>>(const json& j) {
  return cornersOf<8>(j);
}
template <>
std::array<glm::vec3, 4> decode<std::array<glm::vec3, 4>>(const json& j) {
  return cornersOf<4>(j);
}
template <>
std::array<glm::mat4, 2> decode<std::array<glm::mat4, 2>>(const json& j) {
  if (!j.is_array() || j.size() != 2) throw Error("a recorded pair of matrices has the wrong shape");
  return {decode<glm::mat4>(j[0]), decode<glm::mat4>(j[1])};
}

}  // namespace wb
