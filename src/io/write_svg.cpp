// io/write_svg.cpp: SVG pictures of a 2D triangulation and its Voronoi diagram.
//
// The picture is meant for checking a result by eye, so the choices follow from that:
//   - equal scales on both axes and y up, so that the picture is the plane as a mathematician
//     draws it and each Voronoi edge visibly crosses its Delaunay edge at a right angle;
//   - every edge drawn once; the hull in a thicker stroke, so that a missing hull triangle or
//     a hole shows;
//   - everything clipped to the view (the points' bounding box plus a margin) by this file,
//     not by the renderer: a Voronoi vertex of a sliver can lie 1e12 units away, and renderers
//     work in limited fixed-point ranges (cairo: about +-8 million pixels);
//   - one <path> per layer, coordinates to 0.01 px, no per-element styling, so that 100 000
//     points give a few megabytes.
//
// An unbounded Voronoi edge, the ridge of points p and q with a finite end v only, lies on
// the bisector of p and q, and starts at v, the circumcentre of the one triangle pqr having
// pq as an edge (pq is a hull edge). Beyond v it runs to infinity on the side of the hull
// line pq away from the hull, where p and q are nearer than any other input point (all of
// them lie on the hull's side). So the ray leaves v along the outward normal of pq, whether v
// itself lies inside the hull or (r an obtuse corner) outside it. The triangles are positively
// oriented (counter-clockwise), so the hull lies to the left of the hull edge as the triangle
// runs along it, from `from` to `to`, and the outward normal is its right-hand normal
// (dy, -dx): decided by the combinatorics, without a sign test on rounded coordinates.
// A ridge with two infinite ends exists only for collinear points, which have no 2D
// triangulation, so it is not drawn.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "drange/errors.hpp"
#include "drange/svg.hpp"
#include "voronoi/circumcentre.hpp"

namespace drange {
namespace {

// The height of the band below the drawing that holds the legend, in pixels.
constexpr double kLegendPx = 30;
// Neither side of the view is allowed to exceed this many times the other: a nearly collinear
// point set would otherwise give a picture of 800 x 80 000 pixels.
constexpr double kMaxAspect = 4;
// Circles larger than this (in pixels) are left out: they belong to slivers along the hull,
// look like straight lines across the picture, and their coordinates would leave the
// renderers' fixed-point range.
constexpr double kMaxCirclePx = 1e6;

// Colours that stay apart for the common colour blindnesses: blues for the triangulation,
// orange for Voronoi, teal for circles, near-black dots.
constexpr const char* kDelaunayColour = "#4f7cac";
constexpr const char* kHullColour = "#1d3557";
constexpr const char* kVoronoiColour = "#e8590c";
constexpr const char* kCircleColour = "#2a9d8f";
constexpr const char* kCircleOpacity = " stroke-opacity=\"0.45\"";
constexpr const char* kPointColour = "#111";
constexpr const char* kLabelColour = "#333";

struct Xy {
  double x, y;
};

// The viewed rectangle of the plane and its mapping to the picture: x to the right, y up,
// `scale` pixels per unit on both axes.
struct View {
  double x0, y0, x1, y1;
  double scale;
  double width() const { return (x1 - x0) * scale; }
  double height() const { return (y1 - y0) * scale; }
  Xy pixel(Xy p) const { return {(p.x - x0) * scale, (y1 - p.y) * scale}; }
};

Xy point_of(PointsView points, std::size_t i) { return {points.point(i)[0], points.point(i)[1]}; }

// Widens [lo, hi] symmetrically to at least `span`.
void widen_to(double& lo, double& hi, double span) {
  if (hi - lo >= span) return;
  const double extra = (span - (hi - lo)) / 2;
  lo -= extra;
  hi += extra;
}

View make_view(PointsView points, const SvgOptions& options) {
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
  if (points.n > 0) {
    x0 = x1 = points.point(0)[0];
    y0 = y1 = points.point(0)[1];
    for (std::size_t i = 1; i < points.n; ++i) {
      const Xy p = point_of(points, i);
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
      y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
  }
  double side = std::max(x1 - x0, y1 - y0);
  if (!(side > 0)) side = 1;  // one point (or copies of it): a unit square around it
  const double margin = options.margin * side;
  x0 -= margin, x1 += margin, y0 -= margin, y1 += margin;
  side += 2 * margin;
  widen_to(x0, x1, side / kMaxAspect);
  widen_to(y0, y1, side / kMaxAspect);
  return View{x0, y0, x1, y1, options.width_px / (x1 - x0)};
}

// Liang-Barsky: narrows [t0, t1] to the part of the line a + t*d inside the view's rectangle.
// Returns false when nothing is left; t1 may start at +infinity (a ray).
bool clip_to_view(const View& view, Xy a, Xy d, double& t0, double& t1) {
  if (!(std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(d.x) && std::isfinite(d.y))) return false;
  // Each pair: the line's speed towards the outside of one side, and the room left on that side.
  const double speed[4] = {-d.x, d.x, -d.y, d.y};
  const double room[4] = {a.x - view.x0, view.x1 - a.x, a.y - view.y0, view.y1 - a.y};
  for (int k = 0; k < 4; ++k) {
    if (speed[k] == 0) {
      if (room[k] < 0) return false;  // parallel to this side and outside it
      continue;
    }
    const double t = room[k] / speed[k];
    if (speed[k] < 0) t0 = std::max(t0, t);  // entering through this side
    else t1 = std::min(t1, t);               // leaving through it
  }
  return t0 <= t1 && std::isfinite(t1);
}

// Appends `hundredths` / 100 without trailing zeros: 1250 -> "12.5", -7 -> "-0.07".
void append_hundredths(std::string& text, std::int64_t hundredths) {
  if (hundredths < 0) {
    text += '-';
    hundredths = -hundredths;
  }
  char digits[24];
  text.append(digits, std::to_chars(digits, digits + sizeof digits, hundredths / 100).ptr);
  const auto fraction = static_cast<int>(hundredths % 100);
  if (fraction == 0) return;
  text += '.';
  text += static_cast<char>('0' + fraction / 10);
  if (fraction % 10 != 0) text += static_cast<char>('0' + fraction % 10);
}

std::int64_t to_hundredths(double px) { return std::llround(px * 100); }

// The `d` attribute of a path, built as text. Coordinates are rounded to whole hundredths of
// a pixel first, so that a segment starting exactly where the previous one ended (the pen)
// is recognised and continues it with a relative "l dx dy" alone, without a new "M x y":
// with the edges ordered into trails (see into_trails) that halves the file, and keeps
// 100 000 points under librsvg's 10 MB limit. Differences of rounded values are exact, so
// relative steps do not drift.
class PathData {
 public:
  void segment(Xy a, Xy b) {
    const Pixel from = round(a), to = round(b);
    if (!at_pen(from)) move(from);
    text_ += 'l';
    pair(to.x - from.x, to.y - from.y);
    pen_ = to;
    ++count_;
  }
  // A full circle as two half arcs (SVG paths have no circle command).
  void circle(Xy centre, double r) {
    const std::int64_t radius = to_hundredths(r);
    move(round({centre.x - r, centre.y}));
    for (const std::int64_t sweep : {2 * radius, -2 * radius}) {
      text_ += 'a';
      pair(radius, radius);
      text_ += " 0 1 0 ";
      pair(sweep, 0);
    }
    ++count_;
  }
  // A dot: a zero-length stroke, made round by the path's round line caps.
  void dot(Xy p) {
    move(round(p));
    text_ += "h0";
    ++count_;
  }
  bool empty() const { return count_ == 0; }
  const std::string& text() const { return text_; }

 private:
  struct Pixel {
    std::int64_t x, y;  // hundredths of a pixel
  };
  static Pixel round(Xy p) { return {to_hundredths(p.x), to_hundredths(p.y)}; }
  bool at_pen(Pixel p) const { return has_pen_ && p.x == pen_.x && p.y == pen_.y; }
  void move(Pixel p) {
    text_ += 'M';
    pair(p.x, p.y);
    pen_ = p;
    has_pen_ = true;
  }
  // Two numbers; a minus sign separates them by itself.
  void pair(std::int64_t x, std::int64_t y) {
    append_hundredths(text_, x);
    if (y >= 0) text_ += ' ';
    append_hundredths(text_, y);
  }

  std::string text_;
  std::size_t count_ = 0;
  Pixel pen_{0, 0};
  bool has_pen_ = false;
};

// The part of the segment (t1 = 1) or ray (t1 = infinity) a + t*d inside the view, in pixels.
void add_clipped(PathData& path, const View& view, Xy a, Xy d, double t1) {
  double t0 = 0;
  if (!clip_to_view(view, a, d, t0, t1)) return;
  path.segment(view.pixel({a.x + t0 * d.x, a.y + t0 * d.y}), view.pixel({a.x + t1 * d.x, a.y + t1 * d.y}));
}

using Link = std::pair<std::int32_t, std::int32_t>;  // an edge between two vertex ids

// Orders and directs the edges (vertex ids below `vertices`) into trails, greedily: from each
// vertex in turn, walk along unused edges until stuck. Consecutive edges of a trail share a
// vertex, so the path draws them without a move. A trail can only get stuck at a vertex of
// odd degree or at its start, so there are about as many trails as odd vertices.
std::vector<Link> into_trails(const std::vector<Link>& edges, std::size_t vertices) {
  // The edges at each vertex, in compressed rows: first[v] .. first[v + 1] in `at`.
  std::vector<std::size_t> first(vertices + 1, 0);
  for (const Link& e : edges) ++first[static_cast<std::size_t>(e.first) + 1], ++first[static_cast<std::size_t>(e.second) + 1];
  for (std::size_t v = 0; v < vertices; ++v) first[v + 1] += first[v];
  std::vector<std::size_t> at(2 * edges.size());
  std::vector<std::size_t> fill(first.begin(), first.end() - 1);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    at[fill[static_cast<std::size_t>(edges[i].first)]++] = i;
    at[fill[static_cast<std::size_t>(edges[i].second)]++] = i;
  }
  std::vector<bool> used(edges.size(), false);
  std::vector<std::size_t>& next = fill;  // per vertex, the first of its edges that may be unused
  std::copy(first.begin(), first.end() - 1, next.begin());
  const auto unused_edge = [&](std::size_t v) -> std::size_t {
    while (next[v] < first[v + 1] && used[at[next[v]]]) ++next[v];
    return next[v] < first[v + 1] ? at[next[v]] : edges.size();
  };

  std::vector<Link> trails;
  trails.reserve(edges.size());
  for (std::size_t start = 0; start < vertices; ++start) {
    while (unused_edge(start) < edges.size()) {
      for (std::size_t v = start, e; (e = unused_edge(v)) < edges.size();) {
        used[e] = true;
        const auto from = static_cast<std::int32_t>(v);
        const std::int32_t to = edges[e].first == from ? edges[e].second : edges[e].first;
        trails.emplace_back(from, to);
        v = static_cast<std::size_t>(to);
      }
    }
  }
  return trails;
}

// Every edge of the triangulation once, directed as the (counter-clockwise) triangle runs
// along it; an edge of one triangle only is a hull edge, with the hull on its left.
struct Edge {
  std::uint64_t key;  // (min << 32) | max of the two point ids
  std::int32_t from, to;
  bool operator<(const Edge& other) const { return key < other.key; }
};

std::uint64_t edge_key(std::int32_t a, std::int32_t b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b)), hi = static_cast<std::uint32_t>(std::max(a, b));
  return (std::uint64_t{lo} << 32) | hi;
}

struct EdgeSets {
  std::vector<Edge> interior;
  std::vector<Edge> hull;  // sorted by key, for the rays' look-up
};

EdgeSets triangulation_edges(const Triangulation& t) {
  std::vector<Edge> all;
  all.reserve(t.simplices.size());
  for (std::size_t s = 0; s < t.size(); ++s) {
    const std::int32_t* v = t.simplex(s);
    for (int k = 0; k < 3; ++k) all.push_back({edge_key(v[k], v[(k + 1) % 3]), v[k], v[(k + 1) % 3]});
  }
  std::sort(all.begin(), all.end());
  EdgeSets edges;
  for (std::size_t i = 0; i < all.size();) {
    std::size_t j = i + 1;
    while (j < all.size() && all[j].key == all[i].key) ++j;
    (j - i == 1 ? edges.hull : edges.interior).push_back(all[i]);
    i = j;
  }
  return edges;
}

// Line widths, dot and dash sizes follow the mean spacing of the points in pixels, so that
// 100 points get bold strokes and 100 000 points hairlines instead of a solid blot.
struct Style {
  double dot, edge, hull, voronoi, dash, circle;
};

Style make_style(const View& view, std::size_t n) {
  const double spacing = std::sqrt(view.width() * view.height() / double(std::max<std::size_t>(n, 1)));
  Style style{};
  style.dot = std::clamp(0.12 * spacing, 1.0, 6.0);
  style.edge = std::clamp(0.02 * spacing, 0.25, 1.2);
  style.hull = std::max(2.5 * style.edge, 1.5);
  style.voronoi = std::clamp(0.025 * spacing, 0.3, 1.5);
  style.dash = std::clamp(0.08 * spacing, 1.0, 5.0);
  style.circle = std::clamp(0.015 * spacing, 0.25, 0.8);
  return style;
}

std::string escape_xml(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// A coordinate of the plane in its shortest exact form, for the description.
std::string shortest(double v) {
  char digits[32];
  return std::string(digits, std::to_chars(digits, digits + sizeof digits, v).ptr);
}

// A size in pixels, to 0.01, for attributes.
std::string px(double v) {
  std::string text;
  append_hundredths(text, to_hundredths(v));
  return text;
}

// The stroke attributes of a layer or a legend sample.
std::string stroke(const char* colour, double width) {
  return std::string("stroke=\"") + colour + "\" stroke-width=\"" + px(width) + "\"";
}

// One layer: <g id=...> with its style, holding one path (none when the layer is empty).
void write_layer(std::ostream& out, const char* id, const std::string& style, const PathData& path) {
  out << "<g id=\"" << id << "\" class=\"" << id << "\" " << style << ">";
  if (!path.empty()) out << "<path d=\"" << path.text() << "\"/>";
  out << "</g>\n";
}

void check_inputs(PointsView points, const Triangulation& t, const Voronoi* diagram, const SvgOptions& options) {
  if (points.dim != 2) {
    throw UsageError("SVG pictures are 2D only, the points have dimension " + std::to_string(points.dim));
  }
  if (!(options.width_px > 0 && options.width_px <= 1e6) || !(options.margin >= 0 && options.margin <= 100)) {
    throw UsageError("write_svg: the width must be in (0, 1e6] pixels and the margin in [0, 100]");
  }
  const auto n = static_cast<std::int64_t>(points.n);
  const auto in_range = [](std::int64_t v, std::int64_t lo, std::int64_t end) { return v >= lo && v < end; };
  if (!t.simplices.empty() && (t.dim != 2 || t.simplices.size() % 3 != 0)) {
    throw UsageError("write_svg: the triangulation is not one of 2D points (dimension " + std::to_string(t.dim) + ")");
  }
  for (std::size_t i = 0; i < points.n; ++i) {
    if (!(std::isfinite(points.point(i)[0]) && std::isfinite(points.point(i)[1]))) {
      throw UsageError("write_svg: point " + std::to_string(i) + " has a coordinate that is not finite");
    }
  }
  for (const std::int32_t v : t.simplices)
    if (!in_range(v, 0, n)) throw UsageError("write_svg: the triangulation names point " + std::to_string(v) + " of " + std::to_string(n));
  if (diagram == nullptr) return;
  if (diagram->dim != 2) throw UsageError("write_svg: the Voronoi diagram has dimension " + std::to_string(diagram->dim));
  for (const std::int32_t p : diagram->ridge_points)
    if (!in_range(p, 0, n)) throw UsageError("write_svg: a Voronoi ridge names point " + std::to_string(p) + " of " + std::to_string(n));
  const auto vertices = static_cast<std::int64_t>(diagram->num_vertices());
  if (diagram->ridge_vertices.size() != diagram->num_ridges()) throw UsageError("write_svg: Voronoi ridges without their vertices");
  for (const std::int32_t v : diagram->ridge_vertices.values)
    if (!in_range(v, -1, vertices)) throw UsageError("write_svg: a Voronoi ridge names vertex " + std::to_string(v));
}

PathData circles_path(PointsView points, const Triangulation& t, const View& view) {
  PathData path;
  for (std::size_t s = 0; s < t.size(); ++s) {
    const double* corners[3] = {points.point(t.simplex(s)[0]), points.point(t.simplex(s)[1]), points.point(t.simplex(s)[2])};
    double c[2];
    if (!std::isfinite(diagram::simplex_circumcentre(2, corners, c))) continue;
    const double r = std::hypot(c[0] - corners[0][0], c[1] - corners[0][1]);
    if (!(r * view.scale <= kMaxCirclePx)) continue;
    // Drawn only when it crosses the view: not wholly outside it, nor around it.
    const double dx_near = std::max({view.x0 - c[0], 0.0, c[0] - view.x1});
    const double dy_near = std::max({view.y0 - c[1], 0.0, c[1] - view.y1});
    const double dx_far = std::max(c[0] - view.x0, view.x1 - c[0]);
    const double dy_far = std::max(c[1] - view.y0, view.y1 - c[1]);
    if (std::hypot(dx_near, dy_near) > r || std::hypot(dx_far, dy_far) < r) continue;
    path.circle(view.pixel({c[0], c[1]}), r * view.scale);
  }
  return path;
}

// The bounded ridges first, in trails, then the rays of the unbounded ones.
PathData voronoi_path(const Voronoi& diagram, PointsView points, const std::vector<Edge>& hull, const View& view) {
  std::vector<Link> bounded;
  struct Ray {
    std::int32_t vertex;
    Xy direction;
  };
  std::vector<Ray> rays;
  for (std::size_t r = 0; r < diagram.num_ridges(); ++r) {
    if (diagram.ridge_vertices.row_size(r) != 2) continue;
    const std::int32_t* ends = diagram.ridge_vertices.row(r);
    if (ends[0] >= 0 && ends[1] >= 0) {
      if (ends[0] != ends[1]) bounded.emplace_back(ends[0], ends[1]);
      continue;
    }
    const std::int32_t finite = std::max(ends[0], ends[1]);
    if (finite < 0) continue;  // two infinite ends: collinear points only (see the top of the file)
    const Edge key{edge_key(diagram.ridge_points[2 * r], diagram.ridge_points[2 * r + 1]), 0, 0};
    const auto edge = std::lower_bound(hull.begin(), hull.end(), key);
    if (edge == hull.end() || edge->key != key.key) continue;  // not a hull edge of this triangulation
    const Xy from = point_of(points, static_cast<std::size_t>(edge->from));
    const Xy to = point_of(points, static_cast<std::size_t>(edge->to));
    rays.push_back({finite, {to.y - from.y, from.x - to.x}});  // the right-hand normal: outwards
  }
  const auto vertex = [&](std::int32_t v) { return Xy{diagram.vertex(v)[0], diagram.vertex(v)[1]}; };
  PathData path;
  for (const Link& e : into_trails(bounded, diagram.num_vertices())) {
    const Xy a = vertex(e.first), b = vertex(e.second);
    add_clipped(path, view, a, {b.x - a.x, b.y - a.y}, 1.0);
  }
  for (const Ray& ray : rays) add_clipped(path, view, vertex(ray.vertex), ray.direction, std::numeric_limits<double>::infinity());
  return path;
}

PathData edges_path(const std::vector<Edge>& edges, PointsView points, const View& view) {
  std::vector<Link> links;
  links.reserve(edges.size());
  for (const Edge& e : edges) links.emplace_back(e.from, e.to);
  PathData path;
  for (const Link& e : into_trails(links, points.n)) {
    path.segment(view.pixel(point_of(points, static_cast<std::size_t>(e.first))),
                 view.pixel(point_of(points, static_cast<std::size_t>(e.second))));
  }
  return path;
}

void write_labels(std::ostream& out, PointsView points, const View& view, const Style& style) {
  // A white halo behind each label (paint-order: the stroke first) keeps it readable over lines.
  out << "<g id=\"labels\" class=\"labels\" font-family=\"sans-serif\" font-size=\"11\" fill=\"" << kLabelColour
      << "\" stroke=\"#fff\" stroke-width=\"3\" stroke-linejoin=\"round\" paint-order=\"stroke\">";
  const double offset = style.dot / 2 + 2;
  for (std::size_t i = 0; i < points.n; ++i) {
    const Xy p = view.pixel(point_of(points, i));
    out << "<text x=\"" << px(p.x + offset) << "\" y=\"" << px(p.y - offset) << "\">" << i << "</text>";
  }
  out << "</g>\n";
}

// The band below the drawing: a sample of each layer drawn, with its count.
void write_legend(std::ostream& out, const View& view, const SvgOptions& options, std::size_t points,
                  std::size_t triangles, const Voronoi* diagram) {
  const double y = view.height() + kLegendPx / 2;
  double x = 12;
  out << "<g id=\"legend\" class=\"legend\" font-family=\"sans-serif\" font-size=\"12\" fill=\"#222\">";
  // `sample`: "h0" for a dot (its caps are round), "h24" for a line.
  const auto item = [&](const char* sample, const std::string& stroke, const std::string& text) {
    out << "<path d=\"M" << px(x) << ' ' << px(y) << sample << "\" fill=\"none\" stroke-linecap=\"round\" " << stroke << "/>";
    x += sample[1] == '0' ? 10 : 30;
    out << "<text x=\"" << px(x) << "\" y=\"" << px(y + 4) << "\">" << text << "</text>";
    x += 7.0 * static_cast<double>(text.size()) + 20;  // about the width of 12 px sans-serif text
  };
  if (options.points) item("h0", stroke(kPointColour, 5), std::to_string(points) + " points");
  if (options.triangulation) {
    item("h24", stroke(kDelaunayColour, 1.2), std::to_string(triangles) + " triangles");
    item("h24", stroke(kHullColour, 3), "convex hull");
  }
  if (options.voronoi && diagram != nullptr) {
    item("h24", stroke(kVoronoiColour, 1.5) + " stroke-dasharray=\"5 3\"",
         std::to_string(diagram->num_vertices()) + " Voronoi vertices");
  }
  if (options.circumcircles) item("h24", stroke(kCircleColour, 1) + kCircleOpacity, "circumcircles");
  out << "</g>\n";
}

}  // namespace

void write_svg(std::ostream& out, PointsView points, const Triangulation& t, const Voronoi* diagram,
               const SvgOptions& options) {
  check_inputs(points, t, diagram, options);
  const View view = make_view(points, options);
  const Style style = make_style(view, points.n);
  const double height = view.height() + kLegendPx;

  std::string title = options.title;
  if (title.empty()) {
    title = (diagram != nullptr && options.voronoi ? "Delaunay triangulation and Voronoi diagram of "
                                                   : "Delaunay triangulation of ") +
            std::to_string(points.n) + " points (drange)";
  }
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << px(view.width()) << "\" height=\"" << px(height)
      << "\" viewBox=\"0 0 " << px(view.width()) << ' ' << px(height) << "\">\n"
      << "<title>" << escape_xml(title) << "</title>\n"
      << "<desc>x from " << shortest(view.x0) << " to " << shortest(view.x1) << ", y from " << shortest(view.y0)
      << " to " << shortest(view.y1) << " (y up), " << shortest(view.scale) << " pixels per unit</desc>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n"
      << "<rect width=\"" << px(view.width()) << "\" height=\"" << px(view.height())
      << "\" fill=\"none\" stroke=\"#ccc\"/>\n";  // the view's frame: what lies beyond is clipped

  // Bottom to top: circles, Delaunay edges, Voronoi edges, the hull, points, labels.
  const std::string lines = "fill=\"none\" stroke-linecap=\"round\" ";
  if (options.circumcircles) {
    write_layer(out, "circles", lines + stroke(kCircleColour, style.circle) + kCircleOpacity, circles_path(points, t, view));
  }
  const EdgeSets edges = triangulation_edges(t);
  if (options.triangulation) {
    write_layer(out, "delaunay", lines + stroke(kDelaunayColour, style.edge), edges_path(edges.interior, points, view));
  }
  if (options.voronoi && diagram != nullptr) {
    write_layer(out, "voronoi",
                lines + stroke(kVoronoiColour, style.voronoi) + " stroke-dasharray=\"" + px(style.dash) + ' ' +
                    px(0.6 * style.dash) + "\"",
                voronoi_path(*diagram, points, edges.hull, view));
  }
  if (options.triangulation) write_layer(out, "hull", lines + stroke(kHullColour, style.hull), edges_path(edges.hull, points, view));
  if (options.points) {
    PathData dots;
    for (std::size_t i = 0; i < points.n; ++i) dots.dot(view.pixel(point_of(points, i)));
    write_layer(out, "points", lines + stroke(kPointColour, style.dot), dots);
  }
  if (options.point_labels) write_labels(out, points, view, style);
  write_legend(out, view, options, points.n, t.size(), diagram);
  out << "</svg>\n";
}

}  // namespace drange
