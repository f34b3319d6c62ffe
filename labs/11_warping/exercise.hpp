/// @file exercise.hpp
/// Lab 11 C++ exercises. The signatures are fixed: the app, the tests and the grader call them.
#pragma once
#include <glm/glm.hpp>

#include <vector>

namespace lab11 {

/// EXERCISE 11.3: LiSPSM's distance n from the warp's eye to the near side of the body it covers
/// (Wimmer, Scherzer and Purgathofer 2004), scaled by the lab's slider and faded near the light.
/// - `zNear`: the view distance where the body starts (z0); `depthRange`: the body's extent d along
///   the warp axis (the view direction projected across the light); `sinGamma`: sin of the angle γ
///   between the view direction and the light's.
/// - n_opt = (z0 + sqrt(z0 · z1)) / sin γ, with z1 = z0 + d · sin γ (README.md derives it).
/// - The fade: f = 0 for sin γ ≤ 0.02, 1 for sin γ ≥ `fadeSin`, linear between (f = 1 when
///   `fadeSin` ≤ 0.02 and sin γ > 0.02). With s = `strength` · f: n = n_opt / s, and +infinity when
///   s = 0 (no warp: the uniform map).
float warpNear(float zNear, float depthRange, float sinGamma, float strength, float fadeSin);

/// EXERCISE 11.4: the warped light matrix. `lightView` takes world space to light space, where the
/// light looks down −z and +y is the warp axis (the view direction projected across the light).
/// `body`: the points the map must cover. `n`: 11.3's distance (+infinity: no warp).
/// `casterReach`: how far towards the light (world units) the depth range reaches past the body.
/// - No warp: glm::ortho over the body's light-space bounds (x, y; depth extended by casterReach
///   towards the light) times lightView.
/// - A warp: the same orthographic depth; a perspective along +y whose eye sits n before the body's
///   nearest y, on the body's x centre, mapping the body's y range onto [−1, 1] (near side −1), and
///   dividing x and the depth by the distance from the eye along y; then x scaled and moved so the
///   body's warped x range is exactly [−1, 1].
glm::mat4 warpMatrix(const glm::mat4& lightView, const std::vector<glm::vec3>& body, float n, float casterReach);

/// EXERCISE 11.6: SDSM's splits. `bounds`: the smallest and largest view distance the frame holds
/// (11.5's reduction; (0, 0) when it holds nothing). The range is `bounds` clamped to
/// [nearPlane, farPlane], or [nearPlane, farPlane] itself when `bounds` holds nothing or the clamped
/// range is empty. Returns C_0 .. C_N (N = `cascades`) between its ends by the practical scheme:
/// C_i = λ · lo · (hi / lo)^(i / N) + (1 − λ) · (lo + (hi − lo) · i / N); C_0 = lo and C_N = hi exactly.
std::vector<float> fittedSplits(glm::vec2 bounds, float nearPlane, float farPlane, int cascades, float lambda);

/// EXERCISE 11.H1 (a bug hunt: working code with a real bug in it; README.md): the view distances at
/// which the camera pass switches from one cascade to the next (the far end of every cascade but the
/// last), from `splits` (11.6: C_0 .. C_N, fitted to the frame with warp.sdsm=on). The camera pass keeps
/// the split positions as fractions of the shadow range, as engines do, and turns them back into
/// distances here; `nearPlane` and `farPlane` are the camera's near plane and the shadow distance.
std::vector<float> switchDistances(const std::vector<float>& splits, float nearPlane, float farPlane);

}  // namespace lab11
