// Internal: batched triangles, thick lines, and text through a glyph atlas.
#include "painter.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <utility>

#include "font.h"
#include "target.h"

namespace rigid::render::detail {

namespace {

const char* kVertexSrc = R"(
in vec3 a_pos;
in vec4 a_color;
in vec3 a_uv;
uniform vec2 u_size;
out vec4 v_color;
out vec3 v_uv;
void main() {
  gl_Position = vec4(a_pos.x / u_size.x * 2.0 - 1.0, 1.0 - a_pos.y / u_size.y * 2.0, a_pos.z, 1.0);
  v_color = a_color;
  v_uv = a_uv;
}
)";

// Glyph coverage is lightly darkened (exponent 0.8) so thin strokes stay legible.
const char* kFragmentSrc = R"(
in vec4 v_color;
in vec3 v_uv;
uniform sampler2D u_atlas;
out vec4 frag;
void main() {
  float cov = v_uv.z > 0.5 ? pow(texture(u_atlas, v_uv.xy).r, 0.8) : 1.0;
  frag = vec4(v_color.rgb, v_color.a * cov);
}
)";

// Glyph atlas: one R8 texture, shelf-packed, kept for the process. 1024² holds
// several hundred glyphs, more than a figure's text at a few sizes; when it is
// full it starts afresh (see text()).
class Atlas {
 public:
  static constexpr int kSize = 1024;
  struct Entry {
    int x = 0, y = 0, w = 0, h = 0, left = 0, top = 0;
  };

  void init() {
    gl.GenTextures(1, &tex_);
    gl.BindTexture(GL_TEXTURE_2D, tex_);
    std::vector<std::uint8_t> zero(static_cast<std::size_t>(kSize) * kSize, 0);
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R8, kSize, kSize, 0, GL_RED, GL_UNSIGNED_BYTE, zero.data());
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  GLuint texture() const { return tex_; }

  // The atlas entry of a glyph at a size, rasterising it on first use; full -> nullptr.
  const Entry* get(std::uint32_t glyph, int size) {
    const auto key = std::make_pair(glyph, size);
    auto it = entries_.find(key);
    if (it != entries_.end()) return &it->second;
    const GlyphBitmap b = rasterize_glyph(glyph, size);
    Entry e;
    e.w = b.width;
    e.h = b.height;
    e.left = b.left;
    e.top = b.top;
    if (e.w > 0 && e.h > 0) {
      if (shelf_x_ + e.w + 1 > kSize) {
        shelf_x_ = 1;
        shelf_y_ += shelf_h_ + 1;
        shelf_h_ = 0;
      }
      if (shelf_y_ + e.h + 1 > kSize || e.w + 2 > kSize) return nullptr;
      e.x = shelf_x_;
      e.y = shelf_y_;
      shelf_x_ += e.w + 1;
      shelf_h_ = std::max(shelf_h_, e.h);
      gl.BindTexture(GL_TEXTURE_2D, tex_);
      gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
      gl.TexSubImage2D(GL_TEXTURE_2D, 0, e.x, e.y, e.w, e.h, GL_RED, GL_UNSIGNED_BYTE,
                       b.coverage.data());
    }
    return &entries_.emplace(key, e).first->second;
  }

  // Forgets every glyph (when full); the caller flushes pending text first.
  void reset() {
    entries_.clear();
    shelf_x_ = shelf_y_ = 1;
    shelf_h_ = 0;
  }

 private:
  GLuint tex_ = 0;
  std::map<std::pair<std::uint32_t, int>, Entry> entries_;
  int shelf_x_ = 1, shelf_y_ = 1, shelf_h_ = 0;
};

struct Resources {
  GLuint program = 0, vao = 0, vbo = 0;
  GLint u_size = -1, u_atlas = -1;
  Atlas atlas;
};

Resources& resources() {
  static Resources* r = [] {
    auto* res = new Resources;
    const char* attrs[] = {"a_pos", "a_color", "a_uv"};
    res->program = build_program(kVertexSrc, kFragmentSrc, attrs, 3);
    res->u_size = gl.GetUniformLocation(res->program, "u_size");
    res->u_atlas = gl.GetUniformLocation(res->program, "u_atlas");
    gl.GenVertexArrays(1, &res->vao);
    gl.GenBuffers(1, &res->vbo);
    res->atlas.init();
    return res;
  }();
  return *r;
}

}  // namespace

Painter& painter() {
  static Painter p;
  return p;
}

void Painter::begin(int width, int height) {
  resources();
  width_ = width;
  height_ = height;
  verts_.clear();
  batches_.clear();
  state_ = Batch{};
}

void Painter::new_batch() {
  if (!batches_.empty() && batches_.back().count == 0) batches_.pop_back();
  Batch b = state_;
  b.first = verts_.size();
  b.count = 0;
  batches_.push_back(b);
}

void Painter::clip(double x0, double y0, double x1, double y1) {
  // Scissor is in physical pixels, y up.
  const int s = target().scale();
  state_.clip = true;
  state_.sx = static_cast<int>(std::floor(x0)) * s;
  state_.sy = (height_ - static_cast<int>(std::ceil(y1))) * s;
  state_.sw = (static_cast<int>(std::ceil(x1)) - static_cast<int>(std::floor(x0))) * s;
  state_.sh = (static_cast<int>(std::ceil(y1)) - static_cast<int>(std::floor(y0))) * s;
  new_batch();
}

void Painter::no_clip() {
  state_.clip = false;
  new_batch();
}

void Painter::depth_test(bool on) {
  state_.depth = on;
  new_batch();
}

void Painter::push(const P3& p, Color c, float u, float v, float t) {
  if (batches_.empty()) new_batch();
  verts_.push_back({static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()),
                    c.r, c.g, c.b, c.a, u, v, t});
  ++batches_.back().count;
}

void Painter::triangle(const P3& a, const P3& b, const P3& c, Color color) {
  push(a, color);
  push(b, color);
  push(c, color);
}

void Painter::rect(double x0, double y0, double x1, double y1, Color color) {
  triangle({x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, color);
  triangle({x0, y0, 0}, {x1, y1, 0}, {x0, y1, 0}, color);
}

void Painter::rect_outline(double x0, double y0, double x1, double y1, double w, Color color) {
  rect(x0, y0, x1, y0 + w, color);
  rect(x0, y1 - w, x1, y1, color);
  rect(x0, y0 + w, x0 + w, y1 - w, color);
  rect(x1 - w, y0 + w, x1, y1 - w, color);
}

void Painter::convex(const std::vector<P3>& pts, Color color) {
  for (std::size_t i = 1; i + 1 < pts.size(); ++i) triangle(pts[0], pts[i], pts[i + 1], color);
}

void Painter::disc(const P3& c, double radius, Color color) {
  // About 2 px per edge keeps discs round after MSAA.
  const int n = std::clamp(static_cast<int>(2 * EIGEN_PI * radius / 2.0), 12, 96);
  P3 prev = c + P3(radius, 0, 0);
  for (int i = 1; i <= n; ++i) {
    const double a = 2 * EIGEN_PI * i / n;
    const P3 p = c + P3(radius * std::cos(a), radius * std::sin(a), 0);
    triangle(c, prev, p, color);
    prev = p;
  }
}

// A solid thick line through pts: per-segment quads joined by miters, or by
// round fans where the turn is sharp (miter longer than 2 half-widths).
void Painter::solid_strip(const std::vector<P3>& pts, double hw, Color color, bool round_caps) {
  // Drop repeated points; they have no direction.
  std::vector<P3> p;
  p.reserve(pts.size());
  for (const P3& q : pts)
    if (p.empty() || (q.head<2>() - p.back().head<2>()).norm() > 1e-6) p.push_back(q);
  if (p.size() < 2) {
    if (round_caps && !p.empty()) disc(p[0], hw, color);
    return;
  }
  const std::size_t n = p.size();
  auto normal = [&](std::size_t i) {  // left normal of segment i -> i+1
    Eigen::Vector2d d = (p[i + 1].head<2>() - p[i].head<2>()).normalized();
    return Eigen::Vector2d(-d.y(), d.x());
  };
  auto off = [](const P3& q, const Eigen::Vector2d& o) {
    return P3(q.x() + o.x(), q.y() + o.y(), q.z());
  };
  // Offsets at the start of the current segment.
  Eigen::Vector2d n0 = normal(0);
  P3 l = off(p[0], n0 * hw), r = off(p[0], -n0 * hw);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const Eigen::Vector2d ni = normal(i);
    P3 l_end, r_end, l_next = P3::Zero(), r_next = P3::Zero();
    bool round_join = false;
    if (i + 2 < n) {
      const Eigen::Vector2d nn = normal(i + 1);
      Eigen::Vector2d m = ni + nn;
      const double c = m.norm() > 1e-9 ? (m.normalized()).dot(ni) : 0.0;
      if (c > 0.5) {
        m = m.normalized() * (hw / c);
        l_end = l_next = off(p[i + 1], m);
        r_end = r_next = off(p[i + 1], -m);
      } else {
        round_join = true;
        l_end = off(p[i + 1], ni * hw);
        r_end = off(p[i + 1], -ni * hw);
        l_next = off(p[i + 1], nn * hw);
        r_next = off(p[i + 1], -nn * hw);
      }
    } else {
      l_end = off(p[i + 1], ni * hw);
      r_end = off(p[i + 1], -ni * hw);
    }
    triangle(l, r, r_end, color);
    triangle(l, r_end, l_end, color);
    if (round_join) disc(p[i + 1], hw, color);
    l = l_next;
    r = r_next;
  }
  if (round_caps) {
    disc(p.front(), hw, color);
    disc(p.back(), hw, color);
  }
}

void Painter::polyline(const std::vector<P3>& pts, double width, Color color,
                       const DashPattern& dash, bool round_caps) {
  const double hw = 0.5 * width;
  if (dash.empty()) {
    solid_strip(pts, hw, color, round_caps);
    return;
  }
  // Cut the path into dashes by 2D arc length; the pattern runs on across vertices.
  std::size_t k = 0;
  double left = dash[0];
  bool on = true;
  std::vector<P3> piece;
  if (pts.empty()) return;
  piece.push_back(pts[0]);
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    P3 a = pts[i];
    const P3 b = pts[i + 1];
    double seg = (b.head<2>() - a.head<2>()).norm();
    while (seg > left) {
      const P3 cut = a + (b - a) * (left / seg);
      if (on) {
        piece.push_back(cut);
        solid_strip(piece, hw, color, round_caps);
      }
      piece.assign(1, cut);
      seg -= left;
      a = cut;
      on = !on;
      k = (k + 1) % dash.size();
      left = dash[k];
    }
    left -= seg;
    if (on)
      piece.push_back(b);
    else
      piece.assign(1, b);
  }
  if (on) solid_strip(piece, hw, color, round_caps);
}

TextExtent Painter::text(std::string_view markup, double x, double y, double size, Color color,
                         HAlign h, VAlign v, bool vertical, double depth) {
  const TextLayout lay = layout_text(markup, size);
  const TextExtent& e = lay.extent;
  // Whole-pixel origin keeps glyph texels aligned with pixels (crisp text).
  const Eigen::Vector2d origin = text_origin(e, x, y, h, v, vertical);
  const double ox = origin.x(), oy = origin.y();
  Resources& res = resources();
  for (const PlacedGlyph& g : lay.glyphs) {
    const Atlas::Entry* a = res.atlas.get(g.glyph, g.size_px);
    if (a == nullptr) {
      // Atlas full: draw what is queued, then start a fresh atlas.
      flush();
      res.atlas.reset();
      a = res.atlas.get(g.glyph, g.size_px);
      if (a == nullptr) continue;
    }
    if (a->w == 0) continue;
    const double gx = std::round(g.x) + a->left;  // ink left, along the baseline
    const double gy = std::round(g.y) + a->top;   // ink top, above the baseline
    const double w = a->w, hgt = a->h;
    const float s = 1.0f / Atlas::kSize;
    const float u0 = a->x * s, v0 = a->y * s, u1 = (a->x + a->w) * s, v1 = (a->y + a->h) * s;
    // Corners: top-left, top-right, bottom-right, bottom-left of the glyph bitmap.
    P3 c00, c10, c11, c01;
    if (!vertical) {
      c00 = {ox + gx, oy - gy, depth};
      c10 = {ox + gx + w, oy - gy, depth};
      c11 = {ox + gx + w, oy - gy + hgt, depth};
      c01 = {ox + gx, oy - gy + hgt, depth};
    } else {
      c00 = {ox - gy, oy - gx, depth};
      c10 = {ox - gy, oy - gx - w, depth};
      c11 = {ox - gy + hgt, oy - gx - w, depth};
      c01 = {ox - gy + hgt, oy - gx, depth};
    }
    push(c00, color, u0, v0, 1);
    push(c10, color, u1, v0, 1);
    push(c11, color, u1, v1, 1);
    push(c00, color, u0, v0, 1);
    push(c11, color, u1, v1, 1);
    push(c01, color, u0, v1, 1);
  }
  return e;
}

void Painter::flush() {
  if (verts_.empty()) return;
  Resources& res = resources();
  gl.UseProgram(res.program);
  gl.Uniform2f(res.u_size, static_cast<float>(width_), static_cast<float>(height_));
  gl.Uniform1i(res.u_atlas, 0);
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_2D, res.atlas.texture());
  gl.BindVertexArray(res.vao);
  gl.BindBuffer(GL_ARRAY_BUFFER, res.vbo);
  gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(verts_.size() * sizeof(Vertex)),
                verts_.data(), GL_STREAM_DRAW);
  const GLsizei stride = sizeof(Vertex);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(0));
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride,
                         reinterpret_cast<const void*>(offsetof(Vertex, r)));
  gl.EnableVertexAttribArray(2);
  gl.VertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride,
                         reinterpret_cast<const void*>(offsetof(Vertex, u)));
  gl.Enable(GL_BLEND);
  gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl.Disable(GL_CULL_FACE);
  gl.DepthMask(GL_FALSE);
  for (const Batch& b : batches_) {
    if (b.count == 0) continue;
    if (b.clip) {
      gl.Enable(GL_SCISSOR_TEST);
      gl.Scissor(b.sx, b.sy, b.sw, b.sh);
    } else {
      gl.Disable(GL_SCISSOR_TEST);
    }
    // Lines in a scene are opaque: they write depth, so a translucent surface drawn after
    // them covers only those behind it (a curve on a plane stays in front of the plane).
    if (b.depth) {
      gl.Enable(GL_DEPTH_TEST);
      gl.DepthFunc(GL_LEQUAL);
      gl.DepthMask(GL_TRUE);
    } else {
      gl.Disable(GL_DEPTH_TEST);
      gl.DepthMask(GL_FALSE);
    }
    gl.DrawArrays(GL_TRIANGLES, static_cast<GLint>(b.first), static_cast<GLsizei>(b.count));
  }
  gl.Disable(GL_SCISSOR_TEST);
  gl.Disable(GL_DEPTH_TEST);
  gl.DepthMask(GL_TRUE);
  verts_.clear();
  batches_.clear();
}

}  // namespace rigid::render::detail
