/// @file scene.hpp
/// Scene files (scenes/*.json): primitives with transforms and materials, lights and camera
/// bookmarks. Loading is CPU-only and testable; GpuScene uploads and draws a loaded scene.
#pragma once
#include "common/platform/shader.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/mesh.hpp"

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace wb {

/// Surface appearance: a colour and an optional RGBA texture whose alpha is alpha-tested.
struct Material {
  glm::vec3 color{0.8f};          ///< albedo (multiplies the texture)
  std::filesystem::path texture;  ///< absolute path, or empty for none
};

/// One object: its geometry already in object space, a model matrix and a material.
struct SceneObject {
  std::string name;    ///< from the file, or "objects[i]"
  MeshData mesh;       ///< object-space geometry
  glm::mat4 model{1};  ///< object → world
  Material material;   ///< appearance
  /// Casts a stencil shadow volume (lab 09; file field "casts_volume", default true unless the object
  /// is textured: an alpha-tested outline is not its triangles' outline).
  bool castsVolume = true;
  /// Drawn into the depth shadow maps by the framework's shadow passes (file field "casts_shadow",
  /// default true). A receiver that cannot shade anything, such as a ground that everything stands
  /// on, may say false: the maps then skip its texels (lab 10's field fills three cascades
  /// otherwise). Filtered maps (ESM, VSM, EVSM) draw it anyway: their filtering mixes occluders
  /// with the receivers behind them, and without the receiver it mixes them with the far plane.
  bool castsShadow = true;
};

/// The kinds of light a scene can hold.
enum class LightType { Directional, Spot, Point };

/// A light. Directional lights use `direction`; spot lights use all fields; point lights ignore
/// `direction` and `angle`.
struct Light {
  LightType type = LightType::Directional;  ///< kind of light
  glm::vec3 position{0, 10, 0};             ///< world position (spot, point)
  glm::vec3 direction{0, -1, 0};            ///< unit direction the light travels
  glm::vec3 color{1};                       ///< radiance scale
  float angle = 30;                         ///< spot: half-angle of the cone in degrees
  float nearPlane = 0.5f;                   ///< spot/point: near plane of the shadow projection
  float farPlane = 50;                      ///< spot/point: far plane of the shadow projection
  float size = 0;  ///< spot: the diameter of the light's disk, facing `direction`, in world units (0: a point)
};

/// Where a scene asks for its penumbra to be measured (lab 07): a straight shadow edge on the
/// ground that runs along world x, crossed along z. Ground pixels with x in `x` and z in `z` are cut
/// into `bins` slabs along x, and each slab's visibility profile across z gives one width.
struct PenumbraProbe {
  bool on = false;  ///< the scene has one
  glm::vec2 x{0};   ///< the world x range [lo, hi]
  glm::vec2 z{0};   ///< the world z range [lo, hi]
  int bins = 10;    ///< slabs along x
};

/// A loaded scene file.
struct Scene {
  std::filesystem::path path;           ///< the file it came from
  std::vector<SceneObject> objects;     ///< everything drawn
  std::vector<Light> lights;            ///< at least one
  std::vector<CameraBookmark> cameras;  ///< at least one
  PenumbraProbe penumbraProbe;          ///< "penumbra_probe", if the scene has one
  glm::vec3 boundsMin{0};               ///< world-space minimum corner of all objects
  glm::vec3 boundsMax{0};               ///< world-space maximum corner of all objects

  /// Loads and validates a scene; throws wb::UsageError naming the file, the field and the reason.
  static Scene load(const std::filesystem::path& file);
};

/// `light` turned by `degrees` about the vertical axis through the world's origin (its position and
/// its direction; a turning sun, the lights' orbit setting).
Light turnedAboutY(Light light, float degrees);

/// The object's axis-aligned bounds in world space (first: the smallest x, y, z; second: the
/// largest), from its welded positions through its model matrix.
std::pair<glm::vec3, glm::vec3> worldBounds(const SceneObject& object);

/// Perturbs `scene` deterministically from `seed` (grading-time variations, so a render cannot be
/// copied from published data): every light turns by 1 to 3 degrees (spot and point lights also
/// move by up to 2% of the scene's size) and every camera bookmark turns by up to 3 degrees.
void varyScene(Scene& scene, uint32_t seed);

/// A scene on the GPU: one mesh and texture per object.
class GpuScene {
 public:
  /// Uploads every object and loads the textures (stb_image); throws wb::UsageError on a bad image.
  explicit GpuScene(const Scene& scene);
  /// Draws every object with `program`, setting u_model, u_color and u_hasTexture and binding the
  /// object's texture to unit `textureUnit` (a white texel when it has none). The default is the
  /// last unit GL 4.1 guarantees, so units 0-14 stay the lab's: a shadow map bound to unit 1 is not
  /// replaced by a leaf texture half-way through the draw. Each object is drawn `instances` times
  /// (lab 08 draws six, one per cube face, and picks the face from gl_InstanceID).
  void draw(const Program& program, int textureUnit = kAlbedoUnit, int instances = 1) const;
  /// draw(), but only the objects that cast shadows (SceneObject::castsShadow): the shadow passes.
  void drawCasters(const Program& program, int textureUnit = kAlbedoUnit, int instances = 1) const;
  /// drawCasters(), but only object i where `only[i]` is true (a missing entry is false): lab 10's
  /// per-cascade caster culling.
  void drawCasters(const Program& program, const std::vector<bool>& only) const;
  static constexpr int kAlbedoUnit = 15;  ///< GL 4.1 guarantees 16 texture units per stage

  /// Number of objects; object i is objects[i] of the Scene this was built from.
  size_t objectCount() const { return items_.size(); }
  /// Gives object `object` the index buffer `indices` into its welded positions
  /// (SceneObject::mesh.weldedPositions), drawn as `mode` by drawWelded(): lab 09 passes six per
  /// triangle with GL_TRIANGLES_ADJACENCY. Throws wb::Error for a bad object, index or count.
  void setIndices(size_t object, const std::vector<uint32_t>& indices, GLenum mode);
  /// Draws the welded positions of every object whose welded index buffer is drawn as `mode`
  /// (GL_TRIANGLES: its welded triangles, until setIndices() gives it another) with `program`,
  /// setting u_model, u_color and u_hasTexture = 0. Only attribute 0 (position) is fed. With
  /// `depthClamp`, GL_DEPTH_CLAMP is enabled for the draw (nothing is clipped at the near or far
  /// plane: shadow volumes extruded to infinity keep their far cap) and put back as it was
  /// afterwards; without it the depth-clamp state is left alone. Returns the number of objects drawn.
  size_t drawWelded(const Program& program, GLenum mode, bool depthClamp = false) const;
  /// Draws object `object`'s welded positions with its welded index buffer, as drawWelded() does
  /// (so a lab can change state between casters); throws wb::Error for an object out of range.
  void drawObjectWelded(size_t object, const Program& program, bool depthClamp = false) const;

 private:
  void drawItems(const Program& program, int unit, int instances, bool castersOnly,
                 const std::vector<bool>* only = nullptr) const;
  struct Item {
    Mesh mesh;
    glm::mat4 model;
    glm::vec3 color;
    GLuint texture;
    bool textured;
    bool casts;
  };
  std::vector<Item> items_;
  std::vector<Texture> textures_;
  Texture white_;
};

}  // namespace wb
