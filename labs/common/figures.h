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
