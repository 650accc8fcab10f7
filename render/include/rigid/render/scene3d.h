// 3D scenes: shapes, tubes, arrows, an axis triad and labels, seen through a
// look-at camera and lit softly by a key and a fill light (Lambert diffuse,
// mild Blinn-Phong highlight, hemispheric ambient). Translucent surfaces are
// drawn after opaque ones, back faces of all before front faces, each pass
// sorted far to near, which is exact for nested convex shapes such as an
// energy ellipsoid inside a momentum ellipsoid. The scene knows only
// geometry: a lab converts its physics into points, directions and sizes.
// Coordinates are right-handed; the default camera looks at the origin with
// +z up. Rendering uses a depth buffer and 4× MSAA. The title and legend share
// Plot2D's style; labels place themselves beside their points, clear of the
// drawn geometry, of each other and of the title and legend.
//
// This header is the description library (rigid::render, Eigen only): it
// declares nothing it cannot define, so a program linking only the description
// links. Laying out, fitting the camera, drawing and saving a scene take fonts
// and OpenGL; they are free functions of the drawing library (rigid::render_gl,
// draw.h), which exists only in builds with the renderer.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "rigid/render/mesh.h"
#include "rigid/render/palette.h"

namespace rigid::render {

/// A look-at camera; orthographic when asked, else perspective with a vertical field of view.
struct Camera {
  Eigen::Vector3d eye{4.0, 3.0, 2.5};
  Eigen::Vector3d target{0.0, 0.0, 0.0};
  Eigen::Vector3d up{0.0, 0.0, 1.0};
  double fov_y_deg = 30.0;  ///< perspective only
  bool orthographic = false;
  double ortho_height = 0.0;  ///< world height seen; 0 matches the perspective view at the target
  /// Frame the scene tightly: keeping the viewing direction (eye - target) and up, move the eye
  /// along its line of sight and sideways in the image plane (or set the orthographic height)
  /// so the projected geometry, its labels' text and its lines' widths fill the free region of
  /// layout() (draw.h), clear of the title and legend, without distorting the perspective.
  bool fit = true;
};

/// Surface appearance; opacity < 1 makes the surface translucent.
struct Material {
  Color color = kAutoColor;
  float opacity = 1.0f;
  float specular = 0.25f;   ///< strength of the Blinn-Phong highlight
  float shininess = 48.0f;  ///< Blinn-Phong exponent
  /// false: drawn in its flat colour, unshaded (a translucent plate or disk whose
  /// colour must match its legend swatch from any side).
  bool lit = true;
};

/// Text naming a 3D point: drawn on the point where that is clear, else beside it (right,
/// left, above, below, diagonally), wherever it covers the least geometry and no other text.
struct Label3D {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  std::string text;
  Color color = kTextColor;
  /// Centred on its point whatever it covers, unless another text is there: for the end
  /// of a leader line the scene draws to it (moved off, the label would leave its leader).
  bool pinned = false;
};

/// A scene of shapes, lines and labels rendered to an image.
class Scene3D {
 public:
  Camera camera;
  std::string title;        ///< drawn at the top (text.h markup)
  bool show_legend = true;  ///< a legend of labelled objects in the top-right corner
  /// The smallest text drawn (labels, the legend), in pixels; 0: the figure style's own
  /// at the image's size. A scene shown small on a screen sets it, so it stays legible.
  double min_text_px = 0;
  /// When set, the legend drawn is this scene's (each entry once), then any part of this
  /// scene's own it lacks: an animation's frames share the legend of all of them, so it
  /// neither grows nor reorders when a part appears mid-film (the path so far, the
  /// herpolhode).
  std::shared_ptr<const Scene3D> legend_from;

  /// Sphere of a radius about a centre.
  void add_sphere(const Eigen::Vector3d& center, double radius, Material m = {},
                  std::string label = {});
  /// A point drawn as a ball (a start, a mass, a pivot): its legend entry is a dot of its
  /// colour, not a bar a reader would take for a line.
  void add_marker(const Eigen::Vector3d& center, double radius, Material m = {},
                  std::string label = {});
  /// Ellipsoid with semi-axes a (columns of rotation give their directions).
  void add_ellipsoid(const Eigen::Vector3d& center, const Eigen::Vector3d& semi_axes,
                     const Eigen::Matrix3d& rotation, Material m = {}, std::string label = {});
  /// Solid cone from a base circle (centre, radius) to an apex.
  void add_cone(const Eigen::Vector3d& apex, const Eigen::Vector3d& base_center, double radius,
                Material m = {}, std::string label = {});
  /// Capped cylinder of a radius from p0 to p1.
  void add_cylinder(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, double radius,
                    Material m = {}, std::string label = {});
  /// Arrow from `from` to `to`: a shaft of the given radius and a cone head (2.5× radius, ≤ 35% of
  /// length).
  void add_arrow(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double radius,
                 Material m = {}, std::string label = {});
  /// Box with half-extents along the columns of rotation.
  void add_box(const Eigen::Vector3d& center, const Eigen::Vector3d& half_extents,
               const Eigen::Matrix3d& rotation, Material m = {}, std::string label = {});
  /// Flat disk of a radius facing along normal.
  void add_disk(const Eigen::Vector3d& center, const Eigen::Vector3d& normal, double radius,
                Material m = {}, std::string label = {});
  /// Torus about the axis normal with major and minor (tube) radii.
  void add_torus(const Eigen::Vector3d& center, const Eigen::Vector3d& normal, double major_radius,
                 double minor_radius, Material m = {}, std::string label = {});
  /// Square plane of half-size facing along normal.
  void add_plane(const Eigen::Vector3d& center, const Eigen::Vector3d& normal, double half_size,
                 Material m = {}, std::string label = {});
  /// Tube of a radius along a polyline (e.g. a polhode on an ellipsoid).
  void add_tube(std::vector<Eigen::Vector3d> path, double radius, Material m = {},
                std::string label = {});
  /// Arbitrary mesh placed by a transform.
  void add_mesh(Mesh mesh, const Eigen::Affine3d& transform, Material m = {},
                std::string label = {});
  /// Thick screen-space polyline (width in reference pixels) that is hidden by nearer surfaces.
  void add_polyline(std::vector<Eigen::Vector3d> points, Color color, double width = 3.5,
                    std::string label = {});
  /// Axis triad at origin along the columns of rotation, arrows of a length, tips labelled (e.g.
  /// "1","2","3").
  void add_axes(const Eigen::Vector3d& origin, const Eigen::Matrix3d& rotation, double length,
                const std::array<std::string, 3>& labels = {"x", "y", "z"}, double radius = 0);
  /// Text anchored at a 3D point.
  void add_label(Label3D label);
  /// Convenience: text at a point, centred.
  void add_label(const Eigen::Vector3d& position, std::string text, Color color = kTextColor);

  /// Where the overlay and the scene go at a size: what layout() in draw.h returns. Only
  /// declared here, as the description never lays itself out; draw.h defines it.
  struct Layout;

  /// Adds every surface, line and label of `other` (its camera and title are not taken):
  /// the union of an animation's frames, to fit one camera to all of them.
  void merge(const Scene3D& other);

  /// The scene as a faint ghost to lay over another: every surface and line at `opacity`
  /// of its own, no labels, and one legend entry, `label`, for all of it.
  Scene3D faded(const std::string& label, float opacity = 0.3f) const;

  /// The labels of the legend's entries, in its order, each once: legend_from's, if set,
  /// then any of this scene's own it lacks.
  std::vector<std::string> legend_labels() const;
  /// What a legend needs of the scene and no more: each label's first part, its
  /// geometry (paths, points, meshes) dropped; for legend_from, where a film's frames
  /// share it and a copy a frame must stay cheap.
  Scene3D legend_only() const;
  /// The scene without the parts of the legend's entries in `hidden`: each surface or line
  /// labelled so, and the unlabelled ones added right after it (a polhode's other loops,
  /// the point an arrow ends on), up to the next labelled one; legend_from's too.
  Scene3D without(const std::vector<std::string>& hidden) const;

  /// What the scene holds; public so the renderer (and tests) can read it.
  enum class Shape { kSphere, kCone, kCylinder, kDisk, kBox, kTorus, kPlane, kTube, kCustom };
  struct Object {
    Shape shape = Shape::kSphere;
    Eigen::Affine3d transform = Eigen::Affine3d::Identity();
    Material material;
    std::string label;
    double torus_minor = 0.25;          ///< minor/major radius ratio for kTorus
    Mesh mesh;                          ///< kCustom only
    std::vector<Eigen::Vector3d> path;  ///< kTube only (world coordinates)
    double tube_radius = 0;             ///< kTube only
    bool marker = false;                ///< a point (add_marker): a dot in the legend
  };
  struct Polyline {
    std::vector<Eigen::Vector3d> points;
    Color color;
    double width;
    std::string label;
  };
  /// The surfaces added so far, in order.
  const std::vector<Object>& objects() const { return objects_; }
  /// The screen-space polylines added so far, in order.
  const std::vector<Polyline>& polylines() const { return polylines_; }
  /// The labels added so far (add_axes adds one per axis), in order.
  const std::vector<Label3D>& labels() const { return labels_; }
  /// The same scene with everything drawn in the colour of the item named `label` (a
  /// legend entry names all of it) in `color`: a legend's swatch must follow it (the
  /// legend test recolours each entry in turn).
  Scene3D recolored(const std::string& label, Color color) const;
  /// The same scene with every length (camera included) multiplied by k: drawing
  /// brings a scene of any size into float's comfortable range with it.
  Scene3D scaled(double k) const;

 private:
  Material resolve(Material m);
  std::vector<Object> objects_;
  std::vector<Polyline> polylines_;
  std::vector<Label3D> labels_;
  std::size_t auto_colors_ = 0;
};

}  // namespace rigid::render
