/// @file value_codec.hpp
/// Exercise values as JSON, exactly: floats by their bits (so NaN, infinity and -0 survive) and
/// doubles by their 64 bits. The grader's tapes (common/judge/tape.hpp) and the app's record of
/// its C++ exercises (exercise_tape.hpp) both use it.
#pragma once
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace wb {

nlohmann::json encode(float v);                            ///< a float by its bits
nlohmann::json encode(double v);                           ///< a double by its bits, as a string
nlohmann::json encode(bool v);                             ///< as it is
nlohmann::json encode(int v);                              ///< as it is
nlohmann::json encode(const glm::vec2& v);                 ///< its floats' bits
nlohmann::json encode(const glm::vec3& v);                 ///< its floats' bits
nlohmann::json encode(const glm::vec4& v);                 ///< its floats' bits
nlohmann::json encode(const glm::dvec2& v);                ///< its doubles' bits
nlohmann::json encode(const glm::mat4& v);                 ///< column by column
nlohmann::json encode(const std::vector<glm::vec4>& v);    ///< every float's bits, in order
nlohmann::json encode(const std::vector<glm::vec3>& v);    ///< every float's bits, in order
nlohmann::json encode(const std::vector<uint32_t>& v);     ///< as they are (indices, GL enums)
nlohmann::json encode(const std::vector<float>& v);        ///< every float's bits, in order
nlohmann::json encode(const std::array<glm::vec3, 8>& v);  ///< every float's bits, corner by corner
nlohmann::json encode(const std::array<glm::vec3, 4>& v);  ///< every float's bits, corner by corner
nlohmann::json encode(const std::array<glm::mat4, 2>& v);  ///< both matrices, column by column
/// Decodes what encode() wrote; throws wb::Error on malformed data.
template <class T>
T decode(const nlohmann::json& j);

}  // namespace wb
