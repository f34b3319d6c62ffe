/// @file strf.hpp
/// printf into a std::string, for the short texts of measurements and tables.
#pragma once
#include <cstdio>
#include <string>

namespace wb {

/// Formats like std::snprintf into a std::string (texts up to 511 characters).
template <typename... Args>
std::string strf(const char* format, Args... args) {
  char text[512];
  std::snprintf(text, sizeof text, format, args...);
  return text;
}

}  // namespace wb
