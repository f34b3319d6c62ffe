/// @file gl.hpp
/// Kept for exercise files written before the floors (common/README.md): they include
/// "common/gl.hpp". The framework itself includes common/platform/gl.hpp.
#pragma once
#include "common/platform/gl.hpp"
