// Text: the markup parser and layout, on the font face (font_face.h).

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "font_face.h"

namespace rigid::render {

namespace {

// Scripts are 70% of their parent; subscripts drop 0.2 em, superscripts rise 0.38 em.
constexpr double kScriptScale = 0.7;
constexpr double kSubShift = 0.20;
constexpr double kSupShift = 0.38;
constexpr char32_t kCombiningDot = 0x0307;
constexpr char32_t kDotAbove = 0x02D9;

using GlyphInfo = detail::GlyphMetrics;

// The face (font_face.h), its glyphs' metrics kept by character, and a mutex.
class Font {
 public:
  std::mutex mutex;

  const GlyphInfo& info(char32_t cp) {
    auto it = glyphs_.find(cp);
    if (it != glyphs_.end()) return it->second;
    return glyphs_.emplace(cp, face_.metrics(cp)).first->second;
  }
  long kerning(std::uint32_t left, std::uint32_t right) { return face_.kerning(left, right); }
  double units() const { return face_.units_per_em(); }
  double ascender() const { return face_.ascender(); }
  double descender() const { return face_.descender(); }
  detail::GlyphBitmap rasterize(std::uint32_t glyph, int size_px) {
    return face_.rasterize(glyph, size_px);
  }

 private:
  detail::FontFace face_;
  std::unordered_map<char32_t, GlyphInfo> glyphs_;
};

Font& font() {
  static Font f;
  return f;
}

// One character of parsed markup with its script level and decorations.
struct Item {
  char32_t cp = 0;
  int level = 0;     // 0 normal, >0 superscript depth, <0 subscript depth
  double shift = 0;  // baseline shift in em of the base size
  double scale = 1;  // size relative to the base size
  bool dot = false;  // dot above
};

const std::map<std::string, char32_t, std::less<>>& commands() {
  static const std::map<std::string, char32_t, std::less<>> m = {
      {"alpha", U'α'},    {"beta", U'β'},      {"gamma", U'γ'},   {"delta", U'δ'},
      {"epsilon", U'ε'},  {"zeta", U'ζ'},      {"eta", U'η'},     {"theta", U'θ'},
      {"vartheta", U'ϑ'}, {"iota", U'ι'},      {"kappa", U'κ'},   {"lambda", U'λ'},
      {"mu", U'μ'},       {"nu", U'ν'},        {"xi", U'ξ'},      {"pi", U'π'},
      {"rho", U'ρ'},      {"sigma", U'σ'},     {"tau", U'τ'},     {"upsilon", U'υ'},
      {"phi", U'φ'},      {"varphi", U'ϕ'},    {"chi", U'χ'},     {"psi", U'ψ'},
      {"omega", U'ω'},    {"Gamma", U'Γ'},     {"Delta", U'Δ'},   {"Theta", U'Θ'},
      {"Lambda", U'Λ'},   {"Xi", U'Ξ'},        {"Pi", U'Π'},      {"Sigma", U'Σ'},
      {"Upsilon", U'Υ'},  {"Phi", U'Φ'},       {"Psi", U'Ψ'},     {"Omega", U'Ω'},
      {"deg", U'°'},      {"cdot", U'·'},      {"times", U'×'},   {"pm", U'±'},
      {"approx", U'≈'},   {"le", U'≤'},        {"ge", U'≥'},      {"to", U'→'},
      {"infty", U'∞'},    {"perp", U'⊥'},      {"partial", U'∂'}, {"minus", U'−'},
      {"prime", U'′'},    {"ldots", U'…'},     {"sqrt", U'√'},    {"parallel", U'∥'},
      {"propto", U'∝'},   {"neq", U'≠'},       {"equiv", U'≡'},   {"hbar", U'ħ'},
      {",", U'\u2009'},   {"quad", U'\u2003'}, {"\\", U'\\'},     {"_", U'_'},
      {"^", U'^'},        {"{", U'{'},         {"}", U'}'},       {" ", U' '}};
  return m;
}

// Decodes one UTF-8 code point at s[i], advancing i; invalid bytes become U+FFFD.
char32_t next_utf8(std::string_view s, std::size_t& i) {
  const auto c = static_cast<unsigned char>(s[i++]);
  if (c < 0x80) return c;
  int extra = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : -1;
  if (extra < 0) return 0xFFFD;
  char32_t cp = c & (0x3F >> extra);
  for (int k = 0; k < extra; ++k) {
    if (i >= s.size() || (static_cast<unsigned char>(s[i]) & 0xC0) != 0x80) return 0xFFFD;
    cp = (cp << 6) | (static_cast<unsigned char>(s[i++]) & 0x3F);
  }
  return cp;
}

// Recursive-descent parser of the markup in text.h.
class Parser {
 public:
  explicit Parser(std::string_view s) : s_(s) {}

  std::vector<Item> parse() {
    std::vector<Item> out;
    sequence(out, 0, 0.0, 1.0, false);
    return out;
  }

 private:
  // Parses items until end (or a closing brace when in_group).
  void sequence(std::vector<Item>& out, int level, double shift, double scale, bool in_group) {
    while (pos_ < s_.size()) {
      if (s_[pos_] == '}') {
        ++pos_;
        if (in_group) return;
        continue;
      }
      atom(out, level, shift, scale);
    }
  }

  // One unit: a character, a command, a {group}, or a script applied to the previous unit.
  void atom(std::vector<Item>& out, int level, double shift, double scale) {
    const char c = s_[pos_];
    if (c == '{') {
      ++pos_;
      sequence(out, level, shift, scale, true);
      return;
    }
    if (c == '_' || c == '^') {
      ++pos_;
      const bool sub = c == '_';
      const double child_shift = shift + (sub ? -kSubShift : kSupShift) * scale;
      if (pos_ < s_.size()) atom(out, level + (sub ? -1 : 1), child_shift, scale * kScriptScale);
      return;
    }
    if (c == '\\') {
      ++pos_;
      std::size_t start = pos_;
      while (pos_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[pos_]))) ++pos_;
      if (pos_ == start && pos_ < s_.size()) ++pos_;  // one-symbol command like \, or \_
      const std::string_view name = s_.substr(start, pos_ - start);
      if (name == "dot") {
        // \dot{x} or \dot x: a dot over the last glyph of the argument.
        while (pos_ < s_.size() && s_[pos_] == ' ') ++pos_;
        const std::size_t before = out.size();
        if (pos_ < s_.size()) atom(out, level, shift, scale);
        if (out.size() > before) out.back().dot = true;
        return;
      }
      auto it = commands().find(name);
      if (it != commands().end()) {
        // Unlike TeX, a following space is kept: "\\omega (rad/s)" reads "ω (rad/s)".
        push(out, it->second, level, shift, scale);
      } else {
        push(out, '\\', level, shift, scale);
        for (char ch : name) push(out, static_cast<unsigned char>(ch), level, shift, scale);
      }
      return;
    }
    char32_t cp = next_utf8(s_, pos_);
    if (cp == kCombiningDot) {
      if (!out.empty()) out.back().dot = true;
      return;
    }
    // Inside scripts a hyphen is a minus sign (10^{-6}).
    if (cp == '-' && level != 0) cp = U'−';
    push(out, cp, level, shift, scale);
  }

  static void push(std::vector<Item>& out, char32_t cp, int level, double shift, double scale) {
    out.push_back({cp, level, shift, scale, false});
  }

  std::string_view s_;
  std::size_t pos_ = 0;
};

}  // namespace

namespace detail {

void append_utf8(std::string& out, char32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

TextLayout layout_text(std::string_view markup, double size_px) {
  const std::vector<Item> items = Parser(markup).parse();
  Font& f = font();
  std::lock_guard<std::mutex> lock(f.mutex);
  const int base = std::max(1, static_cast<int>(std::lround(size_px)));
  const double em = base;
  TextLayout out;
  double asc = f.ascender() / f.units() * em;
  double desc = f.descender() / f.units() * em;
  double pen = 0;
  std::uint32_t prev = 0;
  int prev_level = 0;
  for (const Item& it : items) {
    const GlyphInfo& g = f.info(it.cp);
    const int size = std::max(1, static_cast<int>(std::lround(base * it.scale)));
    const double px_per_unit = size / f.units();
    if (prev != 0 && prev_level == it.level) pen += f.kerning(prev, g.index) * px_per_unit;
    const double y = it.shift * em;
    out.glyphs.push_back({g.index, it.cp, size, pen, y});
    if (it.level != 0) {
      // Scripts may reach above the ascender or below the descender.
      asc = std::max(asc, y + f.ascender() / f.units() * size);
      desc = std::max(desc, -y + f.descender() / f.units() * size);
    }
    if (it.dot) {
      // Centre the dot's ink over the glyph's ink, a small gap above its top.
      const GlyphInfo& d = f.info(kDotAbove);
      const double cx = pen + 0.5 * (g.ink_x0 + g.ink_x1) * px_per_unit;
      const double dx = cx - 0.5 * (d.ink_x0 + d.ink_x1) * px_per_unit;
      const double top = y + g.ink_y1 * px_per_unit + 0.06 * size;
      const double dy = top - d.ink_y0 * px_per_unit;
      out.glyphs.push_back({d.index, kDotAbove, size, dx, dy});
      asc = std::max(asc, dy + d.ink_y1 * px_per_unit);
    }
    pen += g.advance * px_per_unit;
    prev = g.index;
    prev_level = it.level;
  }
  out.extent = {pen, asc, desc};
  return out;
}

GlyphBitmap rasterize_glyph(std::uint32_t glyph, int size_px) {
  Font& f = font();
  std::lock_guard<std::mutex> lock(f.mutex);
  return f.rasterize(glyph, size_px);
}

}  // namespace detail

TextExtent measure_text(std::string_view markup, double size_px) {
  return detail::layout_text(markup, size_px).extent;
}

std::string plain_text(std::string_view markup) {
  std::string out;
  for (const Item& it : Parser(markup).parse()) {
    char32_t cp = it.cp;
    // Digits and signs in scripts have Unicode sub/superscript forms; others keep _ or ^.
    static const char32_t kSup[] = {U'⁰', U'¹', U'²', U'³', U'⁴', U'⁵', U'⁶', U'⁷', U'⁸', U'⁹'};
    if (it.level < 0 && cp >= '0' && cp <= '9') {
      cp = U'₀' + (cp - '0');
    } else if (it.level > 0 && cp >= '0' && cp <= '9') {
      cp = kSup[cp - '0'];
    } else if (it.level > 0 && cp == U'−') {
      cp = U'⁻';
    } else if (it.level != 0) {
      out += it.level < 0 ? '_' : '^';
    }
    detail::append_utf8(out, cp);
    if (it.dot) detail::append_utf8(out, kCombiningDot);
  }
  return out;
}

}  // namespace rigid::render
