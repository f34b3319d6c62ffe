#include "common/shell/debug_views.hpp"

#include "common/base/settings.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace wb {

void DebugOptions::addTo(Settings& settings) {
  settings.addChoice("debug.view", view, {"camera", "light"}, "see the scene from the camera or from the light");
  settings.add("debug.shadow_map", showMap,
               "show the shadow map in a corner (linearised; one inset per cascade, a cross for a cube map)");
  settings.add("debug.frustum", showFrustum, "draw the light's frustum (one per cube face or cascade) in the scene");
}

void DebugOptions::addLightFace(Settings& settings) {
  settings.add("debug.light_face", lightFace, 0, 7, "view from the light: which cube face (0-5) or cascade");
}

DebugViews::DebugViews()
    : lines_({{GL_VERTEX_SHADER, "wb/frustum.vert"}, {GL_FRAGMENT_SHADER, "wb/flat.frag"}}),
      inset_({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "wb/depth_view.frag"}}),
      insetArray_({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "wb/depth_view.frag"}},
                  "#define WB_ARRAY 1\n"),
      cube_({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "wb/cube_view.frag"}}),
      overlay_({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "wb/overlay.frag"}}),
      vao_(makeEmptyVertexArray()),
      plain_(makePlainSampler()) {}

glm::mat4 DebugViews::fromLight(const LightView& light, int face, glm::ivec2 frame) {
  const float aspect = float(frame.x) / float(frame.y);
  const glm::vec3 fit = aspect > 1 ? glm::vec3(1 / aspect, 1, 1) : glm::vec3(1, aspect, 1);
  const size_t k = size_t(std::max(face, 0)) % light.viewProj.size();
  return glm::scale(glm::mat4(1), fit) * light.viewProj[k];
}

void DebugViews::draw(const DebugOptions& options, const LightView& light, const glm::mat4& viewer,
                      const FrameTarget& target, GLuint heatmap) const {
  target.bind();
  target.maskDataOutputs(true);  // overlays change what people see, never what is measured
  for (GLenum state : {GL_STENCIL_TEST, GL_SCISSOR_TEST, GL_CULL_FACE}) glDisable(state);  // whatever the lab left on
  glBindVertexArray(vao_.id());
  if (options.showFrustum && light.hasMap()) drawFrusta(light, viewer);
  if (options.showMap && light.hasMap()) drawInset(light, target.size());
  if (heatmap) drawHeatmap(heatmap, target.size());
  target.maskDataOutputs(false);
  glViewport(0, 0, target.size().x, target.size().y);
}

void DebugViews::drawFrusta(const LightView& light, const glm::mat4& viewer) const {
  // Cascades get the usual red, green, blue, yellow; a single map or a cube's faces are yellow.
  const glm::vec3 cascade[4] = {{1, 0.25f, 0.2f}, {0.3f, 1, 0.3f}, {0.3f, 0.5f, 1}, {1, 0.85f, 0.1f}};
  const bool layers = light.target == GL_TEXTURE_2D_ARRAY;
  lines_.use();
  lines_.set("u_viewProj", viewer);
  for (size_t k = 0; k < light.viewProj.size(); ++k) {
    lines_.set("u_invLight", glm::inverse(light.viewProj[k]));
    lines_.set("u_color", layers ? cascade[k % 4] : glm::vec3(1, 0.85f, 0.1f));
    glDrawArrays(GL_LINES, 0, 24);
  }
  lines_.set("u_useCorners", 1);
  for (size_t k = 0; k < light.outlines.size(); ++k) {
    for (int c = 0; c < 8; ++c)
      lines_.set(("u_corners[" + std::to_string(c) + "]").c_str(), light.outlines[k][size_t(c)]);
    lines_.set("u_color", 0.6f * (layers ? cascade[k % 4] : glm::vec3(1, 0.85f, 0.1f)));
    glDrawArrays(GL_LINES, 0, 24);
  }
  lines_.set("u_useCorners", 0);
}

void DebugViews::drawInset(const LightView& light, glm::ivec2 frame) const {
  // Bottom left: the Settings window covers the right side.
  glDisable(GL_DEPTH_TEST);
  GLint labSampler = 0;  // the lab may keep its own sampler on unit 0
  glActiveTexture(GL_TEXTURE0);
  glGetIntegerv(GL_SAMPLER_BINDING, &labSampler);
  glBindSampler(0, plain_.id());
  bindTexture(0, light.texture);
  const bool perspective = light.light.type != LightType::Directional;
  if (light.target == GL_TEXTURE_CUBE_MAP) {
    const int cell = std::max(8, std::min(frame.y / 7, (frame.x / 2 - 8) / 4));
    glViewport(8, 8, 4 * cell, 3 * cell);
    cube_.use();
    cube_.set("u_linear", light.linearDistance ? 1 : 0);
    cube_.set("u_near", light.light.nearPlane);
    cube_.set("u_far", light.light.farPlane);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  } else {
    const bool array = light.target == GL_TEXTURE_2D_ARRAY;
    const int n = array ? int(light.viewProj.size()) : 1;
    const int s = std::max(8, std::min(frame.y / 3, (frame.x / 2 - 8) / n - 4));
    const Program& p = array ? insetArray_ : inset_;
    p.use();
    p.set("u_perspective", perspective ? 1 : 0);
    p.set("u_near", light.light.nearPlane);
    p.set("u_far", light.light.farPlane);
    for (int k = 0; k < n; ++k) {  // one inset per cascade, left to right
      glViewport(8 + k * (s + 4), 8, s, s);
      if (array) p.set("u_layer", k);
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
  }
  glBindSampler(0, GLuint(labSampler));
  glEnable(GL_DEPTH_TEST);
}

void DebugViews::drawHeatmap(GLuint heatmap, glm::ivec2 frame) const {
  // Red: acne, blue: light leaking (see ground_truth.hpp).
  glViewport(0, 0, frame.x, frame.y);
  glDisable(GL_DEPTH_TEST);
  glEnablei(GL_BLEND, 0);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  overlay_.use();
  bindTexture(0, heatmap);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisablei(GL_BLEND, 0);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace wb
