/// @file exercise.hpp
/// Lab 02 C++ exercises: the depth-pass state that fights acne. The signatures are fixed.
#pragma once

namespace lab02 {

/// EXERCISE 02.3a: turn on OpenGL's rasterizer depth bias for filled polygons, with the given slope
/// factor and constant units (glPolygonOffset). The lab turns it off again after the depth pass.
void applyRasterizerBias(float factor, float units);

/// EXERCISE 02.3b: Direct3D's depth-bias rule for a floating-point depth buffer:
/// bias = depthBias · 2^(exponent(maxZ) − 23) + slopeScaledDepthBias · maxDepthSlope, then clamped
/// to depthBiasClamp (a positive clamp caps the bias, a negative one floors it, 0 means no clamp).
/// `maxZ` is the largest depth of the primitive, `maxDepthSlope` = max(|∂z/∂x|, |∂z/∂y|).
double d3dDepthBias(int depthBias, double slopeScaledDepthBias, double depthBiasClamp, double maxDepthSlope,
                    float maxZ);

/// EXERCISE 02.4: when `enabled`, cull the faces that look at the light in the depth pass, so the map
/// stores the back faces; when not, turn culling off.
void cullForDepthPass(bool enabled);

/// EXERCISE 02.H1 (a bug hunt: working code with a real bug in it; README.md): the depth pass's face
/// culling for every method but front_faces.
void depthPassCulling();

}  // namespace lab02
