// The figure layer of the labs: a lab's figures.cpp builds each figure as a
// render description (a Plot2D or a Scene3D) and hands it to the set with a
// name and a caption. The set owns everything else: whether this build can draw
// at all, the GL context, the title (the lab's name and its inputs, then the
// figure's own title), the size asked for with --figure-size, atomic saving as
// <lab>_<name>.png in the --figures directory, the timing, and the listing in
// the JSON "figures" and "captions". Figure code never sees a path, a context
// or a pixel offset.
#pragma once

#include <string>

#include "common/lab.h"
#include "rigid/render/plot2d.h"
#include "rigid/render/scene3d.h"

namespace rigid::lab {

/// One colour per concept across every lab's figure (issue 14): what a reader learns
/// in one figure holds in the next. Okabe-Ito, so colour-blind readers keep it too.
namespace colors {
inline constexpr render::Color kOmega = render::kBlue;    ///< omega, and its path
inline constexpr render::Color kL = render::kVermillion;  ///< L, and what is about L
/// Principal axes 1, 2, 3 (ascending moments, or the body's own numbering).
inline constexpr render::Color kPrincipal[3] = {render::kBluishGreen, render::kOrange,
                                                render::kReddishPurple};
/// A symmetric body's symmetry axis: its principal axis 3.
inline constexpr render::Color kSymmetryAxis = render::kReddishPurple;
inline constexpr render::Color kPolhode = kOmega;  ///< the body's polhode: omega's path
inline constexpr render::Color kSeparatrix = render::kBlack;
inline constexpr render::Color kTorque = render::kYellow;   ///< a torque (apart from the grey axes)
inline constexpr render::Color kFixedAxis = render::kGray;  ///< an axle, a fixed axis, the vertical
inline constexpr render::Color kBody = render::kSkyBlue;    ///< a body's surface, translucent
inline constexpr render::Color kMarker = render::kBlack;    ///< a start, a chosen instant
}  // namespace colors

/// A thin translucent body (a plate, a disk) drawn in its flat colour, unshaded, so
/// that it shows its legend swatch's colour from whichever side it is seen.
inline render::Material flat_body(render::Color color, float opacity) {
  render::Material m;
  m.color = color;
  m.opacity = opacity;
  m.specular = 0.0f;
  m.lit = false;
  return m;
}

class FigureSet {
 public:
  /// A 2D plot; its title, if any, follows the lab's name and inputs after a colon.
  void add(const std::string& name, const std::string& caption, render::Plot2D plot);
  /// A 3D scene; titled likewise.
  void add(const std::string& name, const std::string& caption, render::Scene3D scene);

 private:
  friend class Lab;
  explicit FigureSet(Lab& lab) : lab_(lab) {}
  std::string title(const std::string& own) const;
  template <class Figure>
  void save(const std::string& name, const std::string& caption, const Figure& figure);
  Lab& lab_;
};

}  // namespace rigid::lab
